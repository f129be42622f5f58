#include "mesh_fit.h"

#include "border_curves.h"
#include "disk_map.h"
#include "mesh_regions.h"
#include "patch_solve.h"

#include "field/vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fl::pde {
namespace {

struct FittedRegion {
    Faces faces;
    Patch patch;
    double missed = 0; // Σ w |X - p|²
    double weight = 0; // Σ w
    bool disk = false;
};

constexpr double kReach = 0.05; // how far correction may move a sample in u (2x in v)

// Two Gauss-Newton steps towards the point of `patch` nearest the sample,
// never far from where the disk map put it (`mapped`): the samples must
// keep covering the disk, or the patch would wander where none are left.
void correctParameters(const Patch& patch, Sample& s, const Sample& mapped, bool onBorder) {
    for (int step = 0; step < 2; ++step) {
        const Point x = evaluate(patch, s.u, s.v);
        const Vec3 r{s.point[0] - x.position[0], s.point[1] - x.position[1],
                     s.point[2] - x.position[2]};
        auto dot = [](const Vec3& a, const Vec3& b) {
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        };
        const double uu = dot(x.du, x.du), uv = dot(x.du, x.dv), vv = dot(x.dv, x.dv);
        const double ru = dot(x.du, r), rv = dot(x.dv, r);
        double du = 0, dv = 0;
        if (onBorder) {
            dv = vv > 0 ? rv / vv : 0;
        } else {
            const double damp = 1e-9 * (uu + vv);
            const double det = (uu + damp) * (vv + damp) - uv * uv;
            if (!(det > 0)) return;
            du = ((vv + damp) * ru - uv * rv) / det;
            dv = ((uu + damp) * rv - uv * ru) / det;
        }
        s.u = std::clamp(s.u + du, std::max(0.0, mapped.u - kReach),
                         std::min(1.0, mapped.u + kReach));
        s.v = std::clamp(s.v + dv, mapped.v - 2 * kReach, mapped.v + 2 * kReach);
    }
}

// Fit, then move each sample's (u, v) to the nearest point of the fitted
// patch and fit again (parameter correction): the fit then answers for how
// far the surface is from the points, not for how the disk map spread them
// along it. Border samples keep u = 1 and slide along v.
bool fitCorrected(std::vector<Sample>& samples, const std::vector<Sample>& mapped,
                  const FitOptions& fo, int corrections, Patch& out) {
    for (int round = 0; round <= corrections; ++round) {
        const auto patch = fitToPoints(samples, fo);
        if (!patch) return false;
        out = *patch;
        if (round == corrections) break;
        for (std::size_t i = 0; i < samples.size(); ++i)
            correctParameters(out, samples[i], mapped[i], mapped[i].u >= 1 - 1e-9);
    }
    return true;
}

// Whether every point of an 8 x 16 grid over the patch lies near some
// sample: within four times the typical spacing of the samples (from the
// region's size and their count) and a twentieth of the region's size.
bool staysNearItsSamples(const Patch& patch, const std::vector<Sample>& samples) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const Sample& s : samples)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], s.point[std::size_t(c)]);
            hi[c] = std::max(hi[c], s.point[std::size_t(c)]);
        }
    const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    const double allowed = 4 * size / std::sqrt(double(samples.size())) + 0.05 * size;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j < 16; ++j) {
            const Vec3 x = position(patch, i / 8.0, 2 * std::numbers::pi * j / 16);
            bool near = false;
            for (const Sample& s : samples)
                if (std::hypot(x[0] - s.point[0], x[1] - s.point[1], x[2] - s.point[2]) <=
                    allowed) {
                    near = true;
                    break;
                }
            if (!near) return false;
        }
    return true;
}

