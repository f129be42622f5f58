#include "point_cloud.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

namespace fl::mesh {
namespace {

using formula::Input;

constexpr std::size_t kMaxPoints = 10'000'000;
constexpr std::size_t kChunk = 4096; // points evaluated per call

double elapsedMs(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// Uniform in [0, 1) from the generator, the same on every standard library
// (std::uniform_real_distribution is not).
double unit(std::mt19937& rng) {
    return double(rng() >> 5) * (1.0 / 134217728.0); // 27 bits: plenty for a place in a cell
}

bool tooMany(std::size_t count, MeshResult& result) {
    if (count == 0 || count > kMaxPoints) {
        result.error =
            "a point cloud needs between 1 and " + std::to_string(kMaxPoints) + " points";
        return true;
    }
    return false;
}

Vec3f toFloat(const Vec3& v) {
    return {float(v[0]), float(v[1]), float(v[2])};
}

} // namespace

MeshResult pointsOnSurface(const ImplicitField& field, const PointCloudOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    MeshResult result;
    if (tooMany(options.count, result)) return result;
    // A mesh fine enough to have the surface's shape and pieces; the points'
    // accuracy comes from the Newton steps, not from it.
    MeshOptions mo;
    mo.resolution = std::clamp(std::sqrt(double(options.count)) / 3, 16.0, 96.0);
    mo.threads = options.threads;
    MeshResult base = meshImplicit(field, mo);
    result.warnings = base.warnings;
    result.stats = base.stats;
    result.mesh.primitive = Primitive::Points;
    if (!base.ok() || base.mesh.empty()) {
        result.error = base.error;
        result.cancelled = base.cancelled;
        result.stats.milliseconds = elapsedMs(start);
        return result;
    }
    const Mesh& m = base.mesh;
    std::vector<double> cumulative(m.triangleCount());
    double total = 0;
    for (std::size_t i = 0; i < m.triangleCount(); ++i) {
        const Triangle& t = m.triangles[i];
        Vec3 e1{}, e2{};
        for (std::size_t k = 0; k < 3; ++k) {
            e1[k] = double(m.positions[t[1]][k]) - m.positions[t[0]][k];
            e2[k] = double(m.positions[t[2]][k]) - m.positions[t[0]][k];
        }
        total += 0.5 * field::length(field::cross(e1, e2));
        cumulative[i] = total;
    }
    std::mt19937 rng(options.seed);
    std::vector<Vec3> points(options.count);
    std::vector<Vec3f> faceNormal(options.count);
    for (std::size_t i = 0; i < options.count; ++i) {
        const double pick = unit(rng) * total;
        const std::size_t ti = std::min<std::size_t>(
            std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                        cumulative.begin()),
            cumulative.size() - 1);
        const Triangle& t = m.triangles[ti];
        // Uniform over the triangle: the square-root warp of two numbers.
        const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
        const double a = 1 - r1, b = r1 * (1 - r2), c = r1 * r2;
        for (std::size_t k = 0; k < 3; ++k)
            points[i][k] =
                a * m.positions[t[0]][k] + b * m.positions[t[1]][k] + c * m.positions[t[2]][k];
        faceNormal[i] = m.normals[t[0]]; // replaced by the gradient's below where there is one
    }
    // Onto f = 0: Newton steps along the gradient, all points at once; a step
    // longer than two cells (a point that would jump to another sheet) and
    // points on the faces of a closed box stay where the mesh put them.
    const double cell = field.box.longestSide() / mo.resolution;
    auto onBoxFace = [&](const Vec3& p) {
        if (field.boundary != BoxBoundary::Closed) return false;
        for (std::size_t k = 0; k < 3; ++k)
            if (std::abs(p[k] - field.box.lo[k]) < 1e-6 * cell ||
                std::abs(p[k] - field.box.hi[k]) < 1e-6 * cell)
                return true;
        return false;
    };
    FieldSampler sampler(field);
    std::vector<formula::Dual> grad(points.size());
    std::vector<bool> fixed(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        fixed[i] = onBoxFace(points[i]);
    for (int step = 0; step < 3; ++step) {
        sampler.gradients(points.data(), points.size(), grad.data());
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (fixed[i]) continue;
            const formula::Dual& d = grad[i];
            const double g2 = d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2];
            if (!(g2 > 0) || !std::isfinite(d.v)) continue;
            const double s = d.v / g2;
            if (!(std::abs(s) * std::sqrt(g2) <= 2 * cell)) continue;
            for (std::size_t k = 0; k < 3; ++k)
                points[i][k] -= s * d.d[k];
        }
    }
    sampler.gradients(points.data(), points.size(), grad.data());
    Mesh& out = result.mesh;
    out.positions.reserve(points.size());
    out.normals.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        out.positions.push_back(toFloat(points[i]));
        const formula::Dual& d = grad[i];
        const double g = std::sqrt(d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2]);
        // f > 0 inside: the gradient points in, the normal out.
        if (!fixed[i] && std::isfinite(g) && g > 0)
            out.normals.push_back(toFloat({-d.d[0] / g, -d.d[1] / g, -d.d[2] / g}));
        else
            out.normals.push_back(faceNormal[i]);
    }
    result.stats.evaluations += sampler.counts();
    result.stats.milliseconds = elapsedMs(start);
    return result;
}

