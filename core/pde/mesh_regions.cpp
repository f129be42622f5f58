#include "mesh_regions.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace fl::pde {
namespace {

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(a) << 32) | b;
}

bool degenerate(const mesh::Triangle& t) {
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Dijkstra over the faces of `inRegion` from `seeds`; returns each face's
// nearest seed (index into seeds) and distance, for faces of the region.
void grow(const FaceGraph& g, const Faces& region, const std::vector<std::uint32_t>& seeds,
          std::unordered_map<std::uint32_t, std::pair<std::uint32_t, double>>& owner) {
    std::unordered_set<std::uint32_t> in(region.begin(), region.end());
    owner.clear();
    using Item = std::tuple<double, std::uint32_t, std::uint32_t>; // distance, face, seed
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (std::uint32_t s = 0; s < seeds.size(); ++s)
        queue.emplace(0.0, seeds[s], s);
    while (!queue.empty()) {
        const auto [d, f, s] = queue.top();
        queue.pop();
        if (owner.count(f)) continue;
        owner[f] = {s, d};
        for (std::int32_t n : g.across[f])
            if (n >= 0 && in.count(std::uint32_t(n)) && !owner.count(std::uint32_t(n)))
                queue.emplace(d + distance(g.centroid[f], g.centroid[std::size_t(n)]),
                              std::uint32_t(n), s);
    }
}

std::uint32_t farthest(const FaceGraph& g, const Faces& region, std::uint32_t from) {
    std::unordered_map<std::uint32_t, std::pair<std::uint32_t, double>> owner;
    grow(g, region, {from}, owner);
    std::uint32_t best = from;
    double far = -1;
    for (const auto& [f, o] : owner)
        if (o.second > far || (o.second == far && f < best)) far = o.second, best = f;
    return best;
}

} // namespace

std::optional<FaceGraph> buildFaceGraph(const mesh::Mesh& m, std::string* why,
                                        const std::vector<std::uint32_t>* lines) {
    FaceGraph g;
    g.mesh = &m;
    const std::size_t n = m.triangles.size();
    g.across.assign(n, {-1, -1, -1});
    g.area.assign(n, 0);
    g.centroid.assign(n, {});
    auto where = [&](std::size_t face) {
        return lines && face < lines->size() ? "line " + std::to_string((*lines)[face])
                                             : "triangle " + std::to_string(face + 1);
    };
    std::unordered_map<std::uint64_t, std::uint32_t> directed; // a->b : face
    directed.reserve(3 * n);
    for (std::uint32_t f = 0; f < n; ++f) {
        const auto& t = m.triangles[f];
        if (degenerate(t)) continue;
        std::array<std::array<double, 3>, 3> p;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                p[std::size_t(k)][std::size_t(c)] = m.positions[t[std::size_t(k)]][std::size_t(c)];
        const std::array<double, 3> ab{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]},
            ac{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        g.area[f] = 0.5 * std::hypot(ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                                     ab[0] * ac[1] - ab[1] * ac[0]);
        for (int c = 0; c < 3; ++c)
            g.centroid[f][std::size_t(c)] =
                (p[0][std::size_t(c)] + p[1][std::size_t(c)] + p[2][std::size_t(c)]) / 3;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            const auto [it, fresh] = directed.emplace(key(a, b), f);
            if (!fresh) {
                if (why)
                    *why = "the faces at " + where(it->second) + " and " + where(f) +
                           " wind the same way along the edge from vertex " +
                           std::to_string(a + 1) + " to " + std::to_string(b + 1) +
                           (it->second == f ? ""
                                            : " (an edge with more than two faces, or faces "
                                              "facing opposite ways)");
                return std::nullopt;
            }
        }
    }
    std::unordered_map<std::uint64_t, int> undirected;
    for (std::uint32_t f = 0; f < n; ++f) {
        const auto& t = m.triangles[f];
        if (degenerate(t)) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            if (++undirected[key(std::min(a, b), std::max(a, b))] > 2) {
                if (why)
                    *why = "the edge between vertices " + std::to_string(a + 1) + " and " +
                           std::to_string(b + 1) + " has more than two faces (" + where(f) +
                           "): a PDE patch needs a manifold surface";
                return std::nullopt;
            }
            const auto back = directed.find(key(b, a));
            if (back != directed.end()) g.across[f][std::size_t(k)] = std::int32_t(back->second);
        }
    }
    return g;
}

