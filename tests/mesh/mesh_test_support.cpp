#include "mesh_test_support.h"

#include "formula/compiler.h"

#include <cmath>
#include <stdexcept>

namespace fl::mesh::support {

ImplicitField field(const std::string& formula, Box3 box, BoxBoundary boundary) {
    formula::CompileOptions options;
    options.kind = formula::DefinitionKind::Implicit;
    formula::CompileResult r = formula::compile(formula, options);
    if (!r.ok()) throw std::runtime_error("formula does not compile: " + formula);
    ImplicitField f;
    f.tape = std::move(*r.tape);
    f.box = box;
    f.boundary = boundary;
    return f;
}

ImplicitField field(const std::string& formula, double half, BoxBoundary boundary) {
    return field(formula, Box3{{-half, -half, -half}, {half, half, half}}, boundary);
}

ParametricField parametricField(const std::string& script, std::array<double, 2> u,
                                std::array<double, 2> v, std::array<double, 2> w) {
    formula::CompileOptions options;
    options.kind = formula::DefinitionKind::Parametric;
    formula::CompileResult r = formula::compile(script, options);
    if (!r.ok()) throw std::runtime_error("script does not compile: " + script);
    ParametricField f;
    f.tape = std::move(*r.tape);
    f.ranges = {u, v, w};
    return f;
}

namespace {
double surfaceError(const ImplicitField& f, const Mesh& mesh, bool centroids) {
    ImplicitField unclipped = f;
    unclipped.boundary = BoxBoundary::Open; // distance to the shape, not to the box faces
    FieldSampler s(unclipped);
    double worst = 0;
    auto measure = [&](std::array<double, 3> p) {
        const formula::Dual d = s.gradient(p);
        const double g = std::sqrt(d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2]);
        if (g > 0 && std::isfinite(d.v)) worst = std::max(worst, std::abs(d.v) / g);
    };
    for (const Triangle& t : centroids ? mesh.triangles : std::vector<Triangle>{}) {
        std::array<double, 3> c{};
        for (std::uint32_t i : t)
            for (int k = 0; k < 3; ++k)
                c[std::size_t(k)] += mesh.positions[i][std::size_t(k)] / 3.0;
        measure(c);
    }
    for (const Vec3f& p : mesh.positions)
        measure({p[0], p[1], p[2]});
    return worst / f.box.diagonal();
}
} // namespace

double maxSurfaceError(const ImplicitField& f, const Mesh& mesh) {
    return surfaceError(f, mesh, true);
}
double maxVertexError(const ImplicitField& f, const Mesh& mesh) {
    return surfaceError(f, mesh, false);
}

double areaInXY(const Mesh& m) {
    double a = 0;
    for (const Triangle& t : m.triangles) {
        const auto& p = m.positions[t[0]];
        const auto& q = m.positions[t[1]];
        const auto& r = m.positions[t[2]];
        a += (double(q[0] - p[0]) * (r[1] - p[1]) - double(r[0] - p[0]) * (q[1] - p[1])) / 2;
    }
    return a;
}

} // namespace fl::mesh::support