MeshResult pointsInSolid(const ImplicitField& field, const PointCloudOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    MeshResult result;
    result.mesh.primitive = Primitive::Points;
    if (tooMany(options.count, result)) return result;
    if (!field.box.valid()) {
        result.error = "the domain box must be finite with max above min on every axis";
        return result;
    }
    FieldSampler sampler(field);
    std::vector<double> xs, ys, zs, fs;
    auto evaluate = [&] {
        fs.resize(xs.size());
        if (!xs.empty()) sampler.values(xs.data(), ys.data(), zs.data(), xs.size(), fs.data());
    };
    // How much of the box is inside: a probe grid of 24^3 cell centres.
    constexpr int kProbe = 24;
    for (int k = 0; k < kProbe; ++k)
        for (int j = 0; j < kProbe; ++j)
            for (int i = 0; i < kProbe; ++i) {
                xs.push_back(field.box.lo[0] + (i + 0.5) / kProbe * field.box.size(0));
                ys.push_back(field.box.lo[1] + (j + 0.5) / kProbe * field.box.size(1));
                zs.push_back(field.box.lo[2] + (k + 0.5) / kProbe * field.box.size(2));
            }
    evaluate();
    const std::size_t insideProbes =
        std::size_t(std::count_if(fs.begin(), fs.end(), [](double f) { return f > 0; }));
    if (insideProbes == 0) {
        result.warnings.push_back(
            "no point of a 24^3 probe grid is inside the solid (f > 0): it is empty or thinner "
            "than 1/24 of the box; draw it as points on its surface (type \"implicit\") instead");
        result.stats.evaluations = sampler.counts();
        result.stats.milliseconds = elapsedMs(start);
        return result;
    }
    const double fraction = double(insideProbes) / double(fs.size());
    const double volume = field.box.size(0) * field.box.size(1) * field.box.size(2);
    const double side = std::cbrt(volume * fraction / double(options.count));
    std::array<long, 3> n{};
    for (std::size_t a = 0; a < 3; ++a)
        n[a] = std::max(1L, long(std::ceil(field.box.size(int(a)) / side)));
    if (double(n[0]) * double(n[1]) * double(n[2]) > 64.0 * double(kMaxPoints)) {
        result.error = "the solid fills too little of its box for a point cloud of " +
                       std::to_string(options.count) + " points; shrink the domain box";
        return result;
    }
    std::mt19937 rng(options.seed);
    bool sawNaN = false;
    Mesh& out = result.mesh;
    const long total = n[0] * n[1] * n[2];
    for (long first = 0; first < total; first += long(kChunk)) {
        const long last = std::min(total, first + long(kChunk));
        xs.clear();
        ys.clear();
        zs.clear();
        for (long c = first; c < last; ++c) {
            const long i = c % n[0], j = c / n[0] % n[1], k = c / (n[0] * n[1]);
            xs.push_back(field.box.lo[0] +
                         (double(i) + unit(rng)) / double(n[0]) * field.box.size(0));
            ys.push_back(field.box.lo[1] +
                         (double(j) + unit(rng)) / double(n[1]) * field.box.size(1));
            zs.push_back(field.box.lo[2] +
                         (double(k) + unit(rng)) / double(n[2]) * field.box.size(2));
        }
        evaluate();
        for (std::size_t p = 0; p < fs.size(); ++p) {
            if (std::isnan(fs[p])) sawNaN = true;
            if (!(fs[p] > 0)) continue;
            out.positions.push_back({float(xs[p]), float(ys[p]), float(zs[p])});
            out.normals.push_back({0, 0, 0});
        }
    }
    if (sawNaN)
        result.warnings.push_back("the function is undefined (NaN) in part of the box; the "
                                  "points fill only where it is defined");
    result.stats.evaluations = sampler.counts();
    result.stats.milliseconds = elapsedMs(start);
    return result;
}

