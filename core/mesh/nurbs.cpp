#include "nurbs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace fl::mesh {
namespace {

// The knot span holding t: the index i with knots[i] <= t < knots[i + 1],
// clamped to the valid range so t at the end uses the last span.
int findSpan(const NurbsBasis& b, double t) {
    const int p = b.order - 1;
    if (std::isnan(t)) t = b.first();
    if (t >= b.last()) {
        int i = b.count - 1;
        while (i > p && b.knots[std::size_t(i)] == b.knots[std::size_t(i + 1)])
            --i;
        return i;
    }
    if (t <= b.first()) {
        int i = p;
        while (i + 1 < b.count && b.knots[std::size_t(i + 1)] <= t)
            ++i;
        return i;
    }
    const auto begin = b.knots.begin() + p;
    const auto end = b.knots.begin() + b.count + 1;
    return std::clamp(int(std::upper_bound(begin, end, t) - b.knots.begin()) - 1, p, b.count - 1);
}

// The order non-zero basis functions at t in `span` and their derivatives
// (Cox-de Boor, with the derivative from the order-1 functions).
void basisAt(const NurbsBasis& b, int span, double t, std::vector<double>& n,
             std::vector<double>& dn) {
    const int p = b.order - 1;
    const auto& k = b.knots;
    // Functions of degree 0..p, built up in place; `lower` keeps degree p-1.
    std::vector<double> left(std::size_t(p + 1)), right(std::size_t(p + 1));
    n.assign(std::size_t(p + 1), 0.0);
    n[0] = 1;
    std::vector<double> lower(1, 1.0);
    for (int j = 1; j <= p; ++j) {
        left[std::size_t(j)] = t - k[std::size_t(span + 1 - j)];
        right[std::size_t(j)] = k[std::size_t(span + j)] - t;
        lower.assign(n.begin(), n.begin() + j);
        double saved = 0;
        for (int r = 0; r < j; ++r) {
            const double denom = right[std::size_t(r + 1)] + left[std::size_t(j - r)];
            const double term = denom == 0 ? 0 : n[std::size_t(r)] / denom;
            n[std::size_t(r)] = saved + right[std::size_t(r + 1)] * term;
            saved = left[std::size_t(j - r)] * term;
        }
        n[std::size_t(j)] = saved;
    }
    dn.assign(std::size_t(p + 1), 0.0);
    if (p == 0) return;
    // N'_{i,p} = p (N_{i,p-1} / (k[i+p] - k[i]) - N_{i+1,p-1} / (k[i+p+1] - k[i+1])),
    // with `lower` holding N_{span-p+1 .. span, p-1}.
    for (int r = 0; r <= p; ++r) {
        const int i = span - p + r;
        double d = 0;
        if (r >= 1) {
            const double denom = k[std::size_t(i + p)] - k[std::size_t(i)];
            if (denom != 0) d += lower[std::size_t(r - 1)] / denom;
        }
        if (r <= p - 1) {
            const double denom = k[std::size_t(i + p + 1)] - k[std::size_t(i + 1)];
            if (denom != 0) d -= lower[std::size_t(r)] / denom;
        }
        dn[std::size_t(r)] = p * d;
    }
}

using field::cross;
using field::length;

Vec3f toFloat(const Vec3& p) {
    return {float(p[0]), float(p[1]), float(p[2])};
}

} // namespace

