// The kernel's vocabulary (field/vec3.h, field/box3.h) and the march of a ray
// to f = 0 (field/ray_march.h) that picking, haptic contact and the grader
// share: laws over random rays, and the named hard cases (thin shells,
// grazing rays, closed boxes, open surfaces, undefined regions).
#include "field/box3.h"
#include "field/field_sampler.h"
#include "field/ray_march.h"
#include "formula/compiler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace fl::field;

namespace {

fl::formula::Tape tapeOf(const char* source) {
    fl::formula::CompileOptions o;
    o.kind = fl::formula::DefinitionKind::Implicit;
    auto r = fl::formula::compile(source, o);
    EXPECT_TRUE(r.ok()) << source;
    return *r.tape;
}

ImplicitField fieldOf(const char* source, Box3 box = {},
                      BoxBoundary boundary = BoxBoundary::Closed) {
    ImplicitField f;
    f.tape = tapeOf(source);
    f.box = box;
    f.boundary = boundary;
    return f;
}

} // namespace

TEST(Vec3, OperationsAgreeWithTheirDefinitions) {
    const Vec3 a{1, 2, 3}, b{-2, 0.5, 4};
    EXPECT_EQ(plus(a, b), (Vec3{-1, 2.5, 7}));
    EXPECT_EQ(minus(a, b), (Vec3{3, 1.5, -1}));
    EXPECT_EQ(scaled(a, 2), (Vec3{2, 4, 6}));
    EXPECT_EQ(along(a, b, 2), (Vec3{-3, 3, 11}));
    EXPECT_DOUBLE_EQ(dot(a, b), 1 * -2 + 2 * 0.5 + 3 * 4);
    const Vec3 c = cross(a, b);
    EXPECT_DOUBLE_EQ(dot(c, a), 0);
    EXPECT_DOUBLE_EQ(dot(c, b), 0);
    EXPECT_DOUBLE_EQ(length({3, 4, 12}), 13);
    EXPECT_EQ(unitOr({0, 0, 0}, {1, 0, 0}), (Vec3{1, 0, 0}));
    EXPECT_EQ(unitOr({NAN, 0, 0}, {0, 1, 0}), (Vec3{0, 1, 0}));
    EXPECT_NEAR(length(unitOr({1e-200, 3e-200, 0}, {})), 1, 1e-15);
    EXPECT_FALSE(isFinite({0, INFINITY, 0}));
}

TEST(Box3, ClipRayFindsWhereARayIsInside) {
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    auto s = clipRay({-3, 0, 0}, {1, 0, 0}, box);
    ASSERT_TRUE(s);
    EXPECT_DOUBLE_EQ(s->enter, 2);
    EXPECT_DOUBLE_EQ(s->exit, 4);
    // From inside: it enters at 0.
    s = clipRay({0, 0, 0}, {0, 0, 2}, box);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->enter, 0);
    EXPECT_DOUBLE_EQ(s->exit, 0.5);
    EXPECT_FALSE(clipRay({-3, 2, 0}, {1, 0, 0}, box)); // parallel, outside
    EXPECT_FALSE(clipRay({3, 0, 0}, {1, 0, 0}, box));  // pointing away
    EXPECT_FALSE(clipRay({0, 0, 0}, {NAN, 0, 0}, box));
    EXPECT_TRUE(box.contains({1, -1, 0.5}));
    EXPECT_FALSE(box.contains({1.0001, 0, 0}));
    EXPECT_EQ(nearestFaceNormal(box, {0.2, 0.99, 0}), (Vec3{0, 1, 0}));
    EXPECT_EQ(nearestFaceNormal(box, {-0.999, 0.2, 0}), (Vec3{-1, 0, 0}));
}

// Law: every hit lies on f = 0 (to rounding), on the ray, inside the box, no
// farther than where an exact sphere says, with the outward normal.
TEST(RayMarch, RandomRaysHitTheUnitSphereWhereGeometrySays) {
    const ImplicitField field = fieldOf("1 - x^2 - y^2 - z^2", {{-2, -2, -2}, {2, 2, 2}});
    FieldSampler sampler(field);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int k = 0; k < 300; ++k) {
        const Vec3 origin{4 * u(rng), 4 * u(rng), 4 * u(rng)};
        if (length(origin) < 1.5) continue;
        const Vec3 towards = unitOr(minus(scaled(Vec3{u(rng), u(rng), u(rng)}, 0.9), origin), {});
        const auto hit = marchToSurface(sampler, origin, towards);
        // The exact answer: |o + s d| = 1.
        const double b = dot(origin, towards), c = dot(origin, origin) - 1, disc = b * b - c;
        if (disc <= 1e-9) { // misses (or grazes)
            if (disc < -1e-6) {
                EXPECT_FALSE(hit) << k;
            }
            continue;
        }
        ASSERT_TRUE(hit) << k;
        ++hits;
        const double exact = -b - std::sqrt(disc);
        EXPECT_NEAR(hit->s, exact, 1e-9) << k;
        EXPECT_NEAR(length(hit->point), 1, 1e-9);
        EXPECT_NEAR(dot(hit->normal, hit->point), 1, 1e-6) << "outward, unit";
        EXPECT_FALSE(hit->onBoxFace);
    }
    EXPECT_GT(hits, 100);
}