// The mapped faces tile the polygon inscribed in the unit circle through
// the border's points, not the disk: the slivers between each chord and its
// arc would hold no samples, and the patch would wander there. Stretching
// every point along its ray from the pole by the polygon's radius in that
// direction maps the polygon onto the whole disk (it is convex and holds the
// pole), each border edge onto its arc.
class RadialStretch {
  public:
    // False when the pole is not well inside the polygon (a border edge spans
    // nearly half the circle).
    bool build(const DiskMap& map) {
        for (std::uint32_t b : map.border) {
            double a = std::arg(map.at.at(b));
            angles_.push_back(a < 0 ? a + 2 * std::numbers::pi : a);
        }
        // The loop runs counter-clockwise: angles increase but for one wrap.
        const auto first = std::min_element(angles_.begin(), angles_.end());
        std::rotate(angles_.begin(), first, angles_.end());
        for (std::size_t i = 0; i < angles_.size(); ++i) {
            const double next =
                i + 1 < angles_.size() ? angles_[i + 1] : angles_[0] + 2 * std::numbers::pi;
            if (!(next > angles_[i]) || next - angles_[i] > 0.9 * std::numbers::pi) return false;
        }
        return angles_.size() >= 3;
    }
    // The polygon's radius in the direction v.
    double radiusAt(double v) const {
        auto it = std::upper_bound(angles_.begin(), angles_.end(), v);
        const double hi = it == angles_.end() ? angles_.front() + 2 * std::numbers::pi : *it;
        const double lo = it == angles_.begin() ? angles_.back() - 2 * std::numbers::pi : *(it - 1);
        return std::cos((hi - lo) / 2) / std::cos(v - (hi + lo) / 2);
    }
    std::pair<double, double> operator()(std::complex<double> z) const {
        const auto [u, v] = polar(z);
        auto it = std::upper_bound(angles_.begin(), angles_.end(), v);
        const double hi = it == angles_.end() ? angles_.front() + 2 * std::numbers::pi : *it;
        const double lo = it == angles_.begin() ? angles_.back() - 2 * std::numbers::pi : *(it - 1);
        const double half = (hi - lo) / 2, middle = (hi + lo) / 2;
        const double rho = std::cos(half) / std::cos(v - middle); // the chord's distance along v
        return {std::min(1.0, std::abs(z) / rho), v};
    }

  private:
    std::vector<double> angles_;
};

// The fit's misses at the samples: Σ w d² and Σ w, d the distance from the
// sample to the patch's tangent plane at its (u, v) — how far the surface
// is from the point, not how far along the surface the parameters slid
// (on a coarse mesh a face's samples sit far apart in (u, v) from where
// the patch passes them; |X - p| counted that as a miss, and the fit split
// a 2 000-face sphere into 1 500 patches whose surface was 30 times nearer
// than it said). Where the tangent plane is undefined (a cap's pole), |X - p|.
void measureMisses(FittedRegion& r, const std::vector<Sample>& samples) {
    r.missed = r.weight = 0;
    for (const Sample& s : samples) {
        const Point x = evaluate(r.patch, s.u, s.v);
        const Vec3 d = field::minus(x.position, s.point);
        const Vec3 n = field::cross(x.du, x.dv);
        const double length = std::hypot(n[0], n[1], n[2]);
        const bool hasPlane = length > 1e-12 * (1 + std::hypot(x.du[0], x.du[1], x.du[2]) *
                                                        std::hypot(x.dv[0], x.dv[1], x.dv[2]));
        const double along = hasPlane ? field::dot(d, n) / length : 0;
        const double d2 = hasPlane ? along * along : field::dot(d, d);
        r.missed += s.weight * d2;
        r.weight += s.weight;
    }
}

// The paper's method, for comparison: four curves read off the region at
// u = 0 (the pole), 1/3, 2/3 and 1, each at 4N + 4 values of v, and the
// patch through them (fromBoundaryCurves).
bool fitByCurves(const mesh::Mesh& m, FittedRegion& r, const DiskMap& map,
                 const RadialStretch& stretch, const MeshFitOptions& o) {
    const std::size_t radii = std::clamp<std::size_t>(r.faces.size() / 4, 1, o.radii);
    const std::size_t count = 4 * radii + 4;
    BoundaryCurves curves;
    const std::array<double, 4> at{0, curves.u1, curves.u2, 1};
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t j = 0; j < count; ++j) {
            const double v = 2 * std::numbers::pi * double(j) / double(count);
            const std::complex<double> z = std::polar(at[k] * stretch.radiusAt(v), v);
            // The mapped face holding z (the nearest by barycentric slack).
            Vec3 best{};
            double slack = 1e300;
            for (std::uint32_t f : r.faces) {
                const auto& t = m.triangles[f];
                const std::complex<double> a = map.at.at(t[0]), b = map.at.at(t[1]),
                                           c = map.at.at(t[2]);
                const double d = (b - a).real() * (c - a).imag() - (b - a).imag() * (c - a).real();
                if (d == 0) continue;
                const double wb =
                    ((z - a).real() * (c - a).imag() - (z - a).imag() * (c - a).real()) / d;
                const double wc =
                    ((b - a).real() * (z - a).imag() - (b - a).imag() * (z - a).real()) / d;
                const double wa = 1 - wb - wc;
                const double out = std::max({0.0, -wa, -wb, -wc});
                if (out < slack) {
                    slack = out;
                    for (std::size_t x = 0; x < 3; ++x)
                        best[x] = wa * m.positions[t[0]][x] + wb * m.positions[t[1]][x] +
                                  wc * m.positions[t[2]][x];
                }
            }
            curves.curves[k].push_back(best);
        }
    const auto patch = fromBoundaryCurves(curves, radii, o.a);
    if (!patch) return false;
    r.patch = *patch;
    return true;
}

