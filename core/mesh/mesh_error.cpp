#include "mesh_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fl::mesh {

SurfaceError measureSurfaceError(const ImplicitField& field, const Mesh& mesh) {
    FieldSampler sampler(field);
    SurfaceError e;
    double sum = 0;
    // Barycentric points: the centroid and one towards each corner.
    static constexpr double kWeights[4][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                              {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                              {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                              {1.0 / 6, 1.0 / 6, 2.0 / 3}};
    const bool closed = field.boundary == BoxBoundary::Closed;
    // The points of a few hundred triangles at a time, their gradients in one
    // call (the batch evaluator pays its dispatch per instruction and block,
    // not per point: three times faster than one point at a time), then
    // taken in the same order as before, so the figures do not change.
    constexpr std::size_t kTrianglesPerBatch = 256;
    std::vector<Vec3> points;
    std::vector<formula::Dual> values;
    points.reserve(kTrianglesPerBatch * 4);
    for (std::size_t first = 0; first < mesh.triangles.size(); first += kTrianglesPerBatch) {
        const std::size_t last = std::min(mesh.triangles.size(), first + kTrianglesPerBatch);
        points.clear();
        for (std::size_t i = first; i < last; ++i) {
            const Triangle& t = mesh.triangles[i];
            for (const auto& w : kWeights) {
                Vec3 p{};
                for (int c = 0; c < 3; ++c)
                    for (std::size_t k = 0; k < 3; ++k)
                        p[k] += w[c] * mesh.positions[t[std::size_t(c)]][k];
                points.push_back(p);
            }
        }
        values.resize(points.size());
        sampler.gradients(points.data(), points.size(), values.data());
        for (std::size_t n = 0; n < points.size(); ++n) {
            const Vec3& p = points[n];
            const formula::Dual& d = values[n];
            const double g = std::sqrt(d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2]);
            double distance = g > 0 && std::isfinite(d.v) ? std::abs(d.v) / g
                                                          : std::numeric_limits<double>::infinity();
            if (closed)
                for (std::size_t a = 0; a < 3; ++a)
                    distance = std::min({distance, std::abs(p[a] - field.box.lo[a]),
                                         std::abs(field.box.hi[a] - p[a])});
            if (!std::isfinite(distance)) continue; // undefined here: nothing to compare with
            e.max = std::max(e.max, distance);
            sum += distance;
            ++e.samples;
        }
    }
    const double diagonal = field.box.diagonal();
    e.max /= diagonal;
    e.mean = e.samples ? sum / double(e.samples) / diagonal : 0;
    return e;
}

} // namespace fl::mesh
