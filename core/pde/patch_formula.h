#pragma once
// One PDE patch written as a formula: the script of a parametric FGeometry
// (u in [0, 1], v in [0, 2π]) that computes the same X(u, v) — the spine as
// a cubic in u, each radius as its four exponential terms times cos(nv) and
// sin(nv) — so a student sees that a PDE patch is just a parametric
// function (`pde fit --formula`). A model's shared borders are not in it:
// it is the patch alone.
#include "pde_model.h"

#include <string>
#include <vector>

namespace fl::pde {

// The script's lines (one MFString entry each), with comments.
std::vector<std::string> patchScript(const Patch& patch);

// A scene holding patch k of `model` as an FShape PATCH_k with that script
// (uRange 0 1, vRange 0 2π, the model's box as its domain): X3D XML, or
// ClassicVRML when `classic`.
std::string patchScene(const Model& model, std::size_t k, bool classic);

} // namespace fl::pde