// Fits one disk region; false when it is not a disk (or the map failed).
bool fitRegion(const FaceGraph& g, FittedRegion& r, const MeshFitOptions& o) {
    const auto border = diskBoundary(g, r.faces);
    if (!border) return false;
    const auto map = mapToDisk(g, r.faces, *border);
    if (!map) return false;
    RadialStretch stretch;
    if (!stretch.build(*map) && r.faces.size() > 1) return false;
    const mesh::Mesh& m = *g.mesh;
    // Samples on a barycentric grid of each face (step 1/3: corners, edge
    // thirds and centre; 1/6 in a region of a few faces, so that even one
    // face fixes a patch's coefficients), each with its share of the face's
    // area; a sample on the border (u = 1) counts `borderWeight` times.
    const int steps = r.faces.size() < 8 ? 6 : 3;
    const double perFace = (steps + 1) * (steps + 2) / 2.0;
    std::vector<Sample> samples;
    samples.reserve(std::size_t(perFace) * r.faces.size());
    for (std::uint32_t f : r.faces) {
        const auto& t = m.triangles[f];
        const std::complex<double> z[3] = {map->at.at(t[0]), map->at.at(t[1]), map->at.at(t[2])};
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; i + j <= steps; ++j) {
                const double w[3] = {double(i) / steps, double(j) / steps,
                                     double(steps - i - j) / steps};
                Vec3 p{};
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 3; ++k)
                        p[std::size_t(c)] += w[k] * m.positions[t[std::size_t(k)]][std::size_t(c)];
                const auto [u, v] = stretch(w[0] * z[0] + w[1] * z[1] + w[2] * z[2]);
                samples.push_back(
                    {u, v, p, g.area[f] / perFace * (u >= 1 - 1e-9 ? o.borderWeight : 1.0)});
            }
    }
    if (o.method == FitMethod::BoundaryCurves) {
        if (!fitByCurves(m, r, *map, stretch, o)) return false;
        measureMisses(r, samples);
        r.disk = true;
        return true;
    }
    // Radii the region can fix: small regions take fewer. A fit that wanders
    // between its samples (a grid point of the patch far from every sample)
    // is made again with half the radii.
    FitOptions fo;
    fo.radii = std::clamp<std::size_t>(r.faces.size() / 4, 1, o.radii);
    fo.a = o.a;
    fo.pointAtStart = true;
    fo.smoothPole = true;
    fo.ridge = 1e-6;
    const std::vector<Sample> mapped = samples;
    while (true) {
        samples = mapped;
        if (!fitCorrected(samples, mapped, fo, o.corrections, r.patch)) return false;
        if (fo.radii == 1 || staysNearItsSamples(r.patch, samples)) break;
        fo.radii /= 2;
    }
    measureMisses(r, samples);
    r.disk = true;
    return true;
}

} // namespace

