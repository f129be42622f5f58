// NURBS (nurbs.h): exact conics, derivatives that match finite differences,
// closed revolved surfaces, trimming, and the X3D fallbacks for bad knots,
// weights and orders. The scene nodes: geometry_nodes_test.cpp.
#include "mesh/mesh_topology.h"
#include "mesh/nurbs.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace fl::mesh;

namespace {

const double kHalfRoot2 = std::sqrt(0.5);

// The nine-point rational quadratic circle of radius 1 in the x-y plane.
NurbsCurve unitCircle() {
    NurbsCurve c;
    std::vector<std::string> warnings;
    c.points = {{1, 0, 0},   {1, 1, 0},  {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0},
                {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
    c.weights = {1, kHalfRoot2, 1, kHalfRoot2, 1, kHalfRoot2, 1, kHalfRoot2, 1};
    c.basis =
        makeNurbsBasis(3, 9, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, "", warnings);
    EXPECT_TRUE(warnings.empty());
    return c;
}

// A unit sphere: the circle (u) swept round a half circle from pole to pole (v).
NurbsSurface unitSphere() {
    const NurbsCurve circle = unitCircle();
    // Half circle in the x-z plane from the south pole to the north pole.
    const std::vector<std::array<double, 2>> profile = {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<double> profileWeights = {1, kHalfRoot2, 1, kHalfRoot2, 1};
    NurbsSurface s;
    std::vector<std::string> warnings;
    s.u = circle.basis;
    s.v = makeNurbsBasis(3, 5, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, "v", warnings);
    for (std::size_t j = 0; j < profile.size(); ++j)
        for (std::size_t i = 0; i < circle.points.size(); ++i) {
            const auto& c = circle.points[i];
            s.points.push_back({c[0] * profile[j][0], c[1] * profile[j][0], profile[j][1]});
            s.weights.push_back(circle.weights[i] * profileWeights[j]);
        }
    return s;
}

// A flat bilinear patch over [0, 1]^2: the surface is its (u, v) plane.
NurbsSurface unitPlane() {
    NurbsSurface plane;
    std::vector<std::string> warnings;
    plane.u = makeNurbsBasis(2, 2, {0, 0, 1, 1}, "u", warnings);
    plane.v = makeNurbsBasis(2, 2, {0, 0, 1, 1}, "v", warnings);
    plane.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    plane.weights = {1, 1, 1, 1};
    return plane;
}

double distance(const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

} // namespace

TEST(Nurbs, RationalQuadraticCircleIsExact) {
    const NurbsCurve c = unitCircle();
    for (int k = 0; k <= 1000; ++k) {
        const Vec3 p = evaluate(c, k / 1000.0);
        EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 1e-12);
    }
    EXPECT_NEAR(distance(evaluate(c, 0.25), {0, 1, 0}), 0, 1e-15);
    const Mesh m = nurbsCurveMesh(c, 64);
    EXPECT_TRUE(m.isLines());
    EXPECT_EQ(m.segments.size(), 64u);
}

TEST(Nurbs, SurfaceDerivativesMatchFiniteDifferences) {
    // A random rational bicubic patch with uneven knots.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-1, 1), weight(0.3, 2);
    NurbsSurface s;
    std::vector<std::string> warnings;
    s.u = makeNurbsBasis(4, 6, {0, 0, 0, 0, 0.3, 0.45, 1, 1, 1, 1}, "u", warnings);
    s.v = makeNurbsBasis(3, 5, {0, 0, 0, 0.2, 0.7, 1, 1, 1}, "v", warnings);
    ASSERT_TRUE(warnings.empty());
    for (int k = 0; k < 30; ++k) {
        s.points.push_back({coord(rng), coord(rng), coord(rng)});
        s.weights.push_back(weight(rng));
    }
    const double h = 1e-6;
    for (int k = 0; k < 200; ++k) {
        const double u = 0.01 + 0.98 * (k % 20) / 19.0, v = 0.01 + 0.98 * (k / 20) / 9.0;
        const SurfacePoint p = evaluate(s, u, v);
        const SurfacePoint pu = evaluate(s, u + h, v), mu = evaluate(s, u - h, v);
        const SurfacePoint pv = evaluate(s, u, v + h), mv = evaluate(s, u, v - h);
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_NEAR(p.du[c], (pu.position[c] - mu.position[c]) / (2 * h), 1e-5);
            EXPECT_NEAR(p.dv[c], (pv.position[c] - mv.position[c]) / (2 * h), 1e-5);
        }
    }
}

TEST(Nurbs, RevolvedSphereIsClosedOnTheSphereAndFacesOutward) {
    const Mesh m = nurbsSurfaceMesh(unitSphere(), 48, 24);
    for (const Vec3f& p : m.positions)
        EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1e-6);
    const Topology t = analyseTopology(m);
    EXPECT_TRUE(t.closed()) << t.boundaryEdges << " open edges: the seam or a pole is not shared";
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.consistentlyOriented());
    EXPECT_NEAR(t.signedVolume, 4.0 / 3.0 * std::numbers::pi, 0.05);
    // Normals point out, poles included (their derivatives vanish there).
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f& p = m.positions[i];
        const Vec3f& n = m.normals[i];
        EXPECT_GT(p[0] * n[0] + p[1] * n[1] + p[2] * n[2], 0.99) << "vertex " << i;
    }
}

