#include "pde_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::pde {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// How far in u from its border a patch is pulled onto it. The pull drags
// rows off the patch's surface by up to the fit's miss, and varies along v
// as fast as the border does: over the last 0.4 of u (the first choice) the
// example bunny had 1.5 % of its triangles folded and RMS 0.154 %; over the
// last 0.1, 0.9 % and 0.135 % (Hausdorff 1.75 -> 1.83 %), and its drawings
// come nearer their finest as the resolution grows (0.36 % of the diagonal
// at 64 against 0.60 %). docs/pde.md has the four meshes.
constexpr double kPull = 0.1;

mesh::Vec3f toFloat(const Vec3& p) {
    return {float(p[0]), float(p[1]), float(p[2])};
}

Vec3 unitNormal(const Point& p) {
    const Vec3 n{p.du[1] * p.dv[2] - p.du[2] * p.dv[1], p.du[2] * p.dv[0] - p.du[0] * p.dv[2],
                 p.du[0] * p.dv[1] - p.du[1] * p.dv[0]};
    const double l = std::hypot(n[0], n[1], n[2]);
    return l > 0 ? Vec3{n[0] / l, n[1] / l, n[2] / l} : Vec3{};
}

double distance(const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Whether the ring at u lies within `tolerance` of one point.
bool ringIsAPoint(const Patch& patch, double u, int steps, double tolerance) {
    const Vec3 first = position(patch, u, 0);
    for (int j = 1; j < steps; ++j)
        if (distance(position(patch, u, kTwoPi * j / steps), first) > tolerance) return false;
    return true;
}

// The v at which the patch's curve at u (0 or 1) passes nearest each border
// point, increasing along the loop (unwrapped: v[0] <= ... < v[0] + 2π).
std::vector<double> borderParameters(const Patch& patch, const std::vector<Vec3>& points,
                                     double u) {
    const std::size_t n = points.size();
    const std::size_t m = std::clamp<std::size_t>(16 * n, 256, 8192);
    std::vector<Vec3> curve(m);
    for (std::size_t j = 0; j < m; ++j)
        curve[j] = position(patch, u, kTwoPi * double(j) / double(m));
    std::size_t first = 0;
    for (std::size_t j = 1; j < m; ++j)
        if (distance(curve[j], points[0]) < distance(curve[first], points[0])) first = j;
    std::vector<double> v(n);
    v[0] = kTwoPi * double(first) / double(m);
    std::size_t at = first; // unwrapped sample index
    // Look ahead a few average steps (not half the curve: a loop of many
    // points would cost points x samples).
    const std::size_t ahead = std::min(m / 2, 4 * (m / n) + 8);
    for (std::size_t k = 1; k < n; ++k) {
        // Forward, leaving a sample for each point still to come.
        const std::size_t last = first + m - (n - k);
        std::size_t best = at + 1;
        for (std::size_t j = at + 1; j <= std::min(last, at + ahead); ++j)
            if (distance(curve[j % m], points[k]) < distance(curve[best % m], points[k])) best = j;
        at = best;
        v[k] = kTwoPi * double(at) / double(m);
    }
    return v;
}

// A border loop a patch meets at u (0 or 1): its points, the v at which
// the patch's curve there passes each, and the pull B(v) - X(u, v) that
// brings the patch's rows near it onto it.
struct Ring {
    double u = 1;
    std::vector<Vec3> points;
    std::vector<double> v;
    bool bordered() const { return points.size() >= 3; }
    Vec3 pull(const Patch& patch, double at) const {
        double w = std::fmod(at - v[0], kTwoPi);
        if (w < 0) w += kTwoPi;
        w += v[0];
        const auto it = std::upper_bound(v.begin(), v.end(), w);
        const std::size_t k = std::size_t(it - v.begin()) - 1, next = (k + 1) % v.size();
        const double hi = next == 0 ? v[0] + kTwoPi : v[next];
        const double t = hi > v[k] ? (w - v[k]) / (hi - v[k]) : 0;
        const Vec3 x = position(patch, u, at);
        Vec3 d;
        for (std::size_t c = 0; c < 3; ++c)
            d[c] = points[k][c] + t * (points[next][c] - points[k][c]) - x[c];
        return d;
    }
};

Ring ringOf(const Patch& patch, const std::vector<Vec3>& points,
            const std::vector<std::uint32_t>* loop, double u) {
    Ring r;
    r.u = u;
    if (!loop || loop->size() < 3) return r;
    for (std::uint32_t i : *loop)
        r.points.push_back(points[i]);
    r.v = borderParameters(patch, r.points, u);
    return r;
}

class PatchMesher {
  public:
    PatchMesher(mesh::Mesh& out, std::vector<std::int64_t>& shared,
                std::vector<Vec3>& sharedNormals)
        : out_(out), shared_(shared), sharedNormals_(sharedNormals) {}

    void mesh(const Patch& patch, int nu, int nv, double tolerance, const std::vector<Vec3>& points,
              const std::vector<std::uint32_t>* loop, const std::vector<std::uint32_t>* startLoop) {
        const Ring end = ringOf(patch, points, loop, 1);
        const Ring start = patch.cap ? Ring{} : ringOf(patch, points, startLoop, 0);
        const double v0 = end.bordered() ? end.v[0] : 0;
        // The rows of the grid: the last (first) ring is the border itself.
        const int first = start.bordered() ? 1 : 0;
        const int rows = end.bordered() ? nu - 1 : nu;
        const bool pointAtStart =
            !start.bordered() && (patch.cap || ringIsAPoint(patch, 0, nv, tolerance));
        const bool pointAtEnd = !end.bordered() && ringIsAPoint(patch, 1, nv, tolerance);
        std::vector<std::uint32_t> index(std::size_t(rows + 1) * std::size_t(nv));
        for (int i = first; i <= rows; ++i) {
            const double u = double(i) / nu;
            const bool point = (i == 0 && pointAtStart) || (i == nu && pointAtEnd);
            // Pulled towards the border by a smoothstep from u = 1 - kPull
            // to 1 (from kPull to 0 towards a start border).
            const double s = std::clamp((u - (1 - kPull)) / kPull, 0.0, 1.0),
                         w = s * s * (3 - 2 * s);
            const double r = std::clamp((kPull - u) / kPull, 0.0, 1.0), ws = r * r * (3 - 2 * r);
            for (int j = 0; j < nv; ++j) {
                const double v = v0 + kTwoPi * j / nv;
                auto& slot = index[std::size_t(i) * std::size_t(nv) + std::size_t(j)];
                if (point && j > 0) {
                    slot = index[std::size_t(i) * std::size_t(nv)];
                    continue;
                }
                const Point p = evaluate(patch, u, v);
                Vec3 x = p.position;
                if (end.bordered() && w > 0) {
                    const Vec3 d = end.pull(patch, v);
                    for (std::size_t c = 0; c < 3; ++c)
                        x[c] += w * d[c];
                }
                if (start.bordered() && ws > 0) {
                    const Vec3 d = start.pull(patch, v);
                    for (std::size_t c = 0; c < 3; ++c)
                        x[c] += ws * d[c];
                }
                slot = std::uint32_t(out_.positions.size());
                out_.positions.push_back(toFloat(x));
                out_.normals.push_back(
                    toFloat(point ? capNormal(patch, i == 0, nv) : unitNormal(p)));
                out_.parameters.push_back({float(u), float(v), 0});
            }
        }
        auto at = [&](int i, int j) {
            return index[std::size_t(i) * std::size_t(nv) + std::size_t(j % nv)];
        };
        for (int i = first; i < rows; ++i)
            for (int j = 0; j < nv; ++j)
                quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        const std::size_t columns = std::size_t(nv);
        if (end.bordered()) {
            // The last grid row (v0 + 2πj/nv) zipped to the ring (end.v[k]).
            const std::vector<std::uint32_t> ring = sharedRing(patch, *loop, end);
            zip(
                columns, ring.size(), [&](std::size_t p) { return at(rows, int(p % columns)); },
                [&](std::size_t p) { return v0 + kTwoPi * double(p) / nv; },
                [&](std::size_t q) { return ring[q % ring.size()]; },
                [&](std::size_t q) { return q < ring.size() ? end.v[q] : v0 + kTwoPi; }, true);
        }
        if (start.bordered()) {
            // The first grid row zipped to the ring below it, the ring's v
            // taken from v0 and started at the point that follows v0 most
            // closely.
            const std::vector<std::uint32_t> ring = sharedRing(patch, *startLoop, start);
            const std::size_t nr = ring.size();
            std::vector<double> rv(nr);
            for (std::size_t k = 0; k < nr; ++k) {
                rv[k] = std::fmod(start.v[k] - v0, kTwoPi);
                if (rv[k] < 0) rv[k] += kTwoPi;
            }
            const std::size_t k0 = std::size_t(std::min_element(rv.begin(), rv.end()) - rv.begin());
            zip(
                columns, nr, [&](std::size_t p) { return at(first, int(p % columns)); },
                [&](std::size_t p) { return kTwoPi * double(p) / nv; },
                [&](std::size_t q) { return ring[(k0 + q) % nr]; },
                [&](std::size_t q) { return q < nr ? rv[(k0 + q) % nr] : rv[k0] + kTwoPi; }, false);
        }
    }

  private:
    // Triangles between a grid row and a border ring, by v: the row's
    // columns p < columns at rowV(p), the ring's points q < points at
    // ringV(q) (at p = columns and q = points: the first again, a turn on),
    // the ring beyond the row in u (`above`: the end border) or before it.
    template <typename RowAt, typename RowV, typename RingAt, typename RingV>
    void zip(std::size_t columns, std::size_t points, RowAt rowAt, RowV rowV, RingAt ringAt,
             RingV ringV, bool above) {
        auto add = [&](std::uint32_t row, std::uint32_t ring, std::uint32_t next) {
            above ? triangle(row, ring, next) : triangle(ring, row, next);
        };
        std::size_t p = 0, q = 0;
        while (p < columns || q < points) {
            if (q < points && (p >= columns || ringV(q + 1) <= rowV(p + 1))) {
                add(rowAt(p), ringAt(q), ringAt(q + 1));
                ++q;
            } else {
                add(rowAt(p), ringAt(q), rowAt(p + 1));
                ++p;
            }
        }
    }

    // The border ring: one vertex per shared point for every patch.
    std::vector<std::uint32_t> sharedRing(const Patch& patch,
                                          const std::vector<std::uint32_t>& loop, const Ring& r) {
        std::vector<std::uint32_t> ring;
        for (std::size_t k = 0; k < r.points.size(); ++k) {
            const std::uint32_t point = loop[k];
            if (shared_[point] < 0) {
                shared_[point] = std::int64_t(out_.positions.size());
                out_.positions.push_back(toFloat(r.points[k]));
                out_.normals.push_back({0, 0, 0});
                out_.parameters.push_back({float(r.u), float(r.v[k]), 0});
            }
            const Vec3 n = unitNormal(evaluate(patch, r.u, r.v[k]));
            for (std::size_t c = 0; c < 3; ++c)
                sharedNormals_[point][c] += n[c];
            ring.push_back(std::uint32_t(shared_[point]));
        }
        return ring;
    }
    static Vec3 capNormal(const Patch& patch, bool start, int nv) {
        // The average of the next ring's normals, seen from the cap's point.
        const double inner = start ? 1e-4 : 1 - 1e-4;
        Vec3 sum{};
        for (int k = 0; k < nv; ++k) {
            const Vec3 n = unitNormal(evaluate(patch, inner, kTwoPi * k / nv));
            for (std::size_t c = 0; c < 3; ++c)
                sum[c] += n[c];
        }
        const double l = std::hypot(sum[0], sum[1], sum[2]);
        return l > 0 ? Vec3{sum[0] / l, sum[1] / l, sum[2] / l} : Vec3{};
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && a != c) out_.triangles.push_back({a, b, c});
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
    mesh::Mesh& out_;
    std::vector<std::int64_t>& shared_;
    std::vector<Vec3>& sharedNormals_;
};

} // namespace

