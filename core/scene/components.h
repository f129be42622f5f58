#pragma once
// X3D components and profiles by name, with the highest level each defines.
#include <optional>
#include <string_view>

namespace fl::scene {

// Highest level of a known component; nullopt when the name is unknown.
std::optional<int> componentMaxLevel(std::string_view component);
bool isKnownProfile(std::string_view profile);
// X3D versions a file may name: 3.0 to 4.1.
bool isKnownX3dVersion(std::string_view version);

} // namespace fl::scene
