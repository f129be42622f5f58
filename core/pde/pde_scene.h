#pragma once
// Scenes that show a PDE model, written as text for `pde fit` and the
// window's import: one patch as a parametric FGeometry (its script from
// patch_formula.h), or the whole model in an FPdeSurface that names its
// .pde file or carries it in a data: url. X3D XML, or ClassicVRML when
// `classic`; one FShape each, between the same header and footer.
#include "pde_file.h"

#include <string>

namespace fl::pde {

// Patch k of `model` as FShape PATCH_k (uRange 0 1, vRange 0 2π, the model's
// box, given depth where the mesh was flat, as its domain).
std::string patchScene(const Model& model, std::size_t k, bool classic);

// FShape MODEL, its FPdeSurface naming `url` (a .pde file beside the scene:
// any text XML 1.0 can hold — no control character but tab, line feed and
// carriage return — quoted and escaped as the syntax needs).
std::string modelScene(const std::string& url, bool classic);

// The model as FShape MODEL, its FPdeSurface carrying it (dataUrlOf).
std::string carryingScene(const Model& model, const EncodeOptions& options, bool classic);

} // namespace fl::pde
