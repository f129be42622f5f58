#include "mesh_fit.h"

#include "annulus_map.h"
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
    // A tube (both ends open): its loops at u = 0 and u = 1, each as its
    // faces wind (the start loop so runs the way v decreases).
    bool tube = false;
    std::vector<std::uint32_t> startLoop, endLoop;
};
FittedRegion regionOf(Faces faces) {
    FittedRegion r;
    r.faces = std::move(faces);
    return r;
}

constexpr double kReach = 0.05; // how far correction may move a sample in u (2x in v)

// The least squares' Tikhonov weight for the large regions of a band
// layout: 1e-6, as for the disks, pulls a sphere's bands off it by 1e-4
// of the diagonal; their thousands of samples need no more than this.
constexpr double kBandRidge = 1e-10;

// The barycentric grid step of a face's samples: thirds (corners, edge
// thirds and centre), sixths in a region of a few faces (so that even one
// face fixes a patch's coefficients); for the large regions of a band
// layout (`fewer`), halves or only the corners once a region has so many
// faces that thirds would pass kEnoughSamples.
constexpr std::size_t kEnoughSamples = 6000;
int sampleSteps(std::size_t faces, bool fewer) {
    if (faces < 8) return 6;
    if (!fewer || faces * 10 <= kEnoughSamples) return 3;
    return faces * 6 <= kEnoughSamples ? 2 : 1;
}

// Calls f(face, w) at the points of a barycentric grid of step 1/steps on
// each face, corners included, w the point's weights of the face's corners.
template <typename F>
void forEachFacePoint(const Faces& faces, int steps, F&& f) {
    for (std::uint32_t face : faces)
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; i + j <= steps; ++j)
                f(face, std::array<double, 3>{double(i) / steps, double(j) / steps,
                                              double(steps - i - j) / steps});
}

// The point of a face at the barycentric weights w.
Vec3 pointOf(const mesh::Mesh& m, std::uint32_t face, const std::array<double, 3>& w) {
    const auto& t = m.triangles[face];
    Vec3 p{};
    for (std::size_t c = 0; c < 3; ++c)
        for (std::size_t k = 0; k < 3; ++k)
            p[c] += w[k] * m.positions[t[k]][c];
    return p;
}