std::vector<Faces> connectedRegions(const FaceGraph& g) {
    std::vector<Faces> out;
    std::vector<char> seen(g.across.size(), 0);
    for (std::uint32_t f = 0; f < g.across.size(); ++f) {
        if (seen[f] || degenerate(g.mesh->triangles[f])) continue;
        Faces region;
        std::vector<std::uint32_t> stack{f};
        seen[f] = 1;
        while (!stack.empty()) {
            const std::uint32_t x = stack.back();
            stack.pop_back();
            region.push_back(x);
            for (std::int32_t n : g.across[x])
                if (n >= 0 && !seen[std::size_t(n)]) {
                    seen[std::size_t(n)] = 1;
                    stack.push_back(std::uint32_t(n));
                }
        }
        std::sort(region.begin(), region.end());
        out.push_back(std::move(region));
    }
    return out;
}

std::vector<Faces> partition(const FaceGraph& g, std::size_t count, int relaxations) {
    const std::vector<Faces> parts = connectedRegions(g);
    double total = 0;
    for (const Faces& part : parts)
        for (std::uint32_t f : part)
            total += g.area[f];
    std::vector<Faces> out;
    for (const Faces& part : parts) {
        double area = 0;
        std::array<double, 3> centre{};
        for (std::uint32_t f : part) {
            area += g.area[f];
            for (std::size_t k = 0; k < 3; ++k)
                centre[k] += g.area[f] * g.centroid[f][k];
        }
        const std::size_t want = std::clamp<std::size_t>(
            std::size_t(std::lround(double(count) * (total > 0 ? area / total : 1.0))), 1,
            part.size());
        // Farthest-point seeds, the first nearest the part's centre.
        std::vector<std::uint32_t> seeds;
        {
            std::uint32_t first = part.front();
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < 3; ++k)
                centre[k] = area > 0 ? centre[k] / area : g.centroid[part.front()][k];
            for (std::uint32_t f : part)
                if (const double d = distance(g.centroid[f], centre); d < best) best = d, first = f;
            seeds.push_back(first);
        }
        std::unordered_map<std::uint32_t, std::pair<std::uint32_t, double>> owner;
        while (seeds.size() < want) {
            grow(g, part, seeds, owner);
            std::uint32_t far = seeds.front();
            double most = -1;
            for (std::uint32_t f : part)
                if (const auto it = owner.find(f); it != owner.end() && it->second.second > most)
                    most = it->second.second, far = f;
            if (most <= 0) break;
            seeds.push_back(far);
        }
        std::vector<Faces> regions;
        for (int step = 0; step <= relaxations; ++step) {
            grow(g, part, seeds, owner);
            regions.assign(seeds.size(), {});
            for (std::uint32_t f : part)
                regions[owner.count(f) ? owner[f].first : 0].push_back(f);
            if (step == relaxations) break;
            // Lloyd: each seed to the face nearest its region's area-weighted centre.
            for (std::size_t r = 0; r < regions.size(); ++r) {
                if (regions[r].empty()) continue;
                std::array<double, 3> c{};
                double a = 0;
                for (std::uint32_t f : regions[r]) {
                    a += g.area[f];
                    for (std::size_t k = 0; k < 3; ++k)
                        c[k] += g.area[f] * g.centroid[f][k];
                }
                for (std::size_t k = 0; k < 3; ++k)
                    c[k] = a > 0 ? c[k] / a : g.centroid[regions[r].front()][k];
                double best = std::numeric_limits<double>::infinity();
                for (std::uint32_t f : regions[r])
                    if (const double d = distance(g.centroid[f], c); d < best)
                        best = d, seeds[r] = f;
            }
        }
        for (Faces& r : regions)
            if (!r.empty()) out.push_back(std::move(r));
    }
    return out;
}

std::array<Faces, 2> splitRegion(const FaceGraph& g, const Faces& region) {
    const std::uint32_t a = farthest(g, region, region.front());
    const std::uint32_t b = farthest(g, region, a);
    std::unordered_map<std::uint32_t, std::pair<std::uint32_t, double>> owner;
    grow(g, region, {a, b}, owner);
    std::array<Faces, 2> halves;
    for (std::uint32_t f : region)
        halves[owner.count(f) ? owner[f].first : 0].push_back(f);
    if (halves[1].empty() && halves[0].size() > 1) { // a == b: cut off one face
        halves[1].push_back(halves[0].back());
        halves[0].pop_back();
    }
    return halves;
}

namespace {

// The region's boundary edges (a -> b in its faces' winding), and its Euler
// characteristic; nullopt at a pinched vertex (two boundary edges leave it).
struct Boundary {
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    std::int64_t euler = 0;
};
std::optional<Boundary> boundaryOf(const FaceGraph& g, const Faces& region) {
    const std::unordered_set<std::uint32_t> in(region.begin(), region.end());
    Boundary out;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::unordered_set<std::uint32_t> vertices;
    for (std::uint32_t f : region) {
        const auto& t = g.mesh->triangles[f];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            vertices.insert(a);
            edges.insert({std::min(a, b), std::max(a, b)});
            const std::int32_t n = g.across[f][std::size_t(k)];
            if (n < 0 || !in.count(std::uint32_t(n)))
                if (!out.next.emplace(a, b).second) return std::nullopt; // a pinched vertex
        }
    }
    out.euler =
        std::int64_t(vertices.size()) - std::int64_t(edges.size()) + std::int64_t(region.size());
    return out;
}

