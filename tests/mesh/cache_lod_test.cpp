// The mesh cache (keyed by definition, box, resolution, and t only when the
// geometry reads it) and the continuous level of detail.
#include "mesh/level_of_detail.h"
#include "mesh/mesh_cache.h"
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

using namespace fl::mesh;

TEST(MeshCache, TimeCountsOnlyWhenTheGeometryReadsIt) {
    MeshCache cache;
    ImplicitField still = support::field("0.5 - x*x - y*y - z*z");
    ImplicitField pulsing = support::field("0.3 + 0.1*sin(t) - x*x - y*y - z*z");
    for (double t : {0.0, 1.0, 2.0}) {
        still.t = pulsing.t = t;
        cache.mesh(still, 16);
        cache.mesh(pulsing, 16);
    }
    EXPECT_EQ(cache.misses(), 4u); // the still shape once, the pulsing one per moment
    EXPECT_EQ(cache.hits(), 2u);
    // Another resolution, box or definition is another mesh.
    cache.mesh(still, 16.5);
    ImplicitField moved = still;
    moved.box.hi[0] = 1.5;
    cache.mesh(moved, 16);
    cache.mesh(support::field("0.4 - x*x - y*y - z*z"), 16);
    EXPECT_EQ(cache.misses(), 7u);
}

TEST(MeshCache, TheBudgetEvictsTheLeastRecentlyUsed) {
    MeshCache probe;
    const ImplicitField a = support::field("0.5 - x*x - y*y - z*z");
    const std::size_t one = meshBytes(probe.mesh(a, 24)->mesh);
    MeshCache cache(one * 2 + one / 2); // room for two
    // The same surface written three ways: three keys, three meshes of one size.
    const ImplicitField b = support::field("2*(0.5 - x*x - y*y - z*z)");
    const ImplicitField c = support::field("3*(0.5 - x*x - y*y - z*z)");
    cache.mesh(a, 24);
    cache.mesh(b, 24);
    cache.mesh(a, 24); // a is now the most recent
    cache.mesh(c, 24); // b goes
    EXPECT_EQ(cache.size(), 2u);
    const std::size_t misses = cache.misses();
    cache.mesh(a, 24);
    EXPECT_EQ(cache.misses(), misses);
    cache.mesh(b, 24);
    EXPECT_EQ(cache.misses(), misses + 1);
}

TEST(MeshCache, TwoThreadsAskingTogetherMeshOnce) {
    MeshCache cache;
    const ImplicitField f = support::field("0.5 - x*x - y*y - z*z");
    std::atomic<int> made{0};
    auto ask = [&] {
        cache.get(f, 20, [&] {
            ++made;
            MeshOptions o;
            o.resolution = 20;
            return meshImplicit(f, o);
        });
    };
    std::thread t1(ask), t2(ask);
    t1.join();
    t2.join();
    EXPECT_EQ(made.load(), 1);
}

TEST(LevelOfDetail, ResolutionFollowsDistanceAndIsClamped) {
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    ViewForLod view;
    double previous = 1e9;
    for (double d : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0}) {
        view.distance = d;
        const double r = resolutionForView(box, view, 8, 256);
        EXPECT_LE(r, previous);
        EXPECT_GE(r, 8);
        EXPECT_LE(r, 256);
        previous = r;
    }
    view.distance = 2;
    const double at2 = resolutionForView(box, view, 1, 1e6);
    view.distance = 4;
    EXPECT_NEAR(resolutionForView(box, view, 1, 1e6), at2 / 2, 1e-9); // twice as far: half
    EXPECT_FALSE(lodChangeWorthIt(100, 110));
    EXPECT_TRUE(lodChangeWorthIt(100, 130));
    EXPECT_TRUE(lodChangeWorthIt(100, 70));
}
