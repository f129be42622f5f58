#include "domain_mapping.h"

namespace fl::field {

std::array<double, 6> componentView(const Vec3& p, const Box3& g, const Box3& c) {
    std::array<double, 6> m{};
    for (std::size_t a = 0; a < 3; ++a) {
        const double size = g.hi[a] - g.lo[a];
        const double s = size > 0 ? (p[a] - g.lo[a]) / size : 0;
        m[a] = c.lo[a] + s * (c.hi[a] - c.lo[a]);
        m[3 + a] = s;
    }
    return m;
}

} // namespace fl::field
