#include "suggest.h"

#include <algorithm>
#include <cctype>

namespace fl::formula {

std::size_t editDistance(std::string_view a, std::string_view b) {
    // Damerau (optimal string alignment) distance: swaps count as one edit.
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            std::size_t cost = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                       std::tolower(static_cast<unsigned char>(b[j - 1]))
                                   ? 0
                                   : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
    if (name.size() > 64) return {};
    std::string best;
    std::size_t bestDistance = 3;
    for (const std::string& c : candidates) {
        if (c.size() > 64) continue;
        std::size_t d = editDistance(name, c);
        if (d < bestDistance && d * 2 <= std::max(name.size(), c.size())) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

} // namespace fl::formula