std::optional<MeshFit> fitMesh(const mesh::Mesh& mesh, const MeshFitOptions& o, std::string* why,
                               const std::vector<std::uint32_t>* lines) {
    if (mesh.triangles.empty()) {
        if (why) *why = "the mesh has no faces";
        return std::nullopt;
    }
    const auto graph = buildFaceGraph(mesh, why, lines);
    if (!graph) return std::nullopt;
    MeshFit out;
    const double inf = std::numeric_limits<double>::infinity();
    out.model.lo = {inf, inf, inf};
    out.model.hi = {-inf, -inf, -inf};
    for (const auto& p : mesh.positions)
        for (std::size_t k = 0; k < 3; ++k) {
            out.model.lo[k] = std::min(out.model.lo[k], double(p[k]));
            out.model.hi[k] = std::max(out.model.hi[k], double(p[k]));
        }
    const double diagonal = out.model.diagonal() > 0 ? out.model.diagonal() : 1.0;
    std::vector<FittedRegion> regions;
    std::vector<FittedRegion> pending;
    MeshFitOptions current = o; // the radii being tried
    // Regions that are not disks are split until they are; a single face always is.
    auto stopped = [&] { return o.cancel && o.cancel->load(std::memory_order_relaxed); };
    auto settle = [&]() {
        while (!pending.empty() && !stopped()) {
            FittedRegion r = std::move(pending.back());
            pending.pop_back();
            if (fitRegion(*graph, r, current) || r.faces.size() < 2) {
                regions.push_back(std::move(r));
                continue;
            }
            for (Faces& half : splitRegion(*graph, r.faces))
                if (!half.empty()) pending.push_back({std::move(half), {}, 0, 0, false});
        }
    };
    auto rms = [&]() {
        double missed = 0, weight = 0;
        for (const FittedRegion& r : regions)
            missed += r.missed, weight += r.weight;
        return weight > 0 ? std::sqrt(missed / weight) / diagonal : 0.0;
    };
    if (connectedRegions(*graph).empty()) {
        if (why) *why = "every face has a repeated vertex (no area)";
        return std::nullopt;
    }
    auto fitWith = [&](std::size_t count) {
        regions.clear();
        for (Faces& f : partition(*graph, count))
            pending.push_back({std::move(f), {}, 0, 0, false});
        settle();
        if (o.progress && !stopped()) o.progress(regions.size(), rms());
    };
    auto cancelled = [&] {
        if (why) *why = "cancelled";
        return std::nullopt;
    };
    if (o.patches) {
        fitWith(o.patches);
        if (stopped()) return cancelled();
    } else {
        // The miss shrinks about as a patch's size, so as 1/sqrt(count): the
        // next count is guessed from that, at least 1.25 times the last.
        // More, smaller patches do not always miss less (a small region's
        // border has as many corners as a large one's): the best count seen
        // is kept, and the search stops after two counts that did not beat
        // it. Then the next number of radii is tried (6, 8, 10, 12, up to
        // --radii): fewer radii first, as they take fewer bytes.
        std::vector<FittedRegion> best;
        double bestRms = std::numeric_limits<double>::infinity();
        std::vector<std::size_t> levels;
        for (std::size_t r : {6u, 8u, 10u, 12u})
            if (r < o.radii) levels.push_back(r);
        levels.push_back(o.radii);
        for (std::size_t radii : levels) {
            current.radii = radii;
            std::size_t count = 8;
            fitWith(count);
            if (stopped()) return cancelled();
            std::vector<FittedRegion> levelBest = regions;
            double levelRms = rms();
            int worse = 0;
            while (levelRms > o.error && count < o.maxPatches && worse < 2) {
                const double ratio = rms() / o.error;
                count =
                    std::min(o.maxPatches,
                             std::max(count + count / 4 + 1,
                                      std::size_t(double(count) * std::min(ratio * ratio, 4.0))));
                fitWith(count);
                if (stopped()) return cancelled();
                if (rms() < levelRms) {
                    levelBest = regions;
                    levelRms = rms();
                    worse = 0;
                } else {
                    ++worse;
                }
            }
            if (levelRms < bestRms) {
                best = std::move(levelBest);
                bestRms = levelRms;
            }
            if (bestRms <= o.error) break;
        }
        regions = std::move(best);
    }
    out.rms = rms();
    out.reached = o.patches ? true : out.rms <= o.error;
    // Each patch's border loop (in the order v increases: the faces' own
    // winding, as the disk map laid it), simplified to the error asked
    // for, its points shared with the neighbours along the same seams.
    std::vector<std::vector<std::uint32_t>> loops;
    for (FittedRegion& r : regions) {
        if (!r.disk) continue; // a lone face that could not be mapped: left out
        const auto border = diskBoundary(*graph, r.faces);
        loops.push_back(border ? *border : std::vector<std::uint32_t>{});
        out.model.patches.push_back(std::move(r.patch));
        out.regions.push_back(std::move(r.faces));
    }
    BorderCurves curves = borderCurves(mesh, loops, 2 * o.error * diagonal);
    out.model.borderPoints = std::move(curves.points);
    out.model.borders = std::move(curves.loops);
    return out;
}

} // namespace fl::pde
