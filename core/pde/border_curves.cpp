#include "border_curves.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace fl::pde {
namespace {

Vec3 at(const mesh::Mesh& m, std::uint32_t v) {
    return {m.positions[v][0], m.positions[v][1], m.positions[v][2]};
}

double distance(const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double l = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const double t =
        l > 0 ? std::clamp(((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1] + (p[2] - a[2]) * ab[2]) /
                               l,
                           0.0, 1.0)
              : 0.0;
    return distance(p, {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]});
}

void douglasPeucker(const mesh::Mesh& m, const std::vector<std::uint32_t>& chain, std::size_t first,
                    std::size_t last, double tolerance, std::set<std::uint32_t>& kept) {
    if (last <= first + 1) return;
    double far = -1;
    std::size_t at_ = first;
    for (std::size_t i = first + 1; i < last; ++i) {
        const double d =
            distanceToSegment(at(m, chain[i]), at(m, chain[first]), at(m, chain[last]));
        if (d > far) far = d, at_ = i;
    }
    if (far <= tolerance) return;
    kept.insert(chain[at_]);
    douglasPeucker(m, chain, first, at_, tolerance, kept);
    douglasPeucker(m, chain, at_, last, tolerance, kept);
}

} // namespace

BorderCurves borderCurves(const mesh::Mesh& m, const std::vector<std::vector<std::uint32_t>>& loops,
                          double tolerance) {
    // Which loop walks each directed edge: the region across edge a -> b of
    // one loop is the loop that walks b -> a (none at the mesh's own border).
    std::unordered_map<std::uint64_t, std::size_t> walker;
    auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    for (std::size_t r = 0; r < loops.size(); ++r)
        for (std::size_t i = 0; i < loops[r].size(); ++i)
            walker[key(loops[r][i], loops[r][(i + 1) % loops[r].size()])] = r;
    auto across = [&](std::size_t r, std::size_t i) -> std::int64_t {
        const auto& l = loops[r];
        const auto it = walker.find(key(l[(i + 1) % l.size()], l[i]));
        return it == walker.end() ? -1 : std::int64_t(it->second);
    };
    // Junctions: where the region across changes. A loop with fewer than
    // three gets more, chosen without regard to direction: its smallest
    // vertex, the vertex farthest from it, and the one farthest from both.
    std::set<std::uint32_t> kept;
    for (std::size_t r = 0; r < loops.size(); ++r) {
        const auto& l = loops[r];
        std::size_t junctions = 0;
        for (std::size_t i = 0; i < l.size(); ++i)
            if (across(r, (i + l.size() - 1) % l.size()) != across(r, i)) {
                kept.insert(l[i]);
                ++junctions;
            }
        if (junctions >= 3 || l.size() < 3) continue;
        std::vector<std::uint32_t> chosen{*std::min_element(l.begin(), l.end())};
        for (int extra = 0; extra < 2; ++extra) {
            std::uint32_t best = chosen[0];
            double most = -1;
            for (std::uint32_t v : l) {
                double nearest = 1e300;
                for (std::uint32_t c : chosen)
                    nearest = std::min(nearest, distance(at(m, v), at(m, c)));
                if (nearest > most || (nearest == most && v < best)) most = nearest, best = v;
            }
            chosen.push_back(best);
        }
        kept.insert(chosen.begin(), chosen.end());
    }
    // Each chain between two kept vertices, simplified in the direction
    // from its smaller end id (the neighbour walks it the other way).
    for (const auto& l : loops) {
        std::vector<std::size_t> stops;
        for (std::size_t i = 0; i < l.size(); ++i)
            if (kept.count(l[i])) stops.push_back(i);
        for (std::size_t s = 0; s < stops.size(); ++s) {
            std::vector<std::uint32_t> chain;
            const std::size_t from = stops[s], to = stops[(s + 1) % stops.size()];
            for (std::size_t i = from;; i = (i + 1) % l.size()) {
                chain.push_back(l[i]);
                if (chain.size() > 1 && i == to) break;
            }
            if (chain.front() > chain.back() ||
                (chain.front() == chain.back() && chain[1] > chain[chain.size() - 2]))
                std::reverse(chain.begin(), chain.end());
            douglasPeucker(m, chain, 0, chain.size() - 1, tolerance, kept);
        }
    }
    BorderCurves out;
    std::unordered_map<std::uint32_t, std::uint32_t> number;
    for (const auto& l : loops) {
        auto& loop = out.loops.emplace_back();
        for (std::uint32_t v : l) {
            if (!kept.count(v)) continue;
            const auto [it, fresh] = number.emplace(v, std::uint32_t(out.points.size()));
            if (fresh) out.points.push_back(at(m, v));
            loop.push_back(it->second);
        }
        if (loop.size() < 3) loop.clear(); // too few to pull onto: the patch's own C3
    }
    return out;
}

} // namespace fl::pde
