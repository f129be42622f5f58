#include "mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace fl::mesh {

Topology analyseTopology(const Mesh& mesh) {
    Topology t;
    // Every half-edge as its undirected edge (lower index high) and, in the
    // lowest bit, its direction; sorted, the uses of one edge stand together:
    // how many triangles use it, and the balance of directions (a
    // well-oriented shared edge is walked once each way). A sorted vector,
    // not a hash map: a quarter of a million triangles in a few ms.
    std::vector<std::uint64_t> halfEdges;
    halfEdges.reserve(mesh.triangles.size() * 3);
    std::uint32_t maxIndex = 0;
    for (const Triangle& tri : mesh.triangles) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            ++t.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
            maxIndex = std::max(maxIndex, a);
            // Indices below 2^31 fit beside the direction bit; beyond, the
            // mesh could not be held anyway.
            const std::uint64_t edge = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            halfEdges.push_back((edge << 1) | (a < b ? 1u : 0u));
        }
        const Vec3f& p = mesh.positions[tri[0]];
        const Vec3f& q = mesh.positions[tri[1]];
        const Vec3f& r = mesh.positions[tri[2]];
        // Divergence theorem: the sum of p . (q x r) / 6 over outward triangles.
        t.signedVolume += (double(p[0]) * (double(q[1]) * r[2] - double(q[2]) * r[1]) -
                           double(p[1]) * (double(q[0]) * r[2] - double(q[2]) * r[0]) +
                           double(p[2]) * (double(q[0]) * r[1] - double(q[1]) * r[0])) /
                          6.0;
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    std::vector<bool> used(halfEdges.empty() ? 0 : std::size_t(maxIndex) + 1, false);
    std::size_t usedCount = 0;
    for (std::size_t i = 0; i < halfEdges.size();) {
        const std::uint64_t edge = halfEdges[i] >> 1;
        int count = 0, balance = 0;
        for (; i < halfEdges.size() && (halfEdges[i] >> 1) == edge; ++i) {
            ++count;
            balance += (halfEdges[i] & 1u) ? 1 : -1;
        }
        ++t.edges;
        if (count == 1) ++t.boundaryEdges;
        if (count > 2) ++t.nonManifoldEdges;
        if (count == 2 && balance != 0) ++t.misorientedEdges;
        for (const std::uint32_t v : {std::uint32_t(edge >> 32), std::uint32_t(edge)})
            if (!used[v]) {
                used[v] = true;
                ++usedCount;
            }
    }
    const std::size_t faces = mesh.triangles.size() - t.degenerateTriangles;
    t.eulerCharacteristic = long(usedCount) - long(t.edges) + long(faces);
    return t;
}

Mesh weldedByPosition(const Mesh& mesh) {
    Mesh out = mesh;
    std::map<Vec3f, std::uint32_t> first;
    std::vector<std::uint32_t> to(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        to[i] = first.emplace(mesh.positions[i], std::uint32_t(i)).first->second;
    for (Triangle& t : out.triangles)
        for (auto& v : t)
            v = to[v];
    return out;
}

bool orientClosedSurfaceOutward(Mesh& mesh) {
    if (mesh.isPointCloud() || mesh.isLines() || mesh.triangles.empty()) return false;
    const Topology t = analyseTopology(mesh);
    if (!t.closed() || !t.consistentlyOriented()) return false;
    if (t.signedVolume < 0) {
        for (Triangle& tri : mesh.triangles)
            std::swap(tri[1], tri[2]);
        for (Vec3f& n : mesh.normals)
            for (float& c : n)
                c = -c;
    }
    return true;
}

std::vector<Vec3f> vertexNormals(const Mesh& mesh) {
    std::vector<std::array<double, 3>> sum(mesh.positions.size(), {0, 0, 0});
    for (const Triangle& t : mesh.triangles) {
        if (t[0] >= sum.size() || t[1] >= sum.size() || t[2] >= sum.size()) continue;
        const Vec3f &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        // The cross product's length is twice the area: the weight comes with it.
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        for (std::uint32_t i : t)
            for (int k = 0; k < 3; ++k)
                sum[i][std::size_t(k)] += n[k];
    }
    std::vector<Vec3f> out(sum.size(), Vec3f{0, 0, 0});
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double l = std::hypot(sum[i][0], sum[i][1], sum[i][2]);
        if (l > 0 && std::isfinite(l))
            out[i] = {float(sum[i][0] / l), float(sum[i][1] / l), float(sum[i][2] / l)};
    }
    return out;
}

} // namespace fl::mesh
