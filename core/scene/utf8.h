#pragma once
// Scene files are UTF-8 (VRML97, X3D). Strings that are not — a file saved as
// Shift-JIS or Latin-1 — are repaired on reading, each invalid byte becoming
// U+FFFD, so the model holds valid text that every writer can write back.
#include <string>
#include <string_view>

namespace fl::scene {

bool isValidUtf8(std::string_view text);
std::string replaceInvalidUtf8(std::string_view text);

} // namespace fl::scene
