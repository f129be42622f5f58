// The triangles the god-object touches (haptics/triangle_bvh.h): the first
// crossing of a segment agrees with trying every triangle, inside is inside,
// and a proxy pressed into a box's corner stays on its faces.
#include "force_test_scenes.h"

#include "haptics/probe.h"
#include "haptics/triangle_bvh.h"
#include "mesh/standard_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace fl;
using namespace fl::haptics;
using field::Vec3;

TEST(TriangleBvh, TheFirstCrossingIsTheNearestOfAllTriangles) {
    const mesh::Mesh sphere = mesh::sphereMesh(1, 24);
    const TriangleBvh bvh(sphere);
    EXPECT_EQ(bvh.triangleCount(), sphere.triangleCount());
    // Each triangle alone in a tree of its own: the brute force answer.
    std::vector<TriangleBvh> one;
    for (const auto& t : sphere.triangles) {
        mesh::Mesh m;
        m.positions = sphere.positions;
        m.triangles = {t};
        one.emplace_back(m);
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int k = 0; k < 200; ++k) {
        const Vec3 a{u(random), u(random), u(random)}, b{u(random), u(random), u(random)};
        const auto hit = bvh.firstHit(a, b);
        std::optional<double> best;
        for (const TriangleBvh& t : one)
            if (const auto h = t.firstHit(a, b); h && (!best || h->s < *best)) best = h->s;
        ASSERT_EQ(hit.has_value(), best.has_value()) << k;
        if (hit) {
            EXPECT_DOUBLE_EQ(hit->s, *best) << k;
        }
    }
}

TEST(TriangleBvh, InsideIsAnOddNumberOfCrossings) {
    const TriangleBvh cube(mesh::boxMesh({2, 2, 2}));
    EXPECT_TRUE(cube.contains({0, 0, 0}));
    EXPECT_TRUE(cube.contains({0.99, -0.99, 0.5}));
    EXPECT_FALSE(cube.contains({1.01, 0, 0}));
    EXPECT_FALSE(cube.contains({0, 5, 0}));
    const auto in = cube.firstHit({0, 0, 3}, {0, 0, 0});
    ASSERT_TRUE(in);
    EXPECT_TRUE(in->frontFacing); // entering through the top, wound outwards
    EXPECT_NEAR(in->point[2], 1, 1e-12);
    EXPECT_NEAR(in->normal[2], 1, 1e-12);
}

TEST(PolygonContact, AProxyPressedIntoABoxsCornerStaysOnItsFaces) {
    // A Box made tangible by an FShape grouped with it (the fan's way).
    const auto scene = test::readScene(R"(#X3D V3.3 utf8
PROFILE Immersive
Group { children [
  Shape { geometry Box { size 2 2 2 } }
  FShape { physics FPhysics { surface FSurface {
    friction FFriction { definition "0" } } } }
] }
)");
    ProbeOptions o;
    o.path = {{1.5, 1.5, 1.5}, {0.995, 0.995, 0.995}}; // 5 mm into the corner
    const auto r = runProbe(*scene, o);
    ASSERT_TRUE(r);
    const ProbeTick& end = r->ticks.back();
    ASSERT_EQ(end.contact, ContactKind::Surface);
    // The proxy is on the box, not in it: on one face at least, and it
    // pushes the tool out, never in.
    const auto& p = end.proxy;
    EXPECT_GE(std::max({p[0], p[1], p[2]}), 1 - 1e-6) << p[0] << " " << p[1] << " " << p[2];
    double out = 0;
    for (int k = 0; k < 3; ++k) {
        EXPECT_GE(end.force[std::size_t(k)], 0) << k;
        out += end.force[std::size_t(k)];
    }
    EXPECT_GT(out, 0);
    // Deeper along the diagonal every tick: the proxy never went inside.
    for (const ProbeTick& t : r->ticks)
        EXPECT_GE(std::max({t.proxy[0], t.proxy[1], t.proxy[2]}), 1 - 1e-6) << t.ms;
}

TEST(PolygonContact, ATriangulatedBallFeelsLikeItsFunction) {
    // The same ball, by its function and by its triangles (collision
    // "polygonal" at resolution 64): the proxies agree to the mesh's error.
    auto ball = [](const char* collision) {
        return test::readScene(std::string(R"(#X3D V3.3 utf8
PROFILE Immersive
FShape { geometry FGeometry { definition "1 - x*x - y*y - z*z" resolution 64
  domainMin -1.2 -1.2 -1.2 domainMax 1.2 1.2 1.2 collision ")") +
                               collision + R"(" }
  physics FPhysics { surface FSurface { friction FFriction { definition "0" } } } }
)");
    };
    ProbeOptions o;
    o.path = {{0.3, 0.2, 1.5}, {0.3, 0.2, 0.9}, {-0.4, 0.3, 0.85}}; // ends 1.4 cm deep
    const auto f = runProbe(*ball("function"), o), p = runProbe(*ball("polygonal"), o);
    ASSERT_TRUE(f && p);
    ASSERT_EQ(f->ticks.back().contact, ContactKind::Surface);
    ASSERT_EQ(p->ticks.back().contact, ContactKind::Surface);
    const double apart = field::length(field::minus(f->ticks.back().proxy, p->ticks.back().proxy));
    EXPECT_LT(apart, 0.01) << apart << " function (" << f->ticks.back().proxy[0] << ", "
                           << f->ticks.back().proxy[1] << ", " << f->ticks.back().proxy[2]
                           << ") polygons (" << p->ticks.back().proxy[0] << ", "
                           << p->ticks.back().proxy[1] << ", " << p->ticks.back().proxy[2]
                           << ")"; // a cell of 2.4 / 64
}