NurbsBasis makeNurbsBasis(int order, int count, const std::vector<double>& knots,
                          const std::string& what, std::vector<std::string>& warnings) {
    NurbsBasis b;
    const std::string name = what.empty() ? "" : what + " ";
    if (count < 2) return b;
    // Orders beyond kMaxNurbsOrder cost (order^2) per evaluation for no
    // visible gain: CAD data stays below 10.
    const int highest = std::min(count, kMaxNurbsOrder);
    if (order < 2 || order > highest) {
        const int fixed = std::clamp(order, 2, highest);
        warnings.push_back(name + "order " + std::to_string(order) + " needs 2 to " +
                           std::to_string(highest) + " (at most the control points and " +
                           std::to_string(kMaxNurbsOrder) + "); using " + std::to_string(fixed));
        order = fixed;
    }
    b.order = order;
    b.count = count;
    const std::size_t wanted = std::size_t(count + order);
    bool valid = knots.size() == wanted;
    for (std::size_t i = 1; valid && i < knots.size(); ++i)
        valid = std::isfinite(knots[i]) && knots[i] >= knots[i - 1];
    if (valid) {
        const double range = knots[std::size_t(count)] - knots[std::size_t(order - 1)];
        valid = std::isfinite(knots[0]) && range > 0 && std::isfinite(range);
    }
    if (valid) {
        b.knots = knots;
        return b;
    }
    if (!knots.empty())
        warnings.push_back(name + "knots: " + std::to_string(knots.size()) + " given where " +
                           std::to_string(wanted) +
                           " non-decreasing values are needed; using a uniform open knot vector");
    // Uniform and open: order zeros, evenly spaced inner knots, order ones.
    b.knots.resize(wanted);
    const int inner = count - order;
    for (std::size_t i = 0; i < wanted; ++i) {
        const int j = int(i) - (order - 1);
        b.knots[i] = std::clamp(double(j) / double(inner + 1), 0.0, 1.0);
    }
    return b;
}

int nurbsSegments(int tessellation, int controlPoints) {
    const long long n = tessellation > 0   ? tessellation
                        : tessellation < 0 ? -(long long)tessellation * controlPoints
                                           : 2LL * controlPoints;
    return int(std::clamp<long long>(n, 1, 4096));
}

std::vector<double> nurbsWeights(const std::vector<double>& given, std::size_t points,
                                 std::vector<std::string>& warnings) {
    bool ok = given.size() == points;
    for (double w : given)
        ok = ok && std::isfinite(w) && w > 0;
    if (ok) return given;
    if (!given.empty())
        warnings.push_back("weight: " + std::to_string(given.size()) + " given for " +
                           std::to_string(points) +
                           " control points (each must be > 0); using 1 for all");
    return std::vector<double>(points, 1.0);
}

Vec3 evaluate(const NurbsCurve& c, double t) {
    std::vector<double> n, dn;
    const int span = findSpan(c.basis, t);
    basisAt(c.basis, span, t, n, dn);
    Vec3 sum{0, 0, 0};
    double w = 0;
    const int p = c.basis.order - 1;
    for (int r = 0; r <= p; ++r) {
        const std::size_t i = std::size_t(span - p + r);
        const double f = n[std::size_t(r)] * c.weights[i];
        for (int k = 0; k < 3; ++k)
            sum[std::size_t(k)] += f * c.points[i][std::size_t(k)];
        w += f;
    }
    return {sum[0] / w, sum[1] / w, sum[2] / w};
}

SurfacePoint evaluate(const NurbsSurface& s, double u, double v) {
    std::vector<double> nu, dnu, nv, dnv;
    const int su = findSpan(s.u, u), sv = findSpan(s.v, v);
    basisAt(s.u, su, u, nu, dnu);
    basisAt(s.v, sv, v, nv, dnv);
    const int pu = s.u.order - 1, pv = s.v.order - 1;
    // Homogeneous sums A (weighted point), w and their u and v derivatives.
    Vec3 a{0, 0, 0}, au{0, 0, 0}, av{0, 0, 0};
    double w = 0, wu = 0, wv = 0;
    for (int j = 0; j <= pv; ++j)
        for (int i = 0; i <= pu; ++i) {
            const std::size_t index =
                std::size_t(sv - pv + j) * std::size_t(s.u.count) + std::size_t(su - pu + i);
            const double weight = s.weights[index];
            const double f = nu[std::size_t(i)] * nv[std::size_t(j)] * weight;
            const double fu = dnu[std::size_t(i)] * nv[std::size_t(j)] * weight;
            const double fv = nu[std::size_t(i)] * dnv[std::size_t(j)] * weight;
            for (int k = 0; k < 3; ++k) {
                const double c = s.points[index][std::size_t(k)];
                a[std::size_t(k)] += f * c;
                au[std::size_t(k)] += fu * c;
                av[std::size_t(k)] += fv * c;
            }
            w += f;
            wu += fu;
            wv += fv;
        }
    SurfacePoint out;
    for (std::size_t k = 0; k < 3; ++k) {
        out.position[k] = a[k] / w;
        out.du[k] = (au[k] - wu * out.position[k]) / w;
        out.dv[k] = (av[k] - wv * out.position[k]) / w;
    }
    return out;
}

