#pragma once
// One PDE patch written as a formula: the script of a parametric FGeometry
// (u in [0, 1], v in [0, 2π]) that computes the same X(u, v) — the spine as
// a cubic in u, each radius as its four exponential terms times cos(nv) and
// sin(nv) — so a student sees that a PDE patch is just a parametric
// function (`pde fit --formula`). A model's shared borders are not in it:
// it is the patch alone.
#include "pde_patch.h"

#include <string>
#include <vector>

namespace fl::pde {

// The script's lines (one MFString entry each), with comments.
std::vector<std::string> patchScript(const Patch& patch);
// (pde_scene.h puts it in a scene.)

} // namespace fl::pde
