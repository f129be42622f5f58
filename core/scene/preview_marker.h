#pragma once
// `functionlab convert` adds a coarse mesh of the function shapes as plain
// X3D, so that browsers which know nothing of FShape still show the scene.
// That root node carries this DEF name; every reader drops it again, so the
// preview never becomes part of the user's scene (docs/cli.md).
#include <string_view>

namespace fl::scene {

inline constexpr std::string_view kPreviewDefName = "FunctionLab_Preview";

} // namespace fl::scene
