#include "mesh_error.h"

#include "parallel/work_pool.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace fl::mesh {

SurfaceError measureSurfaceError(const ImplicitField& field, const Mesh& mesh) {
    // Barycentric points of every triangle: the centroid, one towards each
    // corner and the middle of each edge; and every vertex, once. A mesh
    // deviates most at its vertices where they sit off the surface, in
    // the middle of its edges and faces where they cut across a curved one:
    // all three are measured, whatever made the mesh.
    static constexpr double kWeights[7][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                              {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                              {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                              {1.0 / 6, 1.0 / 6, 2.0 / 3},
                                              {0.5, 0.5, 0},
                                              {0, 0.5, 0.5},
                                              {0.5, 0, 0.5}};
    const bool closed = field.boundary == BoxBoundary::Closed;
    // Chunks of triangles, then chunks of vertices, taken by the shared
    // pool's threads; each chunk's points have their gradients in one call
    // (the batch evaluator pays its dispatch per instruction and block, not
    // per point). The chunks' sums are added in chunk order: the same figures
    // however many threads.
    constexpr std::size_t kTrianglesPerChunk = 256, kVerticesPerChunk = 2048;
    struct Chunk {
        double max = 0, sum = 0;
        std::size_t samples = 0;
    };
    const std::size_t triangleChunks =
        (mesh.triangles.size() + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
    const std::size_t chunks =
        triangleChunks + (mesh.positions.size() + kVerticesPerChunk - 1) / kVerticesPerChunk;
    std::vector<Chunk> results(chunks);
    std::atomic<std::size_t> next{0};
    const std::function<void(int)> measure = [&](int) {
        FieldSampler sampler(field);
        std::vector<Vec3> points;
        std::vector<formula::Dual> values;
        points.reserve(std::max(kTrianglesPerChunk * std::size(kWeights), kVerticesPerChunk));
        for (std::size_t c = next++; c < chunks; c = next++) {
            points.clear();
            if (c < triangleChunks) {
                const std::size_t first = c * kTrianglesPerChunk;
                const std::size_t last =
                    std::min(mesh.triangles.size(), first + kTrianglesPerChunk);
                for (std::size_t i = first; i < last; ++i) {
                    const Triangle& t = mesh.triangles[i];
                    for (const auto& w : kWeights) {
                        Vec3 p{};
                        for (int k3 = 0; k3 < 3; ++k3)
                            for (std::size_t k = 0; k < 3; ++k)
                                p[k] += w[k3] * mesh.positions[t[std::size_t(k3)]][k];
                        points.push_back(p);
                    }
                }
            } else {
                const std::size_t first = (c - triangleChunks) * kVerticesPerChunk;
                const std::size_t last = std::min(mesh.positions.size(), first + kVerticesPerChunk);
                for (std::size_t i = first; i < last; ++i)
                    points.push_back(
                        {mesh.positions[i][0], mesh.positions[i][1], mesh.positions[i][2]});
            }
            values.resize(points.size());
            sampler.gradients(points.data(), points.size(), values.data());
            Chunk& r = results[c];
            for (std::size_t n = 0; n < points.size(); ++n) {
                const Vec3& p = points[n];
                const formula::Dual& d = values[n];
                const double g = std::sqrt(d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2]);
                double distance = g > 0 && std::isfinite(d.v)
                                      ? std::abs(d.v) / g
                                      : std::numeric_limits<double>::infinity();
                if (closed)
                    for (std::size_t a = 0; a < 3; ++a)
                        distance = std::min({distance, std::abs(p[a] - field.box.lo[a]),
                                             std::abs(field.box.hi[a] - p[a])});
                if (!std::isfinite(distance)) continue; // undefined here: nothing to compare with
                r.max = std::max(r.max, distance);
                r.sum += distance;
                ++r.samples;
            }
        }
    };
    parallel::WorkPool& pool = parallel::WorkPool::shared();
    pool.run(chunks > 1 ? pool.threads() + 1 : 1, measure);
    SurfaceError e;
    double sum = 0;
    for (const Chunk& r : results) {
        e.max = std::max(e.max, r.max);
        sum += r.sum;
        e.samples += r.samples;
    }
    const double diagonal = field.box.diagonal();
    e.max /= diagonal;
    e.mean = e.samples ? sum / double(e.samples) / diagonal : 0;
    return e;
}

} // namespace fl::mesh
