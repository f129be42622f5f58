#include "box3.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fl::field {

double Box3::longestSide() const {
    return std::max({size(0), size(1), size(2)});
}

double Box3::diagonal() const {
    return std::hypot(size(0), size(1), size(2));
}

bool Box3::valid() const {
    for (int a = 0; a < 3; ++a)
        if (!(std::isfinite(lo[std::size_t(a)]) && std::isfinite(hi[std::size_t(a)]) &&
              size(a) > 0))
            return false;
    return true;
}

bool Box3::contains(const Vec3& p) const {
    for (std::size_t k = 0; k < 3; ++k)
        if (!(p[k] >= lo[k] && p[k] <= hi[k])) return false;
    return true;
}

std::optional<RaySpan> clipRay(const Vec3& o, const Vec3& d, const Box3& box) {
    if (!isFinite(o) || !isFinite(d)) return std::nullopt;
    RaySpan s{0, 1e300};
    for (std::size_t k = 0; k < 3; ++k) {
        if (std::abs(d[k]) < 1e-300) {
            if (o[k] < box.lo[k] || o[k] > box.hi[k]) return std::nullopt;
            continue;
        }
        double a = (box.lo[k] - o[k]) / d[k], b = (box.hi[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        s.enter = std::max(s.enter, a);
        s.exit = std::min(s.exit, b);
    }
    if (!(s.enter <= s.exit) || !std::isfinite(s.enter) || !std::isfinite(s.exit))
        return std::nullopt;
    return s;
}

Vec3 nearestFaceNormal(const Box3& box, const Vec3& p) {
    std::size_t axis = 0;
    double nearest = INFINITY, side = 1;
    for (std::size_t k = 0; k < 3; ++k)
        for (const double face : {box.lo[k], box.hi[k]})
            if (std::abs(p[k] - face) < nearest) {
                nearest = std::abs(p[k] - face);
                axis = k;
                side = face == box.lo[k] ? -1 : 1;
            }
    Vec3 n{0, 0, 0};
    n[axis] = side;
    return n;
}

} // namespace fl::field