TEST(Nurbs, TrimmingKeepsTheInsideOfTheContours) {
    const NurbsSurface plane = unitPlane();
    const auto area = support::areaInXY;
    EXPECT_NEAR(area(nurbsSurfaceMesh(plane, 10, 10)), 1.0, 1e-6);
    Contour2 disc;
    for (int k = 0; k < 256; ++k) {
        const double a = 2 * std::numbers::pi * k / 256;
        disc.push_back({0.5 + 0.4 * std::cos(a), 0.5 + 0.4 * std::sin(a)});
    }
    const double discArea = signedArea2(disc) / 2;
    const Mesh kept = nurbsSurfaceMesh(plane, 10, 10, {disc});
    EXPECT_NEAR(area(kept), discArea, 1e-6);
    // Points inside the disc come from the grid, not only from the contour.
    EXPECT_GT(kept.positions.size(), 256u + 40u);
    const Contour2 outline = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_NEAR(area(nurbsSurfaceMesh(plane, 10, 10, {outline, disc})), 1.0 - discArea, 1e-6);
}

TEST(Nurbs, BadKnotsWeightsAndOrdersFallBackWithWarnings) {
    std::vector<std::string> warnings;
    NurbsBasis b = makeNurbsBasis(3, 4, {0, 1, 2}, "u", warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("uniform open knot vector"), std::string::npos);
    EXPECT_EQ(b.knots, (std::vector<double>{0, 0, 0, 0.5, 1, 1, 1}));
    warnings.clear();
    b = makeNurbsBasis(3, 4, {0, 0, 0, 2, 1, 3, 3}, "", warnings); // decreasing
    EXPECT_EQ(warnings.size(), 1u);
    warnings.clear();
    b = makeNurbsBasis(9, 4, {}, "v", warnings);
    EXPECT_EQ(b.order, 4);
    EXPECT_NE(warnings.at(0).find("v order 9"), std::string::npos);
    EXPECT_EQ(makeNurbsBasis(3, 1, {}, "", warnings).count, 0);
    warnings.clear();
    EXPECT_EQ(nurbsWeights({1, -2, 1}, 3, warnings), (std::vector<double>{1, 1, 1}));
    EXPECT_EQ(warnings.size(), 1u);
    EXPECT_EQ(nurbsSegments(0, 5), 10);
    EXPECT_EQ(nurbsSegments(7, 5), 7);
    EXPECT_EQ(nurbsSegments(-3, 5), 15);
    EXPECT_EQ(nurbsSegments(-2000000000, 5), 4096);
}

TEST(Nurbs, PoleNormalsPointOutOnAnyScaleAndPlace) {
    // The derivatives vanish at the poles only up to rounding, which grows
    // with the coordinates: a sphere of radius 3 around (5, -2, 1).
    NurbsSurface s = unitSphere();
    for (Vec3& p : s.points)
        p = {5 + 3 * p[0], -2 + 3 * p[1], 1 + 3 * p[2]};
    const Mesh m = nurbsSurfaceMesh(s, 32, 16);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3f& p = m.positions[i];
        const Vec3f& n = m.normals[i];
        const double out = ((p[0] - 5) * n[0] + (p[1] + 2) * n[1] + (p[2] - 1) * n[2]) / 3;
        EXPECT_GT(out, 0.98) << "vertex " << i << " at z " << p[2];
    }
}

TEST(Nurbs, TrimmingOutsideTheRangeIsCutToIt) {
    const NurbsSurface plane = unitPlane();
    const Mesh m =
        nurbsSurfaceMesh(plane, 4, 4, {{{-0.5, -0.5}, {1.5, -0.5}, {1.5, 1.5}, {-0.5, 1.5}}});
    for (const Vec3f& p : m.positions) {
        EXPECT_GE(p[0], -1e-6);
        EXPECT_LE(p[0], 1 + 1e-6);
        EXPECT_GE(p[1], -1e-6);
        EXPECT_LE(p[1], 1 + 1e-6);
    }
    EXPECT_EQ(m.triangleCount(), 32u);
}

TEST(Nurbs, HighOrdersAreLowered) {
    std::vector<std::string> warnings;
    const NurbsBasis b = makeNurbsBasis(20000, 20000, {}, "", warnings);
    EXPECT_EQ(b.order, kMaxNurbsOrder);
    ASSERT_EQ(warnings.size(), 1u);
    int u = 4096, v = 4096;
    limitNurbsCells(u, v, warnings);
    EXPECT_LE((long long)u * v, kMaxNurbsCells);
    EXPECT_EQ(u, v);
}
