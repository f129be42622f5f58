#include "annulus_map.h"

#include "cotangent_weights.h"
#include "field/vec3.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <queue>
#include <unordered_set>

namespace fl::pde {
namespace {

using P = std::array<double, 3>;
constexpr double kTwoPi = 2 * std::numbers::pi;

P pos(const mesh::Mesh& m, std::uint32_t v) {
    return {m.positions[v][0], m.positions[v][1], m.positions[v][2]};
}

using Edge = std::pair<std::uint32_t, std::uint32_t>; // directed
Edge edgeOf(const mesh::Triangle& t, int k) {
    return {t[std::size_t(k)], t[std::size_t((k + 1) % 3)]};
}

// Solves L x = rhs for the vertices not in `fixed` (whose values are given),
// L the weighted graph Laplacian; false when the solve fails.
bool solve(const std::map<Edge, double>& weight, const std::vector<std::uint32_t>& vertices,
           const std::unordered_map<std::uint32_t, double>& fixed,
           const std::unordered_map<std::uint32_t, double>& rhs,
           std::unordered_map<std::uint32_t, double>& out) {
    std::unordered_map<std::uint32_t, Eigen::Index> index;
    std::vector<std::uint32_t> free;
    for (std::uint32_t v : vertices)
        if (!fixed.count(v)) {
            index[v] = Eigen::Index(free.size());
            free.push_back(v);
        }
    out = fixed;
    if (free.empty()) return true;
    const auto n = Eigen::Index(free.size());
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (const auto& [v, r] : rhs)
        if (const auto it = index.find(v); it != index.end()) b(it->second) += r;
    std::vector<Eigen::Triplet<double>> entries;
    for (const auto& [e, w] : weight) {
        const auto ia = index.find(e.first), ib = index.find(e.second);
        if (ia == index.end()) continue; // each undirected edge is stored both ways
        entries.emplace_back(ia->second, ia->second, w);
        if (ib != index.end())
            entries.emplace_back(ia->second, ib->second, -w);
        else
            b(ia->second) += w * fixed.at(e.second);
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
    if (solver.info() != Eigen::Success) return false;
    const Eigen::VectorXd x = solver.solve(b);
    if (solver.info() != Eigen::Success || !x.allFinite()) return false;
    for (std::size_t i = 0; i < free.size(); ++i)
        out[free[i]] = x(Eigen::Index(i));
    return true;
}

} // namespace

// Per face, ∫∫ |Xu| du dv = area |∇v| (conformal: |Xu| = 1/|∇u|, |Xv| =
// 1/|∇v|), so the mean ds/du over a slice of u is the sum of its faces'
// area |∇v|, over 2π and the slice's width.
LengthParameter::LengthParameter(const mesh::Mesh& m, const FaceParameters& faces) {
    const std::size_t slices = std::clamp<std::size_t>(faces.size() / 50, 8, 64);
    std::vector<double> length(slices, 0.0);
    for (const auto& [f, c] : faces) {
        const auto& t = m.triangles[f];
        const P a = pos(m, t[0]);
        const P e1 = field::minus(pos(m, t[1]), a), e2 = field::minus(pos(m, t[2]), a);
        // |∇v| of the linear v on the face: |Δv2 e1 - Δv1 e2| / (2 area).
        const double twiceArea = field::length(field::cross(e1, e2));
        if (!(twiceArea > 0)) continue;
        const double dv1 = c[1][1] - c[0][1], dv2 = c[2][1] - c[0][1];
        const double gradV =
            field::length(field::minus(field::scaled(e1, dv2), field::scaled(e2, dv1))) / twiceArea;
        const double u = (c[0][0] + c[1][0] + c[2][0]) / 3;
        if (!std::isfinite(gradV) || !std::isfinite(u)) continue;
        const auto slice = std::min(slices - 1, std::size_t(std::max(0.0, u) * double(slices)));
        length[slice] += 0.5 * twiceArea * gradV / kTwoPi;
    }
    at_ = {0};
    for (double l : length)
        at_.push_back(at_.back() + l);
    if (!(at_.back() > 0) || !std::isfinite(at_.back())) {
        at_.clear(); // the identity
        return;
    }
    for (double& x : at_)
        x /= at_.back();
}

double LengthParameter::operator()(double u) const {
    if (at_.empty()) return u;
    const std::size_t slices = at_.size() - 1;
    const double s = std::clamp(u, 0.0, 1.0) * double(slices);
    const auto k = std::min(slices - 1, std::size_t(s));
    return at_[k] + (s - double(k)) * (at_[k + 1] - at_[k]);
}

std::optional<AnnulusMap> mapToAnnulus(const FaceGraph& g, const Faces& region,
                                       const std::vector<std::uint32_t>& start,
                                       const std::vector<std::uint32_t>& end) {
    const mesh::Mesh& m = *g.mesh;
    const std::unordered_set<std::uint32_t> in(region.begin(), region.end());
    const std::unordered_set<std::uint32_t> onStart(start.begin(), start.end()),
        onEnd(end.begin(), end.end());
    // The cotangent weights, clamped positive (no fold-overs), stored both ways.
    std::map<Edge, double> weight;
    for (const auto& [e, w] : cotangentWeights(m, region))
        weight[e] = weight[{e.second, e.first}] = std::max(w, 1e-3);
    const std::vector<std::uint32_t> vertices = verticesOf(m, region);

    // u: 0 on the start loop, 1 on the end loop.
    std::unordered_map<std::uint32_t, double> fixedU, u;
    for (std::uint32_t v : start)
        fixedU[v] = 0;
    for (std::uint32_t v : end)
        fixedU[v] = 1;
    if (!solve(weight, vertices, fixedU, {}, u)) return std::nullopt;

    // The cut: a shortest path of faces from one with an edge on the start
    // loop to one with an edge on the end loop (breadth first).
    auto borderEdge = [&](std::uint32_t f, const std::unordered_set<std::uint32_t>& loop) {
        for (int k = 0; k < 3; ++k) {
            const std::int32_t n = g.across[f][std::size_t(k)];
            const auto [a, b] = edgeOf(m.triangles[f], k);
            if ((n < 0 || !in.count(std::uint32_t(n))) && loop.count(a) && loop.count(b)) return k;
        }
        return -1;
    };
    std::unordered_map<std::uint32_t, std::int64_t> parent;
    std::queue<std::uint32_t> queue;
    for (std::uint32_t f : region)
        if (borderEdge(f, onStart) >= 0) {
            parent[f] = -1;
            queue.push(f);
        }
    std::int64_t last = -1;
    while (!queue.empty() && last < 0) {
        const std::uint32_t f = queue.front();
        queue.pop();
        if (borderEdge(f, onEnd) >= 0) {
            last = f;
            break;
        }
        for (int k = 0; k < 3; ++k) {
            const std::int32_t n = g.across[f][std::size_t(k)];
            if (n < 0 || !in.count(std::uint32_t(n)) || parent.count(std::uint32_t(n))) continue;
            parent[std::uint32_t(n)] = f;
            queue.push(std::uint32_t(n));
        }
    }
    if (last < 0) return std::nullopt;
    // Jumps of 2π on the edges the cut crosses, each as it leaves a face
    // (in that face's winding): +2π out of a face, so -2π into the next;
    // every face's jumps then sum to zero, and going once round a loop
    // gains 2π.
    std::map<Edge, double> jump;
    auto cross = [&](Edge e) {
        jump[e] += kTwoPi;
        jump[{e.second, e.first}] -= kTwoPi;
    };
    std::vector<std::uint32_t> path;
    for (std::int64_t f = last; f >= 0; f = parent[std::uint32_t(f)])
        path.push_back(std::uint32_t(f));
    std::reverse(path.begin(), path.end());
    const Edge entry = edgeOf(m.triangles[path.front()], borderEdge(path.front(), onStart));
    cross({entry.second, entry.first}); // from outside into the first face
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (g.across[path[i]][std::size_t(k)] == std::int32_t(path[i + 1]))
                cross(edgeOf(m.triangles[path[i]], k));
    cross(edgeOf(m.triangles[path.back()], borderEdge(path.back(), onEnd)));

    // v: harmonic across every edge once its jump is added.
    std::unordered_map<std::uint32_t, double> rhs, v;
    for (const auto& [e, j] : jump)
        if (j != 0) rhs[e.first] += weight.at(e) * j;
    if (!solve(weight, vertices, {{start.front(), 0.0}}, rhs, v)) return std::nullopt;

    AnnulusMap out;
    double area = 0;
    for (std::uint32_t f : region) {
        const auto& t = m.triangles[f];
        auto& c = out.faces[f];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[0], b = t[std::size_t(k)];
            const auto it = jump.find({a, b});
            c[std::size_t(k)] = {u.at(b), v.at(a) + (v.at(b) - v.at(a)) +
                                              (it != jump.end() && k > 0 ? it->second : 0.0)};
        }
        area +=
            (c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[2][0] - c[0][0]) * (c[1][1] - c[0][1]);
    }
    // Faces counter-clockwise in (u, v), as the surface's Xu x Xv faces out.
    if (area < 0)
        for (auto& [f, c] : out.faces)
            for (auto& corner : c)
                corner[1] = -corner[1];
    const LengthParameter byLength(m, out.faces);
    for (auto& [f, c] : out.faces)
        for (auto& corner : c)
            corner[0] = byLength(corner[0]);
    // Walked with the region on the left, the end loop goes the way v
    // increases and the start loop the other way.
    out.end = end;
    out.start.assign(start.rbegin(), start.rend());
    return out;
}

} // namespace fl::pde