// The loops of boundary edges, each started at its smallest vertex (the
// same region gives the same loops), in the order of those vertices.
std::vector<std::vector<std::uint32_t>> loopsOf(const Boundary& b) {
    std::vector<std::vector<std::uint32_t>> loops;
    std::unordered_set<std::uint32_t> done;
    std::vector<std::uint32_t> starts;
    for (const auto& [a, next] : b.next)
        starts.push_back(a);
    std::sort(starts.begin(), starts.end());
    for (std::uint32_t start : starts) {
        if (done.count(start)) continue;
        std::vector<std::uint32_t> loop;
        std::uint32_t at = start;
        do {
            if (!done.insert(at).second) return {}; // not a simple loop
            loop.push_back(at);
            const auto it = b.next.find(at);
            if (it == b.next.end()) return {};
            at = it->second;
        } while (at != start);
        loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace

std::optional<std::vector<std::uint32_t>> diskBoundary(const FaceGraph& g, const Faces& region) {
    const auto b = boundaryOf(g, region);
    if (!b || b->next.empty() || b->euler != 1) return std::nullopt; // closed, or not a disk
    auto loops = loopsOf(*b);
    if (loops.size() != 1) return std::nullopt; // more than one loop
    return std::move(loops[0]);
}

std::optional<std::array<std::vector<std::uint32_t>, 2>> annulusBoundaries(const FaceGraph& g,
                                                                           const Faces& region) {
    const auto b = boundaryOf(g, region);
    if (!b || b->euler != 0) return std::nullopt;
    auto loops = loopsOf(*b);
    if (loops.size() != 2 || loops[0].size() < 3 || loops[1].size() < 3) return std::nullopt;
    return std::array<std::vector<std::uint32_t>, 2>{std::move(loops[0]), std::move(loops[1])};
}

std::vector<std::uint32_t> verticesOf(const mesh::Mesh& m, const Faces& region) {
    std::vector<std::uint32_t> vertices;
    for (std::uint32_t f : region)
        for (std::uint32_t v : m.triangles[f])
            vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

Bands::Bands(const FaceGraph& g, const Faces& part) : part_(part) {
    if (part.empty()) return;
    const mesh::Mesh& m = *g.mesh;
    const std::vector<std::uint32_t> vertices = verticesOf(m, part);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::uint32_t v : vertices)
        mean += Eigen::Vector3d(m.positions[v][0], m.positions[v][1], m.positions[v][2]);
    mean /= double(vertices.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::uint32_t v : vertices) {
        const Eigen::Vector3d d =
            Eigen::Vector3d(m.positions[v][0], m.positions[v][1], m.positions[v][2]) - mean;
        covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    const Eigen::Vector3d axis = eigen.eigenvectors().col(2); // the largest eigenvalue's
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::uint32_t v : vertices) {
        const double h =
            axis.dot(Eigen::Vector3d(m.positions[v][0], m.positions[v][1], m.positions[v][2]));
        lo = std::min(lo, h);
        hi = std::max(hi, h);
    }
    if (!(hi > lo)) return;
    const auto boundary = boundaryOf(g, part);
    closed_ = boundary && boundary->next.empty();
    // A face goes by its lowest corner, not its centre: the two triangles
    // of a quad of a ring-like mesh (a UV sphere's strip) then go together,
    // where their centres, a third of the strip apart, could straddle a cut
    // and make the border a zigzag that no patch's end follows.
    height_.reserve(part.size());
    for (std::uint32_t f : part) {
        double h = std::numeric_limits<double>::infinity();
        for (std::uint32_t v : m.triangles[f])
            h = std::min(h, axis.dot(Eigen::Vector3d(m.positions[v][0], m.positions[v][1],
                                                     m.positions[v][2])));
        height_.push_back((h - lo) / (hi - lo));
    }
}

std::vector<Faces> Bands::cut(std::size_t count) const {
    if (count < 1 || height_.empty()) return {};
    std::vector<double> cuts; // along the axis, as fractions of [lo, hi]
    for (std::size_t k = 1; k < count; ++k)
        cuts.push_back(closed_ ? (1 - std::cos(std::numbers::pi * double(k) / double(count))) / 2
                               : double(k) / double(count));
    std::vector<Faces> out(count);
    for (std::size_t i = 0; i < part_.size(); ++i)
        out[std::size_t(std::upper_bound(cuts.begin(), cuts.end(), height_[i]) - cuts.begin())]
            .push_back(part_[i]);
    return out;
}

} // namespace fl::pde
