#include "pde_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::pde {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

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

// The v at which the patch's u = 1 curve passes nearest each border point,
// increasing along the loop (unwrapped: v[0] <= ... < v[0] + 2π).
std::vector<double> borderParameters(const Patch& patch, const std::vector<Vec3>& points) {
    const std::size_t n = points.size();
    const std::size_t m = std::clamp<std::size_t>(16 * n, 256, 8192);
    std::vector<Vec3> curve(m);
    for (std::size_t j = 0; j < m; ++j)
        curve[j] = position(patch, 1, kTwoPi * double(j) / double(m));
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

class PatchMesher {
  public:
    PatchMesher(mesh::Mesh& out, std::vector<std::int64_t>& shared,
                std::vector<Vec3>& sharedNormals)
        : out_(out), shared_(shared), sharedNormals_(sharedNormals) {}

    void mesh(const Patch& patch, int nu, int nv, double tolerance, const std::vector<Vec3>& points,
              const std::vector<std::uint32_t>* loop) {
        const bool bordered = loop && loop->size() >= 3;
        std::vector<Vec3> border;
        std::vector<double> bv;
        if (bordered) {
            for (std::uint32_t i : *loop)
                border.push_back(points[i]);
            bv = borderParameters(patch, border);
        }
        const double v0 = bordered ? bv[0] : 0;
        // The pull towards the border, B(v) - X(1, v), with B the loop's
        // polyline at v; weighted by a smoothstep from u = 0.6 to 1.
        auto pull = [&](double v) {
            double w = std::fmod(v - v0, kTwoPi);
            if (w < 0) w += kTwoPi;
            w += v0;
            const auto it = std::upper_bound(bv.begin(), bv.end(), w);
            const std::size_t k = std::size_t(it - bv.begin()) - 1, next = (k + 1) % bv.size();
            const double hi = next == 0 ? bv[0] + kTwoPi : bv[next];
            const double t = hi > bv[k] ? (w - bv[k]) / (hi - bv[k]) : 0;
            const Vec3 x = position(patch, 1, v);
            Vec3 d;
            for (std::size_t c = 0; c < 3; ++c)
                d[c] = border[k][c] + t * (border[next][c] - border[k][c]) - x[c];
            return d;
        };
        const int rows = bordered ? nu - 1 : nu; // the last ring is the border itself
        const bool pointAtStart = patch.cap || ringIsAPoint(patch, 0, nv, tolerance);
        const bool pointAtEnd = !bordered && ringIsAPoint(patch, 1, nv, tolerance);
        std::vector<std::uint32_t> index(std::size_t(rows + 1) * std::size_t(nv));
        for (int i = 0; i <= rows; ++i) {
            const double u = double(i) / nu;
            const bool point = (i == 0 && pointAtStart) || (i == nu && pointAtEnd);
            const double s = std::clamp((u - 0.6) / 0.4, 0.0, 1.0), w = s * s * (3 - 2 * s);
            for (int j = 0; j < nv; ++j) {
                const double v = v0 + kTwoPi * j / nv;
                auto& slot = index[std::size_t(i) * std::size_t(nv) + std::size_t(j)];
                if (point && j > 0) {
                    slot = index[std::size_t(i) * std::size_t(nv)];
                    continue;
                }
                const Point p = evaluate(patch, u, v);
                Vec3 x = p.position;
                if (bordered && w > 0) {
                    const Vec3 d = pull(v);
                    for (std::size_t c = 0; c < 3; ++c)
                        x[c] += w * d[c];
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
        for (int i = 0; i < rows; ++i)
            for (int j = 0; j < nv; ++j)
                quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        if (!bordered) return;
        // The border ring: one vertex per shared point for every patch.
        std::vector<std::uint32_t> ring;
        for (std::size_t k = 0; k < border.size(); ++k) {
            const std::uint32_t point = (*loop)[k];
            if (shared_[point] < 0) {
                shared_[point] = std::int64_t(out_.positions.size());
                out_.positions.push_back(toFloat(border[k]));
                out_.normals.push_back({0, 0, 0});
                out_.parameters.push_back({1, float(bv[k]), 0});
            }
            const Vec3 n = unitNormal(evaluate(patch, 1, bv[k]));
            for (std::size_t c = 0; c < 3; ++c)
                sharedNormals_[point][c] += n[c];
            ring.push_back(std::uint32_t(shared_[point]));
        }
        // Zip the last grid row (v0 + 2πj/nv) to the ring (bv[k]), by v.
        const std::size_t nr = ring.size();
        std::size_t p = 0, q = 0;
        while (p < std::size_t(nv) || q < nr) {
            const double nextTop = v0 + kTwoPi * double(p + 1) / nv;
            const double nextRing = q + 1 < nr ? bv[q + 1] : v0 + kTwoPi;
            const std::uint32_t top = at(rows, int(p % std::size_t(nv)));
            if (q < nr && (p >= std::size_t(nv) || nextRing <= nextTop)) {
                triangle(top, ring[q % nr], ring[(q + 1) % nr]);
                ++q;
            } else {
                triangle(top, ring[q % nr], at(rows, int((p + 1) % std::size_t(nv))));
                ++p;
            }
        }
    }

  private:
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
        const auto* loop = i < model.borders.size() ? &model.borders[i] : nullptr;
        bool valid = loop && loop->size() >= 3;
        if (valid)
            for (std::uint32_t k : *loop)
                valid = valid && k < model.borderPoints.size();
        mesher.mesh(model.patches[i], nu, nv, tolerance, model.borderPoints,
                    valid ? loop : nullptr);
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
