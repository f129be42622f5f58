#include "marching_cubes.h"

#include "parallel/work_pool.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

namespace fl::mesh {
namespace {

// Corner i of a cell sits at (i & 1, (i >> 1) & 1, (i >> 2) & 1).
// Edges 0-3 run along x, 4-7 along y, 8-11 along z.
struct Edge {
    int a, b;
};
constexpr Edge kEdges[12] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                             {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

int edgeBetween(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((kEdges[e].a == a && kEdges[e].b == b) || (kEdges[e].a == b && kEdges[e].b == a))
            return e;
    return -1;
}

// Each face's corners in cyclic order.
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                              {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};

struct Case {
    int count = 0; // triangles
    std::array<std::array<std::int8_t, 3>, 12> triangles{};
    EdgeGroups groups; // which loop each crossing edge is on
};

std::array<double, 3> cornerPosition(int c) {
    return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)};
}

// One case: the crossings on each face joined into segments, the segments
// chained into loops, each loop fanned into triangles facing outward.
Case buildCase(int config) {
    auto in = [&](int c) { return (config >> c) & 1; };
    std::vector<std::array<int, 2>> segments;
    for (const auto& f : kFaces) {
        int crossing[4], n = 0;
        for (int k = 0; k < 4; ++k)
            if (in(f[k]) != in(f[(k + 1) % 4])) crossing[n++] = k;
        if (n == 2) {
            segments.push_back({edgeBetween(f[crossing[0]], f[(crossing[0] + 1) % 4]),
                                edgeBetween(f[crossing[1]], f[(crossing[1] + 1) % 4])});
        } else if (n == 4) {
            // Ambiguous face: cut off each inside corner on its own.
            for (int k = 0; k < 4; ++k)
                if (in(f[k]))
                    segments.push_back(
                        {edgeBetween(f[(k + 3) % 4], f[k]), edgeBetween(f[k], f[(k + 1) % 4])});
        }
    }
    Case out;
    out.groups.group.fill(-1);
    std::vector<bool> used(segments.size(), false);
    for (std::size_t s0 = 0; s0 < segments.size(); ++s0) {
        if (used[s0]) continue;
        std::vector<int> loop{segments[s0][0]};
        int current = segments[s0][1];
        used[s0] = true;
        while (current != loop.front()) {
            loop.push_back(current);
            bool found = false;
            for (std::size_t s = 0; s < segments.size() && !found; ++s) {
                if (used[s]) continue;
                if (segments[s][0] == current || segments[s][1] == current) {
                    current = segments[s][0] == current ? segments[s][1] : segments[s][0];
                    used[s] = true;
                    found = true;
                }
            }
            if (!found) break;
        }
        // Orientation: the loop's area vector must point from the inside
        // corners of its edges to the outside ones.
        std::array<double, 3> area{}, outward{};
        std::vector<std::array<double, 3>> p;
        for (int e : loop) {
            const auto a = cornerPosition(kEdges[e].a), b = cornerPosition(kEdges[e].b);
            p.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
            const double sign = in(kEdges[e].a) ? 1 : -1; // from inside to outside
            for (int k = 0; k < 3; ++k)
                outward[std::size_t(k)] += sign * (b[std::size_t(k)] - a[std::size_t(k)]);
        }
        for (std::size_t i = 0; i < p.size(); ++i) {
            const auto& u = p[i];
            const auto& v = p[(i + 1) % p.size()];
            area[0] += u[1] * v[2] - u[2] * v[1];
            area[1] += u[2] * v[0] - u[0] * v[2];
            area[2] += u[0] * v[1] - u[1] * v[0];
        }
        if (area[0] * outward[0] + area[1] * outward[1] + area[2] * outward[2] < 0)
            std::reverse(loop.begin(), loop.end());
        for (std::size_t i = 1; i + 1 < loop.size(); ++i)
            out.triangles[std::size_t(out.count++)] = {std::int8_t(loop[0]), std::int8_t(loop[i]),
                                                       std::int8_t(loop[i + 1])};
        for (int e : loop)
            out.groups.group[std::size_t(e)] = std::int8_t(out.groups.count);
        ++out.groups.count;
    }
    return out;
}

const std::array<Case, 256>& caseTable() {
    static const std::array<Case, 256> table = [] {
        std::array<Case, 256> t{};
        for (int c = 0; c < 256; ++c)
            t[std::size_t(c)] = buildCase(c);
        return t;
    }();
    return table;
}

} // namespace

const EdgeGroups& edgeGroups(int config) {
    return caseTable()[std::size_t(config & 255)].groups;
}

