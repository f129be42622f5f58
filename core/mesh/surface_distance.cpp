#include "surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace fl::mesh {
namespace {

Point3 toPoint(const Vec3f& v) {
    return {v[0], v[1], v[2]};
}
Point3 sub(const Point3& a, const Point3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Point3& a, const Point3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm2(const Point3& a) {
    return dot(a, a);
}

double boxDistance2(const Point3& p, const Point3& lo, const Point3& hi) {
    double d = 0;
    for (int k = 0; k < 3; ++k) {
        const double e =
            p[std::size_t(k)] < lo[std::size_t(k)]   ? lo[std::size_t(k)] - p[std::size_t(k)]
            : p[std::size_t(k)] > hi[std::size_t(k)] ? p[std::size_t(k)] - hi[std::size_t(k)]
                                                     : 0;
        d += e * e;
    }
    return d;
}

double segmentDistance2(const Point3& p, const Point3& a, const Point3& b) {
    const Point3 ab = sub(b, a);
    const double l = norm2(ab);
    const double t = l > 0 ? std::clamp(dot(sub(p, a), ab) / l, 0.0, 1.0) : 0.0;
    return norm2(sub(p, {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]}));
}

} // namespace

double squaredDistanceToTriangle(const Point3& p, const Point3& a, const Point3& b,
                                 const Point3& c) {
    // Inside the prism over the triangle: the distance to its plane; else the
    // nearest of the three edges (which also covers degenerate triangles).
    const Point3 ab = sub(b, a), ac = sub(c, a);
    const Point3 n{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                   ab[0] * ac[1] - ab[1] * ac[0]};
    const double nn = norm2(n);
    if (nn > 0) {
        const Point3 ap = sub(p, a);
        // Barycentric coordinates of p's projection.
        const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
        const double d20 = dot(ap, ab), d21 = dot(ap, ac);
        const double den = d00 * d11 - d01 * d01;
        if (den > 0) {
            const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
            if (v >= 0 && w >= 0 && v + w <= 1) {
                const double h = dot(ap, n);
                return h * h / nn;
            }
        }
    }
    return std::min(
        {segmentDistance2(p, a, b), segmentDistance2(p, b, c), segmentDistance2(p, c, a)});
}

TriangleTree::TriangleTree(const Mesh& mesh) : mesh_(mesh) {
    order_.resize(mesh.triangles.size());
    std::iota(order_.begin(), order_.end(), 0u);
    centroids_.resize(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        for (int k = 0; k < 3; ++k)
            centroids_[i][std::size_t(k)] =
                (double(mesh.positions[t[0]][std::size_t(k)]) +
                 mesh.positions[t[1]][std::size_t(k)] + mesh.positions[t[2]][std::size_t(k)]) /
                3;
    }
    nodes_.reserve(2 * order_.size() / 4 + 2);
    if (!order_.empty()) build(0, std::uint32_t(order_.size()));
}

std::uint32_t TriangleTree::build(std::uint32_t first, std::uint32_t count) {
    const auto at = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    Node n{};
    const double inf = std::numeric_limits<double>::infinity();
    n.lo = {inf, inf, inf};
    n.hi = {-inf, -inf, -inf};
    Point3 clo = n.lo, chi = n.hi;
    for (std::uint32_t i = first; i < first + count; ++i) {
        for (std::uint32_t v : mesh_.triangles[order_[i]])
            for (std::size_t k = 0; k < 3; ++k) {
                n.lo[k] = std::min(n.lo[k], double(mesh_.positions[v][k]));
                n.hi[k] = std::max(n.hi[k], double(mesh_.positions[v][k]));
            }
        for (std::size_t k = 0; k < 3; ++k) {
            clo[k] = std::min(clo[k], centroids_[order_[i]][k]);
            chi[k] = std::max(chi[k], centroids_[order_[i]][k]);
        }
    }
    n.first = first;
    n.count = count;
    if (count > 4) {
        std::size_t axis = 0;
        for (std::size_t k = 1; k < 3; ++k)
            if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
        const std::uint32_t half = count / 2;
        std::nth_element(order_.begin() + first, order_.begin() + first + half,
                         order_.begin() + first + count, [&](std::uint32_t a, std::uint32_t b) {
                             return centroids_[a][axis] < centroids_[b][axis];
                         });
        n.count = 0;
        n.left = build(first, half);
        n.right = build(first + half, count - half);
    }
    nodes_[at] = n;
    return at;
}

