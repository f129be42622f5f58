#include "parametric.h"

#include "parameter_lines.h"

#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

namespace fl::mesh {
namespace {

// The default chord tolerance: this fraction of a cell of the resolution.
constexpr double kToleranceOfACell = 0.02;

using formula::Input;

using field::cross;
using field::dot;
using field::minus;

// field::unitOr, with a flag: the frames below fall back in several steps.
Vec3 unit(const Vec3& a, bool& ok) {
    const Vec3 u = field::unitOr(a, {0, 0, 0});
    ok = u != Vec3{0, 0, 0};
    return u;
}

class Builder {
  public:
    Builder(const ParametricField& field, MeshResult& out)
        : field_(field), out_(out), sampler_(field) {}

    // A grid of samples over two parameters (a, b) at the parameter lines
    // `la` and `lb`, the third fixed at `fixed`; triangles oriented along
    // a x b, or reversed.
    void patch(int a, int b, const std::vector<double>& la, const std::vector<double>& lb,
               std::array<double, 3> fixed, bool reversed) {
        const int n = int(la.size()) - 1, m = int(lb.size()) - 1;
        const std::size_t base = positions_.size();
        const std::size_t count = std::size_t(n + 1) * std::size_t(m + 1);
        std::array<std::vector<double>, 3> in;
        for (auto& v : in)
            v.assign(count, 0);
        for (int j = 0; j <= m; ++j)
            for (int i = 0; i <= n; ++i) {
                std::array<double, 3> q = fixed;
                q[std::size_t(a)] = la[std::size_t(i)];
                q[std::size_t(b)] = lb[std::size_t(j)];
                for (std::size_t k = 0; k < 3; ++k)
                    in[k][std::size_t(j) * std::size_t(n + 1) + std::size_t(i)] = q[k];
            }
        sample(in, count);
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < n; ++i) {
                const auto at = [&](int ii, int jj) {
                    return std::uint32_t(base + std::size_t(jj) * std::size_t(n + 1) +
                                         std::size_t(ii));
                };
                Triangle t0{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
                Triangle t1{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
                if (reversed) {
                    std::swap(t0[1], t0[2]);
                    std::swap(t1[1], t1[2]);
                }
                triangles_.push_back(t0);
                triangles_.push_back(t1);
            }
        // Normals from the partial derivatives along the patch's parameters.
        for (std::size_t i = 0; i < count; ++i) {
            formula::Dual d[3];
            sampler_.partials(in[0][i], in[1][i], in[2][i], d);
            ++out_.stats.evaluations.gradients;
            const Vec3 pa{d[0].d[std::size_t(a)], d[1].d[std::size_t(a)], d[2].d[std::size_t(a)]};
            const Vec3 pb{d[0].d[std::size_t(b)], d[1].d[std::size_t(b)], d[2].d[std::size_t(b)]};
            bool ok = false;
            Vec3 nrm = unit(cross(pa, pb), ok);
            if (reversed) nrm = {-nrm[0], -nrm[1], -nrm[2]};
            normals_[base + i] = nrm;
        }
    }

    // A curve: a ring of `sides` vertices around each sample, carried along
    // by parallel transport so the tube does not twist.
    void tube(int a, const std::vector<double>& la, double radius, int sides) {
        const int n = int(la.size()) - 1;
        std::array<std::vector<double>, 3> in;
        for (auto& v : in)
            v.assign(std::size_t(n + 1), 0);
        for (int i = 0; i <= n; ++i) {
            for (std::size_t k = 0; k < 3; ++k)
                in[k][std::size_t(i)] = field_.ranges[k][0];
            in[std::size_t(a)][std::size_t(i)] = la[std::size_t(i)];
        }
        std::vector<Vec3> centre(std::size_t(n + 1)), tangent(std::size_t(n + 1));
        std::array<std::vector<double>, 3> xyz;
        evaluate(in, std::size_t(n + 1), xyz);
        for (int i = 0; i <= n; ++i) {
            centre[std::size_t(i)] = {xyz[0][std::size_t(i)], xyz[1][std::size_t(i)],
                                      xyz[2][std::size_t(i)]};
            formula::Dual d[3];
            sampler_.partials(in[0][std::size_t(i)], in[1][std::size_t(i)], in[2][std::size_t(i)],
                              d);
            ++out_.stats.evaluations.gradients;
            bool ok = false;
            tangent[std::size_t(i)] =
                unit({d[0].d[std::size_t(a)], d[1].d[std::size_t(a)], d[2].d[std::size_t(a)]}, ok);
            if (!ok) tangent[std::size_t(i)] = i ? tangent[std::size_t(i - 1)] : Vec3{1, 0, 0};
        }
        // A first normal across the tangent, then transported.
        bool ok = false;
        Vec3 side = unit(cross(tangent[0], Vec3{0, 0, 1}), ok);
        if (!ok) side = unit(cross(tangent[0], Vec3{1, 0, 0}), ok);
        const std::size_t base = positions_.size();
        for (int i = 0; i <= n; ++i) {
            const Vec3& T = tangent[std::size_t(i)];
            // Remove the part along the new tangent: the smallest turn.
            const double along = dot(side, T);
            side =
                unit({side[0] - along * T[0], side[1] - along * T[1], side[2] - along * T[2]}, ok);
            if (!ok) side = unit(cross(T, Vec3{0, 0, 1}), ok);
            const Vec3 up = cross(T, side);
            for (int s = 0; s < sides; ++s) {
                const double angle = 2 * M_PI * s / sides;
                const Vec3 dir{std::cos(angle) * side[0] + std::sin(angle) * up[0],
                               std::cos(angle) * side[1] + std::sin(angle) * up[1],
                               std::cos(angle) * side[2] + std::sin(angle) * up[2]};
                const Vec3& c = centre[std::size_t(i)];
                positions_.push_back(
                    {c[0] + radius * dir[0], c[1] + radius * dir[1], c[2] + radius * dir[2]});
                normals_.push_back(dir);
                std::array<double, 3> q{in[0][std::size_t(i)], in[1][std::size_t(i)],
                                        in[2][std::size_t(i)]};
                params_.push_back(q);
            }
        }
        for (int i = 0; i < n; ++i)
            for (int s = 0; s < sides; ++s) {
                const auto at = [&](int ii, int ss) {
                    return std::uint32_t(base + std::size_t(ii) * std::size_t(sides) +
                                         std::size_t(ss % sides));
                };
                // Around T counter-clockwise, then along T: facing out.
                triangles_.push_back({at(i, s), at(i + 1, s + 1), at(i + 1, s)});
                triangles_.push_back({at(i, s), at(i, s + 1), at(i + 1, s + 1)});
            }
        // Caps, so the tube is closed.
        for (int end : {0, n}) {
            const std::size_t centreIndex = positions_.size();
            positions_.push_back(centre[std::size_t(end)]);
            const Vec3& T = tangent[std::size_t(end)];
            normals_.push_back(end == 0 ? Vec3{-T[0], -T[1], -T[2]} : T);
            params_.push_back(
                {in[0][std::size_t(end)], in[1][std::size_t(end)], in[2][std::size_t(end)]});
            for (int s = 0; s < sides; ++s) {
                const std::uint32_t p0 =
                    std::uint32_t(base + std::size_t(end) * std::size_t(sides) + std::size_t(s));
                const std::uint32_t p1 = std::uint32_t(
                    base + std::size_t(end) * std::size_t(sides) + std::size_t((s + 1) % sides));
                if (end == 0)
                    triangles_.push_back({std::uint32_t(centreIndex), p1, p0});
                else
                    triangles_.push_back({std::uint32_t(centreIndex), p0, p1});
            }
        }
    }

    // Weld coincident vertices (seams, poles), drop what collapses, give
    // welded and degenerate vertices the normals of their triangles.
    // `tolerance`: points closer than this are one (a small fraction of the
    // sampling step, so a range written as 6.2831853 still closes its seam).
    Mesh finish(double tolerance) {
        Mesh m;
        tolerance = std::max(tolerance, 1e-300);
        std::map<std::array<long long, 3>, std::uint32_t> cells;
        std::vector<std::uint32_t> remap(positions_.size());
        std::vector<Vec3> normalSum;
        std::vector<bool> bad;
        for (std::size_t i = 0; i < positions_.size(); ++i) {
            const Vec3& p = positions_[i];
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
                remap[i] = UINT32_MAX;
                sawNaN_ = true;
                continue;
            }
            const std::array<long long, 3> key{std::llround(p[0] / tolerance),
                                               std::llround(p[1] / tolerance),
                                               std::llround(p[2] / tolerance)};
            // The point may sit in a neighbouring cell of the one it rounds to.
            std::uint32_t found = UINT32_MAX;
            for (int n = 0; n < 27 && found == UINT32_MAX; ++n) {
                const std::array<long long, 3> near{key[0] + n % 3 - 1, key[1] + n / 3 % 3 - 1,
                                                    key[2] + n / 9 - 1};
                auto it = cells.find(near);
                if (it == cells.end()) continue;
                const Vec3& q = welded_[it->second];
                if (std::abs(q[0] - p[0]) <= tolerance && std::abs(q[1] - p[1]) <= tolerance &&
                    std::abs(q[2] - p[2]) <= tolerance)
                    found = it->second;
            }
            if (found == UINT32_MAX) {
                found = std::uint32_t(m.positions.size());
                cells.emplace(key, found);
                welded_.push_back(p);
                m.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
                m.parameters.push_back(
                    {float(params_[i][0]), float(params_[i][1]), float(params_[i][2])});
                normalSum.push_back({0, 0, 0});
            }
            remap[i] = found;
            for (std::size_t k = 0; k < 3; ++k)
                normalSum[found][k] += normals_[i][k];
        }
        std::vector<Vec3> faceSum(m.positions.size(), Vec3{0, 0, 0});
        for (Triangle t : triangles_) {
            for (auto& i : t)
                i = remap[i];
            if (t[0] == UINT32_MAX || t[1] == UINT32_MAX || t[2] == UINT32_MAX) continue;
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue; // collapsed at a pole
            const auto P = [&](std::uint32_t i) {
                return Vec3{m.positions[i][0], m.positions[i][1], m.positions[i][2]};
            };
            const Vec3 n = cross(minus(P(t[1]), P(t[0])), minus(P(t[2]), P(t[0])));
            if (!(dot(n, n) > 0)) continue; // zero area
            m.triangles.push_back(t);
            for (std::uint32_t i : t)
                for (std::size_t k = 0; k < 3; ++k)
                    faceSum[i][k] += n[k];
        }
        // Faces of a solid's parameter box that map onto each other (a ball's
        // u = 0 and u = 2 pi) meet back to back inside the solid: both go.
        {
            std::map<std::array<std::uint32_t, 3>, std::size_t> seen;
            std::vector<bool> drop(m.triangles.size(), false);
            for (std::size_t i = 0; i < m.triangles.size(); ++i) {
                std::array<std::uint32_t, 3> key = m.triangles[i];
                std::sort(key.begin(), key.end());
                auto [it, added] = seen.emplace(key, i);
                if (added) continue;
                if (it->second != SIZE_MAX && !drop[it->second]) {
                    drop[it->second] = drop[i] = true;
                    it->second = SIZE_MAX; // a third copy stays
                }
            }
            std::vector<Triangle> kept;
            for (std::size_t i = 0; i < m.triangles.size(); ++i)
                if (!drop[i]) kept.push_back(m.triangles[i]);
            if (kept.size() != m.triangles.size()) {
                m.triangles = std::move(kept);
                std::fill(faceSum.begin(), faceSum.end(), Vec3{0, 0, 0});
                for (const Triangle& t : m.triangles) {
                    const auto P = [&](std::uint32_t i) {
                        return Vec3{m.positions[i][0], m.positions[i][1], m.positions[i][2]};
                    };
                    const Vec3 n = cross(minus(P(t[1]), P(t[0])), minus(P(t[2]), P(t[0])));
                    for (std::uint32_t i : t)
                        for (std::size_t k = 0; k < 3; ++k)
                            faceSum[i][k] += n[k];
                }
            }
        }
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            bool ok = false;
            Vec3 n = unit(normalSum[i], ok);
            // A welded seam vertex keeps the mean of its normals; where they
            // cancel or vanish (a pole), the surrounding triangles decide.
            if (!ok || dot(n, unit(faceSum[i], ok)) < 0.5) {
                bool faceOk = false;
                const Vec3 f = unit(faceSum[i], faceOk);
                if (faceOk)
                    n = f;
                else if (!ok)
                    n = {0, 0, 1};
            }
            m.normals.push_back({float(n[0]), float(n[1]), float(n[2])});
        }
        return m;
    }