Mesh nurbsCurveMesh(const NurbsCurve& c, int segments) {
    Mesh m;
    m.primitive = Primitive::Lines;
    if (c.basis.count < 2 || segments < 1) return m;
    for (int k = 0; k <= segments; ++k) {
        const double t = std::lerp(c.basis.first(), c.basis.last(), double(k) / segments);
        m.positions.push_back(toFloat(evaluate(c, t)));
        m.normals.push_back({0, 0, 0});
        if (k > 0) m.segments.push_back({std::uint32_t(k - 1), std::uint32_t(k)});
    }
    return m;
}

std::vector<Point2> nurbsCurve2DPoints(int order, const std::vector<Point2>& points,
                                       const std::vector<double>& weights,
                                       const std::vector<double>& knots, int segments,
                                       std::vector<std::string>& warnings) {
    NurbsCurve c;
    c.basis = makeNurbsBasis(order, int(points.size()), knots, "", warnings);
    if (c.basis.count < 2) return {points.begin(), points.end()};
    for (const Point2& p : points)
        c.points.push_back({p[0], p[1], 0});
    c.weights = nurbsWeights(weights, points.size(), warnings);
    std::vector<Point2> out;
    for (int k = 0; k <= segments; ++k) {
        const double t = std::lerp(c.basis.first(), c.basis.last(), double(k) / segments);
        const Vec3 p = evaluate(c, t);
        out.push_back({p[0], p[1]});
    }
    return out;
}

void limitNurbsCells(int& uSegments, int& vSegments, std::vector<std::string>& warnings) {
    const long long cells = (long long)uSegments * (long long)vSegments;
    if (cells <= kMaxNurbsCells) return;
    const double shrink = std::sqrt(double(kMaxNurbsCells) / double(cells));
    const int u = std::max(1, int(uSegments * shrink)), v = std::max(1, int(vSegments * shrink));
    warnings.push_back("tessellation " + std::to_string(uSegments) + " x " +
                       std::to_string(vSegments) + " is more than " +
                       std::to_string(kMaxNurbsCells) + " cells; using " + std::to_string(u) +
                       " x " + std::to_string(v));
    uSegments = u;
    vSegments = v;
}

