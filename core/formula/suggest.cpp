#include "suggest.h"

#include "text/edit_distance.h"

#include <algorithm>
#include <cctype>

namespace fl::formula {

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
    if (name.size() > 64) return {};
    std::string best;
    std::size_t bestDistance = 3;
    for (const std::string& c : candidates) {
        if (c.size() > 64) continue;
        std::size_t d = text::editDistance(name, c);
        if (d < bestDistance && d * 2 <= std::max(name.size(), c.size())) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

} // namespace fl::formula
