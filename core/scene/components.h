#pragma once
// X3D components and profiles by name, with the highest level each defines.
#include <optional>
#include <string_view>

namespace fl::scene {

// Highest level of a known component; nullopt when the name is unknown.
std::optional<int> componentMaxLevel(std::string_view component);
bool isKnownProfile(std::string_view profile);
// The level of `component` a profile includes (ISO/IEC 19775-1 annexes A–E:
// Core, Interchange, Interactive, Immersive; Full includes every level).
// 0 when the profile does not include it; nullopt for profiles whose tables
// FunctionLab does not keep (CADInterchange, MedicalInterchange,
// MPEG4Interactive), which are not enforced.
std::optional<int> profileComponentLevel(std::string_view profile, std::string_view component);
// X3D versions a file may name: 3.0 to 4.1.
bool isKnownX3dVersion(std::string_view version);

} // namespace fl::scene
