#include "pde_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::pde {
namespace {

mesh::Vec3f toFloat(const Vec3& p) {
    return {float(p[0]), float(p[1]), float(p[2])};
}

Vec3 unitNormal(const Point& p) {
    const Vec3 n{p.du[1] * p.dv[2] - p.du[2] * p.dv[1], p.du[2] * p.dv[0] - p.du[0] * p.dv[2],
                 p.du[0] * p.dv[1] - p.du[1] * p.dv[0]};
    const double l = std::hypot(n[0], n[1], n[2]);
    return l > 0 ? Vec3{n[0] / l, n[1] / l, n[2] / l} : Vec3{};
}

// Whether the ring at u lies within `tolerance` of one point.
bool ringIsAPoint(const Patch& patch, double u, int steps, double tolerance) {
    const Vec3 first = position(patch, u, 0);
    for (int j = 1; j < steps; ++j) {
        const Vec3 p = position(patch, u, 2 * std::numbers::pi * j / steps);
        if (std::hypot(p[0] - first[0], p[1] - first[1], p[2] - first[2]) > tolerance) return false;
    }
    return true;
}

void meshPatch(const Patch& patch, int nu, int nv, double tolerance, mesh::Mesh& out) {
    const bool pointAtStart = ringIsAPoint(patch, 0, nv, tolerance);
    const bool pointAtEnd = ringIsAPoint(patch, 1, nv, tolerance);
    std::vector<std::uint32_t> index(std::size_t(nu + 1) * std::size_t(nv));
    for (int i = 0; i <= nu; ++i) {
        const double u = double(i) / nu;
        const bool point = (i == 0 && pointAtStart) || (i == nu && pointAtEnd);
        for (int j = 0; j < nv; ++j) {
            const double v = 2 * std::numbers::pi * j / nv;
            if (point && j > 0) {
                index[std::size_t(i) * std::size_t(nv) + std::size_t(j)] =
                    index[std::size_t(i) * std::size_t(nv)];
                continue;
            }
            const Point p = evaluate(patch, u, v);
            if (point) {
                // The cap's normal: the average of the next ring's, seen from here.
                const double inner = i == 0 ? 1e-4 : 1 - 1e-4;
                Vec3 sum{};
                for (int k = 0; k < nv; ++k) {
                    const Vec3 n =
                        unitNormal(evaluate(patch, inner, 2 * std::numbers::pi * k / nv));
                    for (int c = 0; c < 3; ++c)
                        sum[std::size_t(c)] += n[std::size_t(c)];
                }
                const double l = std::hypot(sum[0], sum[1], sum[2]);
                out.normals.push_back(
                    l > 0 ? mesh::Vec3f{float(sum[0] / l), float(sum[1] / l), float(sum[2] / l)}
                          : mesh::Vec3f{0, 0, 0});
            } else {
                out.normals.push_back(toFloat(unitNormal(p)));
            }
            index[std::size_t(i) * std::size_t(nv) + std::size_t(j)] =
                std::uint32_t(out.positions.size());
            out.positions.push_back(toFloat(p.position));
            out.parameters.push_back({float(u), float(v), 0});
        }
    }
    auto at = [&](int i, int j) {
        return index[std::size_t(i) * std::size_t(nv) + std::size_t(j % nv)];
    };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1),
                                d = at(i, j + 1);
            if (a != b && b != c && a != c) out.triangles.push_back({a, b, c});
            if (a != c && c != d && a != d) out.triangles.push_back({a, c, d});
        }
}

} // namespace

MeshOptions meshOptionsFor(double resolution) {
    const double r = std::isfinite(resolution) ? std::clamp(resolution, 8.0, 4096.0) : 64.0;
    return {std::max(4, int(std::lround(r / 2))), std::max(8, int(std::lround(r)))};
}

mesh::Mesh meshModel(const Model& model, const MeshOptions& options) {
    mesh::Mesh out;
    const int nu = std::clamp(options.stepsU, 1, 4096), nv = std::clamp(options.stepsV, 3, 4096);
    const double tolerance = 1e-9 * (model.diagonal() > 0 ? model.diagonal() : 1.0);
    for (const Patch& p : model.patches)
        meshPatch(p, nu, nv, tolerance, out);
    return out;
}

} // namespace fl::pde