MeshResult pointsOverParameters(const ParametricField& field, const PointCloudOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    MeshResult result;
    result.mesh.primitive = Primitive::Points;
    if (tooMany(options.count, result)) return result;
    std::vector<int> used = usedParameters(field, result.error);
    if (!result.error.empty()) return result;
    if (used.empty()) {
        result.warnings.push_back("the parametric definition reads none of u, v, w: it is a "
                                  "single point");
    }
    // Samples per used parameter: about count^(1/k) each.
    const long per =
        used.empty()
            ? 1
            : std::max(2L, std::lround(std::pow(double(options.count), 1.0 / double(used.size()))));
    std::array<long, 3> n{1, 1, 1};
    for (int p : used)
        n[std::size_t(p)] = per;
    const long total = n[0] * n[1] * n[2];
    std::array<std::vector<double>, 3> uvw;
    for (auto& v : uvw)
        v.reserve(std::size_t(total));
    for (long c = 0; c < total; ++c) {
        const long idx[3] = {c % n[0], c / n[0] % n[1], c / (n[0] * n[1])};
        for (std::size_t a = 0; a < 3; ++a) {
            const auto& r = field.ranges[a];
            uvw[a].push_back(n[a] == 1 ? r[0]
                                       : r[0] + (r[1] - r[0]) * double(idx[a]) / double(n[a] - 1));
        }
    }
    ParametricSampler sampler(field);
    std::array<std::vector<double>, 3> xyz;
    sampler.positions(uvw, std::size_t(total), xyz);
    result.stats.evaluations.points = std::size_t(total);
    Mesh& out = result.mesh;
    bool sawNaN = false;
    for (std::size_t i = 0; i < std::size_t(total); ++i) {
        const Vec3 p{xyz[0][i], xyz[1][i], xyz[2][i]};
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            sawNaN = true;
            continue;
        }
        Vec3f normal{0, 0, 0};
        if (used.size() == 2) { // a surface: the cross product of its partial derivatives
            formula::Dual d[3];
            sampler.partials(uvw[0][i], uvw[1][i], uvw[2][i], d);
            ++result.stats.evaluations.gradients;
            const auto a = std::size_t(used[0]), b = std::size_t(used[1]);
            const Vec3 pa{d[0].d[a], d[1].d[a], d[2].d[a]}, pb{d[0].d[b], d[1].d[b], d[2].d[b]};
            const Vec3 c{pa[1] * pb[2] - pa[2] * pb[1], pa[2] * pb[0] - pa[0] * pb[2],
                         pa[0] * pb[1] - pa[1] * pb[0]};
            const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            if (std::isfinite(len) && len > 0)
                normal = toFloat({c[0] / len, c[1] / len, c[2] / len});
        }
        out.positions.push_back(toFloat(p));
        out.normals.push_back(normal);
        out.parameters.push_back({float(uvw[0][i]), float(uvw[1][i]), float(uvw[2][i])});
    }
    if (sawNaN)
        result.warnings.push_back("x, y or z is undefined (NaN) for some parameter values; "
                                  "those points are left out");
    result.stats.milliseconds = elapsedMs(start);
    return result;
}

} // namespace fl::mesh
