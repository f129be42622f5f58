#include "affine.h"

#include <algorithm>
#include <cmath>

namespace fl::field {

Affine Affine::operator*(const Affine& o) const {
    Affine r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
        r.t[i] = m[i][0] * o.t[0] + m[i][1] * o.t[1] + m[i][2] * o.t[2] + t[i];
    }
    return r;
}

Affine Affine::translate(double x, double y, double z) {
    Affine a;
    a.t[0] = x, a.t[1] = y, a.t[2] = z;
    return a;
}

Affine Affine::scale(double x, double y, double z) {
    Affine a;
    a.m[0][0] = x, a.m[1][1] = y, a.m[2][2] = z;
    return a;
}

Affine Affine::rotate(double ax, double ay, double az, double angle) {
    Affine a;
    const double n = std::hypot(ax, ay, az); // no overflow for huge or tiny axes
    if (!(n > 0) || !std::isfinite(angle)) return a;
    ax /= n, ay /= n, az /= n;
    const double c = std::cos(angle), s = std::sin(angle), k = 1 - c;
    a.m[0][0] = c + ax * ax * k, a.m[0][1] = ax * ay * k - az * s, a.m[0][2] = ax * az * k + ay * s;
    a.m[1][0] = ay * ax * k + az * s, a.m[1][1] = c + ay * ay * k, a.m[1][2] = ay * az * k - ax * s;
    a.m[2][0] = az * ax * k - ay * s, a.m[2][1] = az * ay * k + ax * s, a.m[2][2] = c + az * az * k;
    return a;
}

Affine Affine::rotate(const std::vector<double>& r) {
    return r.size() == 4 ? rotate(r[0], r[1], r[2], r[3]) : Affine{};
}

Affine Affine::fromMatrix(const Matrix4& p) {
    Affine a;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
            a.m[r][c] = p[std::size_t(c * 4 + r)];
        a.t[r] = p[std::size_t(12 + r)];
    }
    return a;
}

Matrix4 Affine::matrix() const {
    return {m[0][0], m[1][0], m[2][0], 0, m[0][1], m[1][1], m[2][1], 0,
            m[0][2], m[1][2], m[2][2], 0, t[0],    t[1],    t[2],    1};
}

Vec3 Affine::point(const Vec3& p) const {
    Vec3 v = vector(p);
    for (int k = 0; k < 3; ++k)
        v[std::size_t(k)] += t[k];
    return v;
}

Vec3 Affine::vector(const Vec3& v) const {
    Vec3 out{};
    for (int r = 0; r < 3; ++r)
        out[std::size_t(r)] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
    return out;
}

double Affine::determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

std::array<std::array<double, 3>, 3> Affine::cofactors() const {
    std::array<std::array<double, 3>, 3> c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[std::size_t(i)][std::size_t(j)] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    return c;
}

std::optional<Affine> Affine::inverse() const {
    const double det = determinant();
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) return std::nullopt;
    const auto c = cofactors();
    Affine r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = c[std::size_t(j)][std::size_t(i)] / det;
    const Vec3 back = r.vector({t[0], t[1], t[2]});
    for (int k = 0; k < 3; ++k)
        r.t[k] = -back[std::size_t(k)];
    return r;
}

Box3 boundsOf(const Box3& b, const Affine& a) {
    Box3 out{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (int c = 0; c < 8; ++c) {
        const Vec3 q = a.point(
            {c & 1 ? b.hi[0] : b.lo[0], c & 2 ? b.hi[1] : b.lo[1], c & 4 ? b.hi[2] : b.lo[2]});
        for (std::size_t k = 0; k < 3; ++k) {
            out.lo[k] = std::min(out.lo[k], q[k]);
            out.hi[k] = std::max(out.hi[k], q[k]);
        }
    }
    return out;
}

} // namespace fl::field
