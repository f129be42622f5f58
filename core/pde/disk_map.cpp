#include "disk_map.h"

#include "cotangent_weights.h"
#include "field/vec3.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <queue>

namespace fl::pde {
namespace {

field::Vec3 pos(const mesh::Mesh& m, std::uint32_t v) {
    return {m.positions[v][0], m.positions[v][1], m.positions[v][2]};
}

} // namespace

std::pair<double, double> polar(std::complex<double> z) {
    double v = std::arg(z);
    if (v < 0) v += 2 * std::numbers::pi;
    return {std::min(1.0, std::abs(z)), v};
}

std::optional<DiskMap> mapToDisk(const FaceGraph& g, const Faces& region,
                                 const std::vector<std::uint32_t>& border) {
    const mesh::Mesh& m = *g.mesh;
    DiskMap out;
    out.border = border;
    // The border round the circle by arc length, counter-clockwise.
    std::vector<double> arc{0};
    for (std::size_t i = 0; i < border.size(); ++i)
        arc.push_back(arc.back() +
                      field::length(field::minus(pos(m, border[(i + 1) % border.size()]),
                                                 pos(m, border[i]))));
    const double total = arc.back();
    for (std::size_t i = 0; i < border.size(); ++i) {
        const double t = total > 0 ? arc[i] / total : double(i) / double(border.size());
        out.at[border[i]] = std::polar(1.0, 2 * std::numbers::pi * t);
    }
    // Interior vertices, numbered; weights per undirected edge.
    std::unordered_map<std::uint32_t, int> index;
    std::vector<std::uint32_t> inner;
    const EdgeWeights weight = cotangentWeights(m, region);
    for (std::uint32_t f : region)
        for (std::uint32_t a : m.triangles[f])
            if (!out.at.count(a) && !index.count(a)) {
                index[a] = int(inner.size());
                inner.push_back(a);
            }
    if (!inner.empty()) {
        const auto n = Eigen::Index(inner.size());
        std::vector<Eigen::Triplet<double>> entries;
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
        std::vector<double> diagonal(inner.size(), 0);
        for (const auto& [e, w0] : weight) {
            const double w = std::max(w0, 1e-3); // positive: no fold-overs
            const auto ia = index.find(e.first), ib = index.find(e.second);
            auto couple = [&](decltype(ia) i, std::uint32_t other, decltype(ib) j) {
                if (i == index.end()) return;
                diagonal[std::size_t(i->second)] += w;
                if (j != index.end())
                    entries.emplace_back(i->second, j->second, -w);
                else {
                    const auto z = out.at[other];
                    rhs(i->second, 0) += w * z.real();
                    rhs(i->second, 1) += w * z.imag();
                }
            };
            couple(ia, e.second, ib);
            couple(ib, e.first, ia);
        }
        for (std::size_t i = 0; i < inner.size(); ++i)
            entries.emplace_back(Eigen::Index(i), Eigen::Index(i), diagonal[i]);
        Eigen::SparseMatrix<double> a(n, n);
        a.setFromTriplets(entries.begin(), entries.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
        if (solver.info() != Eigen::Success) return std::nullopt;
        const Eigen::MatrixXd x = solver.solve(rhs);
        if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
        for (std::size_t i = 0; i < inner.size(); ++i)
            out.at[inner[i]] = {x(Eigen::Index(i), 0), x(Eigen::Index(i), 1)};
    }
    // The pole: the vertex with the most edges between it and the border
    // (a breadth-first walk in from the border); the Möbius map
    // z -> (z - c) / (1 - conj(c) z) keeps the disk and its circle and sends c to 0.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
    for (const auto& [e, w] : weight) {
        neighbours[e.first].push_back(e.second);
        neighbours[e.second].push_back(e.first);
    }
    std::unordered_map<std::uint32_t, int> depth;
    std::queue<std::uint32_t> queue;
    for (std::uint32_t b : border) {
        depth[b] = 0;
        queue.push(b);
    }
    std::uint32_t pole = border.front();
    while (!queue.empty()) {
        const std::uint32_t v = queue.front();
        queue.pop();
        if (depth[v] > depth[pole] || (depth[v] == depth[pole] && v < pole && depth[v] > 0))
            pole = v;
        for (std::uint32_t n : neighbours[v])
            if (!depth.count(n)) {
                depth[n] = depth[v] + 1;
                queue.push(n);
            }
    }
    if (depth[pole] > 0) {
        const std::complex<double> c = out.at[pole];
        for (auto& [v, z] : out.at) {
            if (depth[v] == 0) continue; // the border stays on the circle (exactly)
            z = (z - c) / (1.0 - std::conj(c) * z);
        }
        for (std::uint32_t b : border) {
            auto& z = out.at[b];
            z = (z - c) / (1.0 - std::conj(c) * z);
            z /= std::abs(z);
        }
    }
    return out;
}

} // namespace fl::pde