    bool sawNaN() const { return sawNaN_; }

  private:
  public:
    void evaluate(const std::array<std::vector<double>, 3>& in, std::size_t count,
                  std::array<std::vector<double>, 3>& xyz) {
        sampler_.positions(in, count, xyz);
        out_.stats.evaluations.points += count;
    }

  private:
    void sample(const std::array<std::vector<double>, 3>& in, std::size_t count) {
        std::array<std::vector<double>, 3> xyz;
        evaluate(in, count, xyz);
        for (std::size_t i = 0; i < count; ++i) {
            positions_.push_back({xyz[0][i], xyz[1][i], xyz[2][i]});
            params_.push_back({in[0][i], in[1][i], in[2][i]});
            normals_.push_back({0, 0, 0});
        }
    }

    const ParametricField& field_;
    MeshResult& out_;
    ParametricSampler sampler_;
    std::vector<Vec3> positions_, normals_, params_;
    std::vector<Vec3> welded_; // positions of the welded vertices, in double
    std::vector<Triangle> triangles_;
    bool sawNaN_ = false;
};

} // namespace

MeshResult meshParametric(const ParametricField& field, const ParametricOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    MeshResult result;
    const std::vector<int> used = usedParameters(field, result.error);
    if (!result.error.empty()) return result;
    if (!(options.resolution >= 1) || !std::isfinite(options.resolution) ||
        options.resolution > 4096) {
        result.error = "the resolution of parametric geometry must lie in 1..4096";
        return result;
    }
    const int n = std::max(1, int(std::lround(options.resolution)));
    Builder b(field, result);
    double extent = 0;
    for (const auto& p : {field.box.size(0), field.box.size(1), field.box.size(2)})
        extent = std::max(extent, p);
    ParameterLineOptions lo;
    if (options.adaptive) {
        // From a quarter of the resolution, halving spans up to four times
        // finer, until the chords stay within the tolerance.
        lo.baseSegments = std::max(2, (n + 3) / 4);
        lo.maxSegments = std::min(4096, 4 * n);
        lo.tolerance = options.tolerance > 0 ? options.tolerance
                                             : kToleranceOfACell * std::max(extent, 1e-9) / n;
    } else {
        lo.baseSegments = lo.maxSegments = n;
    }
    const ParameterLines lines = parameterLines(
        used, field.ranges, lo,
        [&](const std::array<std::vector<double>, 3>& uvw, std::size_t count,
            std::array<std::vector<double>, 3>& xyz) { b.evaluate(uvw, count, xyz); });
    result.stats.chordError = lines.worstDeviation;
    std::size_t finest = 1;
    for (int p : used)
        finest = std::max(finest, lines.lines[std::size_t(p)].size() - 1);
    switch (used.size()) {
    case 0:
        result.warnings.push_back(
            "the parametric definition reads none of u, v, w: it is a single point, "
            "and nothing is meshed");
        break;
    case 1: {
        const double radius =
            options.tubeRadius > 0 ? options.tubeRadius : 0.01 * field.box.diagonal();
        b.tube(used[0], lines.lines[std::size_t(used[0])], radius, std::max(3, options.tubeSides));
        break;
    }
    case 2: {
        std::array<double, 3> fixed{field.ranges[0][0], field.ranges[1][0], field.ranges[2][0]};
        b.patch(used[0], used[1], lines.lines[std::size_t(used[0])],
                lines.lines[std::size_t(used[1])], fixed, false);
        break;
    }
    default: {
        // A solid: its six boundary faces, each facing out of the parameter
        // cube (a mirroring parametrisation is turned round below).
        for (int axis = 0; axis < 3; ++axis) {
            const int a = (axis + 1) % 3, c = (axis + 2) % 3;
            for (int side = 0; side < 2; ++side) {
                std::array<double, 3> fixed{field.ranges[0][0], field.ranges[1][0],
                                            field.ranges[2][0]};
                fixed[std::size_t(axis)] = field.ranges[std::size_t(axis)][std::size_t(side)];
                b.patch(a, c, lines.lines[std::size_t(a)], lines.lines[std::size_t(c)], fixed,
                        side == 0);
            }
        }
        break;
    }
    }
    // Weld within a thousandth of the finest step between samples.
    result.mesh = b.finish(1e-3 * std::max(extent, 1e-9) / double(finest));
    if (used.size() == 3) {
        // The parametrisation's orientation: the Jacobian's sign at the centre.
        formula::GradientEvaluator g(field.tape, {Input::U, Input::V, Input::W});
        for (const auto& [name, v] : field.parameters)
            g.parameters().set(name, v);
        formula::Dual d[3];
        g.evaluateAll({0, 0, 0, field.t, (field.ranges[0][0] + field.ranges[0][1]) / 2,
                       (field.ranges[1][0] + field.ranges[1][1]) / 2,
                       (field.ranges[2][0] + field.ranges[2][1]) / 2},
                      d);
        const double det = d[0].d[0] * (d[1].d[1] * d[2].d[2] - d[1].d[2] * d[2].d[1]) -
                           d[0].d[1] * (d[1].d[0] * d[2].d[2] - d[1].d[2] * d[2].d[0]) +
                           d[0].d[2] * (d[1].d[0] * d[2].d[1] - d[1].d[1] * d[2].d[0]);
        if (det < 0) {
            for (Triangle& t : result.mesh.triangles)
                std::swap(t[1], t[2]);
            for (Vec3f& nn : result.mesh.normals)
                nn = {-nn[0], -nn[1], -nn[2]};
        }
    }
    if (b.sawNaN())
        result.warnings.push_back(
            "x, y or z is undefined (NaN) for some parameter values; the mesh "
            "leaves those points out");
    result.stats.surfaceCells = result.mesh.vertexCount();
    result.stats.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::vector<int> usedParameters(const ParametricField& field, std::string& error) {
    std::vector<int> used;
    if (field.tape.outputs.size() != 3) {
        error = "parametric geometry must assign x, y and z";
        return used;
    }
    for (int p = 0; p < 3; ++p)
        if (field.tape.usesInput[std::size_t(int(Input::U) + p)]) used.push_back(p);
    for (int p : used) {
        const auto& r = field.ranges[std::size_t(p)];
        if (!std::isfinite(r[0]) || !std::isfinite(r[1]) || !(r[1] > r[0])) {
            error = "the ";
            error += "uvw"[p];
            error += "Range must go from low to high";
            return {};
        }
    }
    return used;
}

ParametricSampler::ParametricSampler(const ParametricField& field)
    : t_(field.t), batch_(field.tape), gradient_(field.tape, {Input::U, Input::V, Input::W}) {
    for (const auto& [name, v] : field.parameters) {
        batch_.parameters().set(name, v);
        gradient_.parameters().set(name, v);
    }
}

void ParametricSampler::positions(const std::array<std::vector<double>, 3>& uvw, std::size_t count,
                                  std::array<std::vector<double>, 3>& xyz) {
    formula::BatchInputs inputs;
    inputs.set(Input::X, 0.0);
    inputs.set(Input::Y, 0.0);
    inputs.set(Input::Z, 0.0);
    inputs.set(Input::T, t_);
    inputs.set(Input::U, uvw[0].data());
    inputs.set(Input::V, uvw[1].data());
    inputs.set(Input::W, uvw[2].data());
    for (auto& v : xyz)
        v.assign(count, 0);
    double* outs[3] = {xyz[0].data(), xyz[1].data(), xyz[2].data()};
    batch_.evaluate(inputs, count, outs);
}

void ParametricSampler::partials(double u, double v, double w, formula::Dual out[3]) {
    gradient_.evaluateAll({0, 0, 0, t_, u, v, w}, out);
}

} // namespace fl::mesh
