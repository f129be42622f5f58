#include "surface_displacement.h"

#include "component_mapping.h"
#include "formula/eval_batch.h"

#include <cmath>

namespace fl::mesh {

std::vector<std::string> displaceAlongNormals(Mesh& mesh, const Displacement& displacement,
                                              const Box3& g, double t) {
    std::vector<std::string> warnings;
    const std::size_t n = mesh.vertexCount();
    const std::array<std::vector<double>, 6> in =
        componentViews(mesh, g, displacement.componentBox);
    formula::BatchEvaluator e(displacement.tape);
    formula::BatchInputs inputs;
    const formula::Input order[6] = {formula::Input::X, formula::Input::Y, formula::Input::Z,
                                     formula::Input::U, formula::Input::V, formula::Input::W};
    for (std::size_t k = 0; k < 6; ++k)
        inputs.set(order[k], in[k].data());
    inputs.set(formula::Input::T, t);
    std::vector<double> d(n);
    if (n) e.evaluate(inputs, n, d.data());
    bool undefined = false;
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(d[i])) {
            undefined = true;
            continue;
        }
        for (std::size_t a = 0; a < 3; ++a)
            mesh.positions[i][a] += float(d[i] * mesh.normals[i][a]);
    }
    // Normals of the displaced surface: area-weighted over its triangles.
    std::vector<std::array<double, 3>> sum(n, {0, 0, 0});
    for (const Triangle& tri : mesh.triangles) {
        const Vec3f &p = mesh.positions[tri[0]], &q = mesh.positions[tri[1]],
                    &r = mesh.positions[tri[2]];
        const double u[3] = {double(q[0]) - p[0], double(q[1]) - p[1], double(q[2]) - p[2]};
        const double v[3] = {double(r[0]) - p[0], double(r[1]) - p[1], double(r[2]) - p[2]};
        const double nn[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                              u[0] * v[1] - u[1] * v[0]};
        for (std::uint32_t k : tri)
            for (std::size_t a = 0; a < 3; ++a)
                sum[k][a] += nn[a];
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double len =
            std::sqrt(sum[i][0] * sum[i][0] + sum[i][1] * sum[i][1] + sum[i][2] * sum[i][2]);
        if (len > 0)
            mesh.normals[i] = {float(sum[i][0] / len), float(sum[i][1] / len),
                               float(sum[i][2] / len)};
    }
    if (undefined)
        warnings.push_back(
            "the displacement is undefined (NaN) at some vertices; they are left in place");
    return warnings;
}

} // namespace fl::mesh
