#include "component_mapping.h"

namespace fl::mesh {

std::array<std::vector<double>, 6> componentViews(const Mesh& mesh, const Box3& g, const Box3& c) {
    const std::size_t n = mesh.vertexCount();
    const bool parametric = mesh.parameters.size() == n;
    std::array<std::vector<double>, 6> in;
    for (auto& v : in)
        v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& q = mesh.positions[i];
        const auto m = componentView({q[0], q[1], q[2]}, g, c);
        for (std::size_t k = 0; k < 6; ++k)
            in[k][i] = m[k];
        if (parametric)
            for (std::size_t a = 0; a < 3; ++a)
                in[3 + a][i] = mesh.parameters[i][a];
    }
    return in;
}

} // namespace fl::mesh