namespace {

// Sutherland-Hodgman against the parameter rectangle: for points inside
// it, a contour's winding number is unchanged, so the even-odd region is
// the trimmed region cut to the surface's range.
Contour2 clipToRange(const Contour2& c, double u0, double v0, double u1, double v1) {
    Contour2 out = c;
    for (int side = 0; side < 4 && !out.empty(); ++side) {
        const std::size_t axis = side % 2 == 0 ? 0 : 1;
        const double limit = side == 0 ? u0 : side == 1 ? v0 : side == 2 ? u1 : v1;
        const bool keepAbove = side < 2;
        auto inside = [&](const Point2& p) {
            return keepAbove ? p[axis] >= limit : p[axis] <= limit;
        };
        Contour2 in = std::move(out);
        out.clear();
        for (std::size_t k = 0; k < in.size(); ++k) {
            const Point2& a = in[k];
            const Point2& b = in[(k + 1) % in.size()];
            if (inside(a)) out.push_back(a);
            if (inside(a) != inside(b)) {
                const double f = (limit - a[axis]) / (b[axis] - a[axis]);
                Point2 x{a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
                x[axis] = limit;
                out.push_back(x);
            }
        }
    }
    return out;
}

struct PlaceKey {
    std::array<long long, 3> k;
    bool operator==(const PlaceKey&) const = default;
};
struct PlaceHash {
    std::size_t operator()(const PlaceKey& p) const {
        std::size_t h = 1469598103934665603ULL;
        for (long long v : p.k)
            h = (h ^ std::size_t(v)) * 1099511628211ULL;
        return h;
    }
};

} // namespace

Mesh nurbsSurfaceMesh(const NurbsSurface& s, int uSegments, int vSegments,
                      const std::vector<Contour2>& trim, std::vector<std::string>* warnings) {
    Mesh m;
    if (s.u.count < 2 || s.v.count < 2) return m;
    uSegments = std::max(1, uSegments);
    vSegments = std::max(1, vSegments);
    const double u0 = s.u.first(), u1 = s.u.last(), v0 = s.v.first(), v1 = s.v.last();

    // The (u, v) points to evaluate and their triangles: the whole range as
    // a contour when nothing trims it, so both cases share the same fill.
    FillGrid grid;
    for (int i = 0; i <= uSegments; ++i)
        grid.xs.push_back(std::lerp(u0, u1, double(i) / uSegments));
    for (int j = 0; j <= vSegments; ++j)
        grid.ys.push_back(std::lerp(v0, v1, double(j) / vSegments));
    std::vector<Contour2> region;
    if (trim.empty()) region.push_back({{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}});
    for (const Contour2& c : trim) {
        Contour2 clipped = clipToRange(c, u0, v0, u1, v1);
        if (clipped.size() >= 3) region.push_back(std::move(clipped));
    }
    const PlanarFill fill = fillContours(region, FillRule::EvenOdd, grid);
    if (!fill.problem.empty() && warnings)
        warnings->push_back("trimming contours: " + fill.problem + "; nothing drawn");

    // Where the range's edges meet in space (a revolved profile's seam, a
    // sphere's poles), evaluations coincide: share those vertices and their
    // normals so the mesh is closed and smooth across them. Only points on
    // the range's edges are matched: inside, distinct sheets may touch.
    double extent = 0;
    for (const Vec3& p : s.points)
        extent = std::max({extent, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    const double snap = std::max(extent, 1e-300) * 1e-9;
    // Derivatives this small (relative to the patch and its range) vanish:
    // what is left is rounding, whose direction means nothing.
    const double duFloor = 1e-7 * extent / (u1 - u0), dvFloor = 1e-7 * extent / (v1 - v0);
    std::unordered_map<PlaceKey, std::uint32_t, PlaceHash> byPlace;
    std::vector<std::uint32_t> vertexOf(fill.points.size());
    std::vector<Vec3> normalSum;
    for (std::size_t k = 0; k < fill.points.size(); ++k) {
        const double u = fill.points[k][0], v = fill.points[k][1];
        const SurfacePoint sp = evaluate(s, u, v);
        const bool onEdge = u == u0 || u == u1 || v == v0 || v == v1;
        std::uint32_t index = std::uint32_t(m.positions.size());
        bool fresh = true;
        if (onEdge) {
            const PlaceKey key{{std::llround(sp.position[0] / snap),
                                std::llround(sp.position[1] / snap),
                                std::llround(sp.position[2] / snap)}};
            auto [it, added] = byPlace.try_emplace(key, index);
            index = it->second;
            fresh = added;
        }
        if (fresh) {
            m.positions.push_back(toFloat(sp.position));
            m.parameters.push_back({float(u), float(v), 0});
            normalSum.push_back({0, 0, 0});
        }
        vertexOf[k] = index;
        if (length(sp.du) < duFloor || length(sp.dv) < dvFloor) continue;
        const Vec3 n = cross(sp.du, sp.dv);
        const double len = length(n);
        if (len > 0 && std::isfinite(len))
            for (std::size_t c = 0; c < 3; ++c)
                normalSum[index][c] += n[c] / len;
    }
    for (const Triangle& t : fill.triangles) {
        const Triangle mapped = {vertexOf[t[0]], vertexOf[t[1]], vertexOf[t[2]]};
        if (mapped[0] == mapped[1] || mapped[1] == mapped[2] || mapped[0] == mapped[2])
            continue; // collapsed at a pole
        m.triangles.push_back(mapped);
    }
    // A vertex whose derivatives vanish (a pole, a degenerate edge of
    // control points) takes the mean of its triangles' faces instead.
    std::vector<Vec3> faceSum(m.positions.size(), {0, 0, 0});
    for (const Triangle& t : m.triangles) {
        const auto& a = m.positions[t[0]];
        const auto& b = m.positions[t[1]];
        const auto& c = m.positions[t[2]];
        const Vec3 e1 = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const Vec3 e2 = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        const Vec3 n = cross(e1, e2);
        for (std::uint32_t v : t)
            for (std::size_t k = 0; k < 3; ++k)
                faceSum[v][k] += n[k];
    }
    m.normals.resize(m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        Vec3 n = normalSum[v];
        if (length(n) < 1e-6) n = faceSum[v];
        const double len = length(n);
        m.normals[v] = len > 0 ? Vec3f{float(n[0] / len), float(n[1] / len), float(n[2] / len)}
                               : Vec3f{0, 0, 1};
    }
    return m;
}

} // namespace fl::mesh
