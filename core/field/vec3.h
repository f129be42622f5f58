#pragma once
// Points and vectors of the kernel: three doubles, and the few operations the
// mesher, picking, haptic contact and the grader all need. Plain arrays, so
// formula inputs, meshes and GLM/Qt conversions stay copies of numbers.
#include <algorithm>
#include <array>
#include <cmath>

namespace fl::field {

using Vec3 = std::array<double, 3>;

constexpr Vec3 plus(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
constexpr Vec3 minus(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
constexpr Vec3 scaled(const Vec3& a, double s) {
    return {a[0] * s, a[1] * s, a[2] * s};
}
// The point `s` along a ray: origin + s * direction.
constexpr Vec3 along(const Vec3& origin, const Vec3& direction, double s) {
    return {origin[0] + s * direction[0], origin[1] + s * direction[1],
            origin[2] + s * direction[2]};
}
constexpr double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
inline bool isFinite(const Vec3& a) {
    return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
// `a` made unit length, or `fallback` where it has no direction (zero,
// non-finite): callers say what a degenerate normal or axis means to them.
// Tiny and huge vectors are scaled first, so their squares neither underflow
// nor overflow.
inline Vec3 unitOr(const Vec3& a, const Vec3& fallback) {
    const double m = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
    if (!(m > 0) || !std::isfinite(m)) return fallback;
    const Vec3 b = m > 1e-150 && m < 1e150 ? a : scaled(a, 1 / m);
    const double n = length(b);
    return {b[0] / n, b[1] / n, b[2] / n};
}

} // namespace fl::field