double TriangleTree::squaredDistance(const Point3& p) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    std::vector<std::pair<double, std::uint32_t>> stack{{0.0, 0u}};
    while (!stack.empty()) {
        const auto [d, i] = stack.back();
        stack.pop_back();
        if (d >= best) continue;
        const Node& n = nodes_[i];
        if (n.count > 0) {
            for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
                const auto& t = mesh_.triangles[order_[k]];
                best = std::min(best, squaredDistanceToTriangle(p, toPoint(mesh_.positions[t[0]]),
                                                                toPoint(mesh_.positions[t[1]]),
                                                                toPoint(mesh_.positions[t[2]])));
            }
            continue;
        }
        const double dl = boxDistance2(p, nodes_[n.left].lo, nodes_[n.left].hi);
        const double dr = boxDistance2(p, nodes_[n.right].lo, nodes_[n.right].hi);
        // The nearer child on top of the stack: visited first.
        if (dl < dr) {
            stack.push_back({dr, n.right});
            stack.push_back({dl, n.left});
        } else {
            stack.push_back({dl, n.left});
            stack.push_back({dr, n.right});
        }
    }
    return best;
}

OneWayDistance distanceFrom(const Mesh& from, const TriangleTree& to, std::size_t samples,
                            unsigned seed) {
    OneWayDistance out;
    std::vector<double> cumulative;
    cumulative.reserve(from.triangles.size());
    double total = 0;
    for (const auto& t : from.triangles) {
        const Point3 a = toPoint(from.positions[t[0]]), b = toPoint(from.positions[t[1]]),
                     c = toPoint(from.positions[t[2]]);
        const Point3 ab = sub(b, a), ac = sub(c, a);
        total +=
            0.5 * std::sqrt(norm2({ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                                   ab[0] * ac[1] - ab[1] * ac[0]}));
        cumulative.push_back(total);
    }
    double sum2 = 0;
    // Area-weighted samples make the RMS; the vertices only the largest
    // (they are not spread by area, and a spike sits on one).
    auto take = [&](const Point3& p, bool counted) {
        const double d2 = to.squaredDistance(p);
        out.max = std::max(out.max, std::sqrt(d2));
        if (!counted) return;
        sum2 += d2;
        ++out.samples;
    };
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    if (total > 0)
        for (std::size_t s = 0; s < samples; ++s) {
            const double pick = unit(rng) * total;
            const auto i = std::size_t(
                std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
            const auto& t = from.triangles[std::min(i, from.triangles.size() - 1)];
            double r1 = unit(rng), r2 = unit(rng);
            if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
            const Point3 a = toPoint(from.positions[t[0]]), b = toPoint(from.positions[t[1]]),
                         c = toPoint(from.positions[t[2]]);
            take({a[0] + r1 * (b[0] - a[0]) + r2 * (c[0] - a[0]),
                  a[1] + r1 * (b[1] - a[1]) + r2 * (c[1] - a[1]),
                  a[2] + r1 * (b[2] - a[2]) + r2 * (c[2] - a[2])},
                 true);
        }
    for (const Vec3f& v : from.positions)
        take(toPoint(v), false);
    out.rms = out.samples ? std::sqrt(sum2 / double(out.samples)) : 0;
    return out;
}

std::vector<double> vertexDistances(const Mesh& from, const TriangleTree& to) {
    std::vector<double> out;
    out.reserve(from.positions.size());
    for (const Vec3f& v : from.positions)
        out.push_back(std::sqrt(to.squaredDistance(toPoint(v))));
    return out;
}

SurfaceDistance compareSurfaces(const Mesh& a, const Mesh& b, std::size_t samplesEachWay) {
    return compareSurfaces(a, TriangleTree(a), b, samplesEachWay);
}

SurfaceDistance compareSurfaces(const Mesh& a, const TriangleTree& ta, const Mesh& b,
                                std::size_t samplesEachWay) {
    const TriangleTree tb(b);
    const OneWayDistance ab = distanceFrom(a, tb, samplesEachWay, 1);
    const OneWayDistance ba = distanceFrom(b, ta, samplesEachWay, 2);
    SurfaceDistance out;
    out.samples = ab.samples + ba.samples;
    out.rms = out.samples ? std::sqrt((ab.rms * ab.rms * double(ab.samples) +
                                       ba.rms * ba.rms * double(ba.samples)) /
                                      double(out.samples))
                          : 0;
    out.hausdorff = std::max(ab.max, ba.max);
    return out;
}

} // namespace fl::mesh