MeshOptions meshOptionsFor(double resolution) {
    const double r = std::isfinite(resolution) ? std::clamp(resolution, 8.0, 4096.0) : 64.0;
    return {std::max(4, int(std::lround(r / 2))), std::max(8, int(std::lround(r)))};
}

BoundedGrid boundedGrid(const Model& model, const MeshOptions& options) {
    BoundedGrid g;
    g.options = options;
    g.options.stepsU = std::clamp(options.stepsU, 1, 4096);
    g.options.stepsV = std::clamp(options.stepsV, 3, 4096);
    const double patches = double(model.patches.size());
    const double cells = patches * g.options.stepsU * g.options.stepsV;
    if (cells <= options.maxCells) return g;
    g.reduced = true;
    const double shrink = std::sqrt(options.maxCells / cells);
    g.options.stepsU = std::max(1, int(g.options.stepsU * shrink));
    g.options.stepsV = std::max(3, int(g.options.stepsV * shrink));
    g.fits = patches * g.options.stepsU * g.options.stepsV <= options.maxCells;
    return g;
}

mesh::Mesh meshModel(const Model& model, const MeshOptions& options) {
    mesh::Mesh out;
    const BoundedGrid grid = boundedGrid(model, options);
    if (!grid.fits) return out;
    const int nu = grid.options.stepsU, nv = grid.options.stepsV;
    const double tolerance = 1e-9 * (model.diagonal() > 0 ? model.diagonal() : 1.0);
    std::vector<std::int64_t> shared(model.borderPoints.size(), -1);
    std::vector<Vec3> sharedNormals(model.borderPoints.size(), Vec3{});
    PatchMesher mesher(out, shared, sharedNormals);
    for (std::size_t i = 0; i < model.patches.size(); ++i) {
        auto valid = [&](const std::vector<std::vector<std::uint32_t>>& all)
            -> const std::vector<std::uint32_t>* {
            if (i >= all.size() || all[i].size() < 3) return nullptr;
            for (std::uint32_t k : all[i])
                if (k >= model.borderPoints.size()) return nullptr;
            return &all[i];
        };
        mesher.mesh(model.patches[i], nu, nv, tolerance, model.borderPoints, valid(model.borders),
                    valid(model.startBorders));
    }
    for (std::size_t k = 0; k < shared.size(); ++k)
        if (shared[k] >= 0) {
            const Vec3& n = sharedNormals[k];
            const double l = std::hypot(n[0], n[1], n[2]);
            if (l > 0)
                out.normals[std::size_t(shared[k])] = toFloat({n[0] / l, n[1] / l, n[2] / l});
        }
    return out;
}

} // namespace fl::pde
