#pragma once
// "Did you mean …?" — the closest known name by edit distance.
#include <string>
#include <string_view>
#include <vector>

namespace fl::formula {

// The candidate nearest to `name` if it is close enough to be a plausible
// typo (distance <= 2, and less than half the name); empty otherwise.
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);

} // namespace fl::formula