// A shell far thinner than a step of the march (1/512 of the diagonal): both
// ends of the step are outside, only the interval bound sees it.
TEST(RayMarch, ThinShellIsNotTunnelledThrough) {
    const ImplicitField field = fieldOf("1e-5 - abs(x - 0.3)");
    FieldSampler sampler(field);
    const auto hit = marchToSurface(sampler, {-3, 0.1, 0.2}, {1, 0, 0});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point[0], 0.3 - 1e-5, 1e-12);
    EXPECT_NEAR(hit->normal[0], -1, 1e-9);
}

// A segment (limit 1) stops where the device is: a surface beyond it is not met.
TEST(RayMarch, SegmentStopsAtItsEnd) {
    const ImplicitField field = fieldOf("x - 0.5"); // inside for x > 0.5
    FieldSampler sampler(field);
    MarchOptions segment;
    segment.limit = 1;
    EXPECT_FALSE(marchToSurface(sampler, {-0.8, 0, 0}, {1, 0, 0}, segment));
    const auto hit = marchToSurface(sampler, {-0.8, 0, 0}, {1.5, 0, 0}, segment);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point[0], 0.5, 1e-12);
}

// An FRep solid cut by its box: a ray entering the box inside the solid
// touches the face that closes it; an implicit surface (open box) does not.
TEST(RayMarch, ClosedBoxFaceIsASurfaceOpenBoxIsNot) {
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    const ImplicitField solid = fieldOf("1 - y^2 - z^2", box); // a bar along x
    FieldSampler s(solid);
    auto hit = marchToSurface(s, {-3, 0.2, 0}, {1, 0, 0});
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit->onBoxFace);
    EXPECT_NEAR(hit->point[0], -1, 1e-12);
    EXPECT_EQ(hit->normal, (Vec3{-1, 0, 0}));
    const ImplicitField surface = fieldOf("0.25 - y^2 - z^2", box, BoxBoundary::Open);
    FieldSampler o(surface);
    EXPECT_FALSE(marchToSurface(o, {-3, 0.2, 0}, {1, 0, 0})) << "runs inside the tube";
    hit = marchToSurface(o, {0, 0.2, 0}, {0, 1, 0}); // from inside the tube
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point[1], 0.5, 1e-12);
    EXPECT_LT(dot(hit->normal, {0, 1, 0}), -0.99) << "an open surface faces the ray's origin";
}

