#include "mesh_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

std::optional<std::vector<std::uint32_t>> diskBoundary(const FaceGraph& g, const Faces& region) {
    const std::unordered_set<std::uint32_t> in(region.begin(), region.end());
    std::unordered_map<std::uint32_t, std::uint32_t> next; // boundary edge a -> b
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
                if (!next.emplace(a, b).second) return std::nullopt; // a pinched vertex
        }
    }
    if (next.empty()) return std::nullopt; // closed: no border
    if (std::int64_t(vertices.size()) - std::int64_t(edges.size()) + std::int64_t(region.size()) !=
        1)
        return std::nullopt;
    std::vector<std::uint32_t> loop;
    std::uint32_t at = next.begin()->first;
    // Start at the smallest vertex, so the same region gives the same loop.
    for (const auto& [a, b] : next)
        at = std::min(at, a);
    const std::uint32_t start = at;
    do {
        loop.push_back(at);
        const auto it = next.find(at);
        if (it == next.end() || loop.size() > next.size()) return std::nullopt;
        at = it->second;
    } while (at != start);
    if (loop.size() != next.size()) return std::nullopt; // more than one loop
    return loop;
}

} // namespace fl::pde