DenseResult marchingCubes(const ImplicitField& field, double resolution, int threads) {
    const auto start = std::chrono::steady_clock::now();
    DenseResult result;
    if (!field.box.valid() || !(resolution >= 1)) return result;
    const auto& table = caseTable();
    std::array<int, 3> n{};
    std::array<double, 3> h{};
    const double target = field.box.longestSide() / resolution;
    for (std::size_t a = 0; a < 3; ++a) {
        n[a] = std::max(1, int(std::ceil(field.box.size(int(a)) / target - 1e-9)));
        h[a] = field.box.size(int(a)) / n[a];
    }
    if (threads <= 0) threads = std::max(1, int(std::thread::hardware_concurrency()));
    threads = std::min(threads, n[2]);
    std::vector<Mesh> parts(static_cast<std::size_t>(threads));
    std::vector<EvaluationCounts> counts(static_cast<std::size_t>(threads));
    // Slabs of planes, taken by whichever thread comes: the shared pool may
    // lend fewer threads than asked (parallel/work_pool.h).
    std::atomic<int> nextSlab{0};
    auto slab = [&](int w) {
        const int k0 = n[2] * w / threads, k1 = n[2] * (w + 1) / threads;
        FieldSampler sampler(field);
        const std::size_t row = std::size_t(n[0] + 1), plane = row * std::size_t(n[1] + 1);
        std::vector<double> xs(plane), ys(plane), below(plane), above(plane);
        auto sample = [&](int k, std::vector<double>& out) {
            std::vector<double> zs(plane, field.box.lo[2] + k * h[2]);
            sampler.values(xs.data(), ys.data(), zs.data(), plane, out.data());
        };
        for (int j = 0; j <= n[1]; ++j)
            for (int i = 0; i <= n[0]; ++i) {
                xs[std::size_t(j) * row + std::size_t(i)] = field.box.lo[0] + i * h[0];
                ys[std::size_t(j) * row + std::size_t(i)] = field.box.lo[1] + j * h[1];
            }
        Mesh& m = parts[std::size_t(w)];
        sample(k0, below);
        for (int k = k0; k < k1; ++k) {
            sample(k + 1, above);
            for (int j = 0; j < n[1]; ++j)
                for (int i = 0; i < n[0]; ++i) {
                    double v[8];
                    int config = 0;
                    for (int c = 0; c < 8; ++c) {
                        const std::size_t at =
                            std::size_t(j + ((c >> 1) & 1)) * row + std::size_t(i + (c & 1));
                        v[c] = (c >> 2) & 1 ? above[at] : below[at];
                        if (v[c] > 0) config |= 1 << c; // f > 0: inside, as the adaptive mesher
                    }
                    const Case& cs = table[std::size_t(config)];
                    if (!cs.count) continue;
                    int vertexOfEdge[12];
                    std::fill(std::begin(vertexOfEdge), std::end(vertexOfEdge), -1);
                    for (int t = 0; t < cs.count; ++t) {
                        Triangle tri{};
                        for (int q = 0; q < 3; ++q) {
                            const int e = cs.triangles[std::size_t(t)][std::size_t(q)];
                            if (vertexOfEdge[e] < 0) {
                                const double va = v[kEdges[e].a], vb = v[kEdges[e].b];
                                const double s =
                                    std::isfinite(va / (va - vb)) ? va / (va - vb) : 0.5;
                                const auto pa = cornerPosition(kEdges[e].a),
                                           pb = cornerPosition(kEdges[e].b);
                                Vec3f p{};
                                for (std::size_t a = 0; a < 3; ++a) {
                                    const double local = pa[a] + s * (pb[a] - pa[a]);
                                    const int cell = a == 0 ? i : a == 1 ? j : k;
                                    p[a] = float(field.box.lo[a] + (cell + local) * h[a]);
                                }
                                vertexOfEdge[e] = int(m.positions.size());
                                m.positions.push_back(p);
                            }
                            tri[std::size_t(q)] = std::uint32_t(vertexOfEdge[e]);
                        }
                        m.triangles.push_back(tri);
                    }
                }
            std::swap(below, above);
        }
        counts[std::size_t(w)] = sampler.counts();
    };
    const std::function<void(int)> slabs = [&](int) {
        for (int w = nextSlab++; w < threads; w = nextSlab++)
            slab(w);
    };
    parallel::WorkPool::shared().run(threads, slabs);
    for (std::size_t w = 0; w < parts.size(); ++w) {
        const auto base = std::uint32_t(result.mesh.positions.size());
        result.mesh.positions.insert(result.mesh.positions.end(), parts[w].positions.begin(),
                                     parts[w].positions.end());
        for (Triangle t : parts[w].triangles) {
            for (auto& i : t)
                i += base;
            result.mesh.triangles.push_back(t);
        }
        result.evaluations += counts[w];
    }
    result.mesh.normals.assign(result.mesh.positions.size(), Vec3f{0, 0, 1});
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace fl::mesh