// Where f is undefined (sqrt of a negative) the march goes on; parameters
// and t come from the field.
TEST(RayMarch, UndefinedRegionsParametersAndTime) {
    ImplicitField field = fieldOf("param r = 0.5; sqrt(x + 0.2) * 0 + r + 0.1 * t - abs(x)");
    field.parameters = {{"r", 0.25}};
    field.t = 1;
    FieldSampler sampler(field);
    const auto hit = marchToSurface(sampler, {-3, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(hit);
    // Undefined for x < -0.2, where the solid's left face (-0.35) lies; the
    // first sign change the march sees is inside the defined region.
    EXPECT_NEAR(hit->point[0], 0.35, 1e-12);
}

TEST(RayMarch, DegenerateRaysFindNothingAndDoNotHang) {
    const ImplicitField field = fieldOf("1 - x^2 - y^2 - z^2");
    FieldSampler sampler(field);
    EXPECT_FALSE(marchToSurface(sampler, {0, 0, -3}, {0, 0, 0}));
    EXPECT_FALSE(marchToSurface(sampler, {NAN, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(marchToSurface(sampler, {1e300, 0, 0}, {-1, 0, 0}));
    // Grazing the sphere along its tangent plane: found or not, it ends.
    (void)marchToSurface(sampler, {-3, 1, 0}, {1, 0, 0});
    EXPECT_LT(sampler.counts().points, 5'000'000u);
}

// A sampler narrowed to a box runs the tape simplified for it
// (formula/tape_simplify.h) and answers as the full tape does, bit for bit;
// widened, the full tape again. A chain of spheres: each box near one of
// them decides the union differently, more patterns than the sampler keeps.
TEST(FieldSampler, NarrowedToABoxItAnswersAsTheFullTapeDoes) {
    std::string chain = "sphere(-4, 0, 0, 0.6)";
    for (int k = -3; k <= 4; ++k)
        chain = "(" + chain + ") | sphere(" + std::to_string(k) + ", 0, 0, 0.6)";
    const ImplicitField field = fieldOf(chain.c_str(), {{-5, -1, -1}, {5, 1, 1}});
    FieldSampler wide(field), narrowed(field);
    const std::size_t full = narrowed.instructions();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::size_t fewest = full;
    for (int round = 0; round < 3; ++round)
        for (int b = 0; b < 100; ++b) { // 100 boxes along the chain, again and again
            const Vec3 lo{-5 + 0.1 * b, -0.5 + 0.01 * round, -0.3}, hi{lo[0] + 0.1, 0.5, 0.3};
            const Narrowing scope(narrowed, lo, hi);
            fewest = std::min(fewest, narrowed.instructions());
            std::vector<double> xs, ys, zs;
            std::vector<Vec3> points;
            for (int s = 0; s < 12; ++s) {
                points.push_back({lo[0] + u(rng) * (hi[0] - lo[0]),
                                  lo[1] + u(rng) * (hi[1] - lo[1]),
                                  lo[2] + u(rng) * (hi[2] - lo[2])});
                xs.push_back(points.back()[0]);
                ys.push_back(points.back()[1]);
                zs.push_back(points.back()[2]);
            }
            std::vector<double> a(points.size()), c(points.size());
            wide.values(xs.data(), ys.data(), zs.data(), xs.size(), a.data());
            narrowed.values(xs.data(), ys.data(), zs.data(), xs.size(), c.data());
            std::vector<fl::formula::Dual> g(points.size()), h(points.size());
            wide.gradients(points.data(), points.size(), g.data());
            narrowed.gradients(points.data(), points.size(), h.data());
            for (std::size_t i = 0; i < points.size(); ++i) {
                ASSERT_EQ(a[i], c[i]) << b;
                ASSERT_EQ(wide.value(points[i]), narrowed.value(points[i]));
                ASSERT_EQ(g[i].v, h[i].v);
                ASSERT_EQ(g[i].d, h[i].d);
                ASSERT_EQ(wide.gradient(points[i]).d, narrowed.gradient(points[i]).d);
            }
            const Vec3 mid{(lo[0] + hi[0]) / 2, 0, 0};
            const fl::formula::Interval wi = wide.interval(lo, mid),
                                        ni = narrowed.interval(lo, mid);
            ASSERT_EQ(wi.lo, ni.lo);
            ASSERT_EQ(wi.hi, ni.hi);
        }
    EXPECT_LT(fewest * 4, full) << "one sphere's box should need about a ninth of the chain";
    narrowed.widen();
    EXPECT_EQ(narrowed.instructions(), full);
    // Nested: a box inside a box simplifies the tape already simplified, to
    // the tape one narrowing to the inner box makes (known by what was
    // decided, so shared), and another sampler can run it (adopt).
    {
        const Narrowing outer(narrowed, {-1.2, -0.5, -0.5}, {1.2, 0.5, 0.5});
        const std::size_t middle = narrowed.instructions();
        EXPECT_LT(middle, full);
        const Narrowing inner(narrowed, {-0.2, -0.3, -0.3}, {0.2, 0.3, 0.3});
        EXPECT_LT(narrowed.instructions(), middle);
        FieldSampler other(field);
        const Narrowing direct(other, {-0.2, -0.3, -0.3}, {0.2, 0.3, 0.3});
        EXPECT_EQ(other.instructions(), narrowed.instructions());
        FieldSampler third(field);
        const Narrowing adopted(third, narrowed.tapeNow());
        EXPECT_EQ(third.instructions(), narrowed.instructions());
        for (double x = -0.2; x <= 0.2; x += 0.05) {
            const Vec3 p{x, 0.1 * x, -0.2 * x};
            EXPECT_EQ(third.value(p), wide.value(p));
            EXPECT_EQ(other.gradient(p).d, wide.gradient(p).d);
        }
    }
    EXPECT_EQ(narrowed.instructions(), full);
    EXPECT_EQ(narrowed.tapeNow(), nullptr);
    // A tape without min, max or select is never narrowed.
    FieldSampler smooth(fieldOf("1 - x^2 - y^2 - z^2", {{-1, -1, -1}, {1, 1, 1}}));
    const std::size_t before = smooth.counts().intervals;
    smooth.narrow({0, 0, 0}, {0.5, 0.5, 0.5});
    EXPECT_EQ(smooth.counts().intervals, before);
}
