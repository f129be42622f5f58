#include "cotangent_weights.h"

#include "field/vec3.h"

#include <algorithm>

namespace fl::pde {
namespace {

field::Vec3 at(const mesh::Mesh& m, std::uint32_t v) {
    return {m.positions[v][0], m.positions[v][1], m.positions[v][2]};
}

// The cotangent of the angle b-a-c at a (0 where the angle is degenerate).
double cotangent(const field::Vec3& a, const field::Vec3& b, const field::Vec3& c) {
    const field::Vec3 u = field::minus(b, a), v = field::minus(c, a);
    const double s = field::length(field::cross(u, v));
    return s > 0 ? field::dot(u, v) / s : 0;
}

} // namespace

EdgeWeights cotangentWeights(const mesh::Mesh& m, const Faces& region) {
    EdgeWeights weight;
    for (std::uint32_t f : region) {
        const auto& t = m.triangles[f];
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
            weight[{std::min(a, b), std::max(a, b)}] +=
                0.5 * cotangent(at(m, c), at(m, a), at(m, b));
        }
    }
    return weight;
}

} // namespace fl::pde