// A band layout's region of more faces than even their corners make
// kEnoughSamples — half a bunny is 100 000 samples — keeps about that many
// of its samples inside, chosen by a hash of their order (no pattern of the
// mesh's), each standing for the ones left out; every border sample stays.
// The least squares' cost grows with the samples, and its coefficients are
// fixed many times over by these.
void thin(std::vector<Sample>& samples) {
    if (samples.size() <= kEnoughSamples) return;
    const std::size_t keepOneIn = (samples.size() + kEnoughSamples - 1) / kEnoughSamples;
    std::vector<Sample> kept;
    kept.reserve(samples.size() / keepOneIn + 1);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        Sample s = samples[i];
        if (s.u <= 1e-9 || s.u >= 1 - 1e-9) {
            kept.push_back(s);
        } else if (std::uint32_t(i * 2654435761u) % keepOneIn == 0) {
            s.weight *= double(keepOneIn);
            kept.push_back(s);
        }
    }
    samples = std::move(kept);
}

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
// A tube's samples on its start loop (u = 0) slide along v too.
bool fitCorrected(std::vector<Sample>& samples, const std::vector<Sample>& mapped,
                  const FitOptions& fo, int corrections, Patch& out) {
    for (int round = 0; round <= corrections; ++round) {
        const auto patch = fitToPoints(samples, fo);
        if (!patch) return false;
        out = *patch;
        if (round == corrections) break;
        for (std::size_t i = 0; i < samples.size(); ++i)
            correctParameters(out, samples[i], mapped[i],
                              mapped[i].u >= 1 - 1e-9 || (!fo.pointAtStart && mapped[i].u <= 1e-9));
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

// Fits r.patch to the samples with parameter correction, and measures its
// misses. Radii the region can fix: small regions take fewer. A fit that
// wanders between its samples (a grid point of the patch far from every
// sample) is made again with half the radii.
bool fitSamples(const std::vector<Sample>& mapped, FitOptions fo, const MeshFitOptions& o,
                FittedRegion& r) {
    fo.a = o.a;
    std::vector<Sample> samples;
    for (fo.radii = std::clamp<std::size_t>(r.faces.size() / 4, 1, o.radii);;) {
        samples = mapped;
        if (!fitCorrected(samples, mapped, fo, o.corrections, r.patch)) return false;
        if (fo.radii == 1 || staysNearItsSamples(r.patch, samples)) break;
        fo.radii /= 2;
    }
    measureMisses(r, samples);
    return true;
}

// fitSamples with the PDE's a that misses least of o.a / 4, o.a / 2 and
// o.a, as a band layout's regions take it. a sets how fast the radii may
// bend along u: a sphere's bands and caps mostly miss about a third as much
// at a / 4 as at a, but not every one.
bool fitWithBestA(const std::vector<Sample>& mapped, const FitOptions& fo, const MeshFitOptions& o,
                  FittedRegion& r) {
    bool any = false;
    for (const double a : {o.a / 4, o.a / 2, o.a}) {
        MeshFitOptions with = o;
        with.a = a;
        FittedRegion tried = regionOf(r.faces);
        if (!fitSamples(mapped, fo, with, tried) || (any && !(tried.missed < r.missed))) continue;
        r.patch = std::move(tried.patch);
        r.missed = tried.missed;
        r.weight = tried.weight;
        any = true;
    }
    return any;
}

// Fits one disk region; false when it is not a disk (or the map failed).
// `byLength`: the disk map's radius made proportional to length from the
// pole (LengthParameter), as the caps of a band layout take it (on a
// sphere's cap the conformal radius is tan(θ/2), whose z = cos θ a cubic
// spine misses near the pole by 1e-3).
bool fitRegion(const FaceGraph& g, FittedRegion& r, const MeshFitOptions& o,
               bool byLength = false) {
    const auto border = diskBoundary(g, r.faces);
    if (!border) return false;
    const auto map = mapToDisk(g, r.faces, *border);
    if (!map) return false;
    RadialStretch stretch;
    if (!stretch.build(*map) && r.faces.size() > 1) return false;
    const mesh::Mesh& m = *g.mesh;
    // Samples on a barycentric grid of each face (sampleSteps), each with its
    // share of the face's area; a sample on the border (u = 1) counts
    // `borderWeight` times.
    std::optional<LengthParameter> length;
    if (byLength) {
        FaceParameters corners;
        for (std::uint32_t f : r.faces) {
            auto& c = corners[f];
            for (std::size_t k = 0; k < 3; ++k) {
                const auto [u, v] = stretch(map->at.at(m.triangles[f][k]));
                c[k] = {u, v};
            }
            // v unwrapped within the face; at the pole (u = 0) it is the others'.
            for (std::size_t k = 1; k < 3; ++k)
                c[k][1] +=
                    2 * std::numbers::pi * std::round((c[0][1] - c[k][1]) / (2 * std::numbers::pi));
            for (std::size_t k = 0; k < 3; ++k)
                if (c[k][0] < 1e-12) c[k][1] = (c[(k + 1) % 3][1] + c[(k + 2) % 3][1]) / 2;
        }
        length.emplace(m, corners);
    }
    const int steps = sampleSteps(r.faces.size(), byLength);
    const double perFace = (steps + 1) * (steps + 2) / 2.0;
    std::vector<Sample> samples;
    samples.reserve(std::size_t(perFace) * r.faces.size());
    std::uint32_t cornersOf = std::uint32_t(-1); // the face z holds the disk points of
    std::array<std::complex<double>, 3> z{};
    forEachFacePoint(r.faces, steps, [&](std::uint32_t f, const std::array<double, 3>& w) {
        if (f != cornersOf) {
            for (std::size_t k = 0; k < 3; ++k)
                z[k] = map->at.at(m.triangles[f][k]);
            cornersOf = f;
        }
        auto [u, v] = stretch(w[0] * z[0] + w[1] * z[1] + w[2] * z[2]);
        if (length) u = (*length)(u);
        samples.push_back(
            {u, v, pointOf(m, f, w), g.area[f] / perFace * (u >= 1 - 1e-9 ? o.borderWeight : 1.0)});
    });
    if (byLength) thin(samples);
    if (o.method == FitMethod::BoundaryCurves) {
        if (!fitByCurves(m, r, *map, stretch, o)) return false;
        measureMisses(r, samples);
        r.disk = true;
        return true;
    }
    FitOptions fo;
    fo.pointAtStart = true;
    fo.smoothPole = true;
    fo.ridge = byLength ? kBandRidge : 1e-6;
    if (!(byLength ? fitWithBestA(samples, fo, o, r) : fitSamples(samples, fo, o, r))) return false;
    r.disk = true;
    return true;
}

// Fits one tube region (an annulus: open at both ends, its two `loops` as
// annulusBoundaries gave them) as a patch whose C0 and C3 are its loops;
// false when the map failed.
bool fitTube(const FaceGraph& g, FittedRegion& r,
             const std::array<std::vector<std::uint32_t>, 2>& loops, const MeshFitOptions& o) {
    const auto map = mapToAnnulus(g, r.faces, loops[0], loops[1]);
    if (!map) return false;
    const mesh::Mesh& m = *g.mesh;
    const int steps = sampleSteps(r.faces.size(), true);
    const double perFace = (steps + 1) * (steps + 2) / 2.0;
    std::vector<Sample> mapped;
    mapped.reserve(std::size_t(perFace) * r.faces.size());
    forEachFacePoint(r.faces, steps, [&](std::uint32_t f, const std::array<double, 3>& w) {
        const auto& uv = map->faces.at(f);
        Sample s;
        s.point = pointOf(m, f, w);
        for (std::size_t k = 0; k < 3; ++k) {
            s.u += w[k] * uv[k][0];
            s.v += w[k] * uv[k][1];
        }
        s.u = std::clamp(s.u, 0.0, 1.0);
        const bool border = s.u <= 1e-9 || s.u >= 1 - 1e-9;
        s.weight = g.area[f] / perFace * (border ? o.borderWeight : 1.0);
        mapped.push_back(s);
    });
    thin(mapped);
    FitOptions fo;
    fo.ridge = kBandRidge;
    if (!fitWithBestA(mapped, fo, o, r)) return false;
    r.disk = r.tube = true;
    r.startLoop = loops[0];
    r.endLoop = loops[1];
    return true;
}

// A mesh of one part — closed like a sphere, or open at both ends like a
// cylinder — as `count` bands across its long axis (mesh_regions.h): a
// closed part's end bands as caps, every other band as a tube; the paper's
// layout for such shapes. Nullopt when a band is not a disk or an annulus
// as it must be, or a fit fails.
std::optional<std::vector<FittedRegion>> fitBands(const FaceGraph& g, const Bands& bands,
                                                  std::size_t count, const MeshFitOptions& o) {
    std::vector<Faces> cut = bands.cut(count);
    if (cut.size() != count) return std::nullopt;
    // Every band's shape before any is fitted: a tube's loops, or a disk at an end.
    std::vector<std::optional<std::array<std::vector<std::uint32_t>, 2>>> tube(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (cut[i].empty()) return std::nullopt;
        tube[i] = annulusBoundaries(g, cut[i]);
        if (!tube[i] && (!(i == 0 || i + 1 == count) || !diskBoundary(g, cut[i])))
            return std::nullopt;
    }
    std::vector<FittedRegion> out;
    for (std::size_t i = 0; i < count; ++i) {
        // A large band takes a second: a cancelled fit stops between bands.
        if (o.cancel && o.cancel->load(std::memory_order_relaxed)) return std::nullopt;
        FittedRegion r = regionOf(std::move(cut[i]));
        const bool fitted = tube[i] ? fitTube(g, r, *tube[i], o) : fitRegion(g, r, o, true);
        if (!fitted) return std::nullopt;
        out.push_back(std::move(r));
    }
    return out;
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
                if (!half.empty()) pending.push_back(regionOf(std::move(half)));
        }
    };
    auto rms = [&]() {
        double missed = 0, weight = 0;
        for (const FittedRegion& r : regions)
            missed += r.missed, weight += r.weight;
        return weight > 0 ? std::sqrt(missed / weight) / diagonal : 0.0;
    };
    const std::vector<Faces> parts = connectedRegions(*graph);
    if (parts.empty()) {
        if (why) *why = "every face has a repeated vertex (no area)";
        return std::nullopt;
    }
    auto fitWith = [&](std::size_t count) {
        regions.clear();
        for (Faces& f : partition(*graph, count))
            pending.push_back(regionOf(std::move(f)));
        settle();
        if (o.progress && !stopped()) o.progress(regions.size(), rms());
    };
    auto cancelled = [&] {
        if (why) *why = "cancelled";
        return std::nullopt;
    };
    // A mesh of one part may be a sphere- or tube-like shape that a few
    // bands fit far better than disks (the paper's layout: caps at the ends,
    // tubes between); tried first, with as many bands as patches asked for,
    // or with a few counts up to kMostBands until the error is reached.
    std::optional<std::vector<FittedRegion>> banded;
    double bandedRms = std::numeric_limits<double>::infinity();
    if (parts.size() == 1 && o.method == FitMethod::Points) {
        constexpr std::size_t kMostBands = 8;
        // Without a count: 1 (a tube), 2 (two caps), 3, 4, 6, 8 — a band's miss
        // falls fast with its length, so few tries find the count; and none
        // past the point where the misses so far, falling as a power of the
        // count, would still miss the error at kMostBands (the bunny: 1.3 %
        // at 2, 0.96 % at 3, so about 0.45 % at 8; a sphere's fall as the
        // count to the 1.5th power or faster).
        std::vector<std::size_t> counts{1, 2, 3, 4, 6, 8};
        if (o.patches) counts = {o.patches};
        std::size_t lastCount = 0;
        double lastRms = 0;
        const Bands bands(*graph, parts[0]);
        for (std::size_t count : counts) {
            if (count > kMostBands || stopped()) break;
            auto tried = fitBands(*graph, bands, count, o);
            if (!tried) continue;
            regions = std::move(*tried);
            const double now = rms();
            if (now < bandedRms) {
                bandedRms = now;
                banded = regions;
            }
            if (o.progress) o.progress(regions.size(), now);
            if (!o.patches && bandedRms <= o.error) break;
            if (lastCount > 0 && now < lastRms) {
                const double power =
                    std::log(lastRms / now) / std::log(double(count) / double(lastCount));
                if (now * std::pow(double(count) / double(kMostBands), power) > o.error) break;
            } else if (lastCount > 0) {
                break; // more bands missed more
            }
            lastCount = count;
            lastRms = now;
        }
        if (stopped()) return cancelled();
    }
    if (banded && !o.patches && bandedRms <= o.error) {
        regions = std::move(*banded); // no layout of disks would take fewer patches
    } else if (o.patches) {
        fitWith(o.patches);
        if (stopped()) return cancelled();
        if (banded && bandedRms < rms()) regions = std::move(*banded);
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
        if (banded && bandedRms < bestRms) regions = std::move(*banded);
    }
    out.rms = rms();
    out.reached = o.patches ? true : out.rms <= o.error;
    // Each patch's border loop (in the order v increases: the faces' own
    // winding, as the disk map laid it), simplified to the error asked
    // for, its points shared with the neighbours along the same seams.
    // A tube's start loop goes in after every patch's border, as its faces
    // wind like every other loop (so that the seams are found), and is
    // turned round after.
    std::vector<std::vector<std::uint32_t>> loops, starts; // per patch
    for (FittedRegion& r : regions) {
        if (!r.disk) continue; // a lone face that could not be mapped: left out
        if (r.tube) {
            loops.push_back(std::move(r.endLoop));
        } else {
            const auto border = diskBoundary(*graph, r.faces);
            loops.push_back(border ? *border : std::vector<std::uint32_t>{});
        }
        starts.push_back(std::move(r.startLoop)); // empty but for a tube
        out.model.patches.push_back(std::move(r.patch));
        out.regions.push_back(std::move(r.faces));
    }
    const std::size_t patchCount = loops.size();
    std::vector<std::size_t> startAt(patchCount, 0); // in `loops`; 0: none
    for (std::size_t i = 0; i < patchCount; ++i)
        if (!starts[i].empty()) {
            startAt[i] = loops.size();
            loops.push_back(std::move(starts[i]));
        }
    BorderCurves curves = borderCurves(mesh, loops, 2 * o.error * diagonal);
    out.model.borderPoints = std::move(curves.points);
    out.model.borders.assign(curves.loops.begin(),
                             curves.loops.begin() + std::ptrdiff_t(patchCount));
    if (loops.size() > patchCount) {
        out.model.startBorders.resize(patchCount);
        for (std::size_t i = 0; i < patchCount; ++i)
            if (startAt[i] != 0)
                out.model.startBorders[i].assign(curves.loops[startAt[i]].rbegin(),
                                                 curves.loops[startAt[i]].rend());
    }
    return out;
}

} // namespace fl::pde
