// Displacement textures: added to f for implicit geometry (with the chain rule
// through the domain mapping in the gradient, and intervals that still
// contain every value), along the normals for parametric geometry.
#include "formula/compiler.h"
#include "mesh/mesh_topology.h"
#include "mesh/parametric.h"
#include "mesh/surface_displacement.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fl::mesh;

namespace {

fl::formula::Tape compile(const std::string& source, fl::formula::DefinitionKind kind) {
    fl::formula::CompileOptions o;
    o.kind = kind;
    auto r = fl::formula::compile(source, o);
    if (!r.ok()) throw std::runtime_error("does not compile: " + source);
    return *r.tape;
}

ImplicitField displaced(const std::string& f, const std::string& d, Box3 component) {
    ImplicitField field = support::field(f);
    field.displacement = Displacement{compile(d, fl::formula::DefinitionKind::Generic), component};
    return field;
}

} // namespace

TEST(Displacement, AddsToFInTheTexturesOwnBox) {
    // d = x over the unit box: at the geometry's x = -1 it is 0, at x = 1 it is 1.
    const ImplicitField f = displaced("0.25 - x*x - y*y - z*z", "x", {{0, 0, 0}, {1, 1, 1}});
    FieldSampler s(f);
    EXPECT_NEAR(s.value({-1, 0, 0}), 0.25 - 1 + 0, 1e-12);
    EXPECT_NEAR(s.value({1, 0, 0}), 0.25 - 1 + 1, 1e-12);
    EXPECT_NEAR(s.value({0, 0, 0}), 0.25 + 0.5, 1e-12);
    // A constant displacement grows the ball: 0.25 + 0.1 - r^2 >= 0.
    const MeshResult r =
        meshImplicit(displaced("0.25 - x*x - y*y - z*z", "0.1", {}), MeshOptions{});
    ASSERT_TRUE(r.ok());
    const double radius = std::sqrt(0.35);
    EXPECT_NEAR(analyseTopology(r.mesh).signedVolume, 4.0 / 3.0 * M_PI * radius * radius * radius,
                0.01);
}

TEST(Displacement, GradientMatchesFiniteDifferencesThroughTheMapping) {
    const ImplicitField f =
        displaced("0.5 - x*x - y*y - z*z", "0.1*sin(3*x)*u + 0.2*y*w*w", {{-2, 0, 1}, {2, 3, 5}});
    FieldSampler s(f);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> d(-0.9, 0.9);
    for (int i = 0; i < 200; ++i) {
        const std::array<double, 3> p{d(rng), d(rng), d(rng)};
        const fl::formula::Dual g = s.gradient(p);
        EXPECT_NEAR(g.v, s.value(p), 1e-12);
        for (std::size_t a = 0; a < 3; ++a) {
            std::array<double, 3> lo = p, hi = p;
            lo[a] -= 1e-6;
            hi[a] += 1e-6;
            EXPECT_NEAR(g.d[a], (s.value(hi) - s.value(lo)) / 2e-6, 1e-5);
        }
    }
}

TEST(Displacement, IntervalsStillContainEveryValue) {
    const ImplicitField f =
        displaced("0.5 - x*x - y*y - z*z", "0.3*noise(4*x, 4*y, 4*z)*v", {{-1, -1, -1}, {1, 1, 1}});
    FieldSampler s(f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int i = 0; i < 100; ++i) {
        std::array<double, 3> lo{d(rng), d(rng), d(rng)}, hi = lo;
        for (double& c : hi)
            c += 0.2;
        const fl::formula::Interval r = s.interval(lo, hi);
        for (int k = 0; k < 50; ++k) {
            std::array<double, 3> p{};
            for (std::size_t a = 0; a < 3; ++a)
                p[a] = lo[a] + (hi[a] - lo[a]) *
                                   (k * 0.61803 + a * 0.3 - std::floor(k * 0.61803 + a * 0.3));
            const double v = s.value(p);
            ASSERT_TRUE(r.contains(v)) << v << " not in [" << r.lo << ", " << r.hi << "]";
        }
    }
}

TEST(Displacement, ParametricSurfacesMoveAlongTheirNormals) {
    ParametricField pf;
    pf.tape = compile("x = sin(v)*cos(u); y = sin(v)*sin(u); z = cos(v);",
                      fl::formula::DefinitionKind::Parametric);
    pf.ranges = {{{0, 2 * M_PI}, {0, M_PI}, {0, 1}}};
    MeshResult r = meshParametric(pf);
    ASSERT_TRUE(r.ok());
    // Outward normals: a positive displacement makes the sphere bigger.
    bool outward = true;
    for (std::size_t i = 0; i < r.mesh.vertexCount(); ++i) {
        const auto& p = r.mesh.positions[i];
        const auto& n = r.mesh.normals[i];
        outward = outward && p[0] * n[0] + p[1] * n[1] + p[2] * n[2] > 0;
    }
    const double sign = outward ? 1 : -1;
    const Displacement d{compile(sign > 0 ? "0.1" : "-0.1", fl::formula::DefinitionKind::Generic),
                         {}};
    EXPECT_TRUE(displaceAlongNormals(r.mesh, d, pf.box, 0).empty());
    for (const auto& p : r.mesh.positions)
        EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.1, 1e-5);
    EXPECT_TRUE(analyseTopology(r.mesh).closed());
}
