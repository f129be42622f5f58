// The Bloor–Wilson patch: it satisfies its PDE, its derivatives are its
// derivatives, the paper's boundary-curve solve interpolates the curves, and
// the least-squares fit recovers a patch from its own points.
#include "pde/patch_solve.h"
#include "pde/pde_mesh.h"
#include "pde/pde_patch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace fl::pde;

namespace {

Patch randomPatch(std::size_t radii, double a, unsigned seed, bool pointAtStart = false) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1, 1);
    Patch p;
    p.a = a;
    p.setRadii(radii);
    auto fill = [&](Mode& m, double scale) {
        for (Vec3& c : m)
            for (double& x : c)
                x = scale * d(rng);
    };
    fill(p.spine, 1);
    for (std::size_t k = 0; k < radii; ++k) {
        fill(p.cosines[k], 1.0 / double(k + 1));
        fill(p.sines[k], 1.0 / double(k + 1));
        if (pointAtStart) {
            // An(0) = c1 e^{-an} + c3 = 0: the u = 0 ring is one point.
            const double g0 = std::exp(-a * double(k + 1));
            for (int c = 0; c < 3; ++c) {
                p.cosines[k][2][std::size_t(c)] = -g0 * p.cosines[k][0][std::size_t(c)];
                p.sines[k][2][std::size_t(c)] = -g0 * p.sines[k][0][std::size_t(c)];
            }
        }
    }
    return p;
}

double distance(const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

double largestDifference(const Patch& a, const Patch& b) {
    double worst = 0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j < 24; ++j) {
            const double u = i / 20.0, v = 2 * std::numbers::pi * j / 24;
            worst = std::max(worst, distance(position(a, u, v), position(b, u, v)));
        }
    return worst;
}

} // namespace

TEST(PdePatch, TheAnalyticSolutionSatisfiesThePde) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const Patch p = randomPatch(3, 1.0, seed);
        for (double u : {0.2, 0.5, 0.8})
            for (double v : {0.3, 2.0, 4.5}) {
                const Vec3 r = residual(p, u, v, 2e-3);
                EXPECT_LT(std::hypot(r[0], r[1], r[2]), 0.05) << "seed " << seed;
            }
    }
    // The same surface under another a's operator is no solution: the check can fail.
    const Patch p = randomPatch(3, 1.0, 7);
    const Vec3 r = residual(p, 0.5, 1.0, 2e-3, 2.0);
    EXPECT_GT(std::hypot(r[0], r[1], r[2]), 1.0);
}

TEST(PdePatch, DerivativesMatchFiniteDifferences) {
    const Patch p = randomPatch(4, 1.5, 11);
    const double h = 1e-6;
    for (double u : {0.1, 0.45, 0.9})
        for (double v : {0.0, 1.3, 5.9}) {
            const Point x = evaluate(p, u, v);
            const Vec3 up = position(p, u + h, v), um = position(p, u - h, v);
            const Vec3 vp = position(p, u, v + h), vm = position(p, u, v - h);
            for (int c = 0; c < 3; ++c) {
                const auto k = std::size_t(c);
                EXPECT_NEAR(x.du[k], (up[k] - um[k]) / (2 * h), 1e-6);
                EXPECT_NEAR(x.dv[k], (vp[k] - vm[k]) / (2 * h), 1e-6);
            }
        }
    for (int n = 0; n <= 5; ++n)
        for (double u : {0.0, 0.3, 1.0}) {
            const Basis b = basis(n, 1.2, u), bp = basis(n, 1.2, u + h), bm = basis(n, 1.2, u - h);
            for (std::size_t i = 0; i < 4; ++i) {
                EXPECT_NEAR(b.du[i], (bp.value[i] - bm.value[i]) / (2 * h), 1e-6);
                EXPECT_NEAR(b.du2[i], (bp.du[i] - bm.du[i]) / (2 * h), 1e-5);
                EXPECT_LE(std::abs(b.value[i]), 1.0); // the scaled basis stays bounded
            }
        }
}

TEST(PdePatch, TheBoundaryCurveSolveInterpolatesTheCurves) {
    const std::size_t radii = 3;
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const Patch truth = randomPatch(radii, 1.0, seed);
        BoundaryCurves c;
        c.u1 = 0.3;
        c.u2 = 0.7;
        const std::array<double, 4> at{0, c.u1, c.u2, 1};
        const int m = 16;
        for (std::size_t k = 0; k < 4; ++k)
            for (int j = 0; j < m; ++j)
                c.curves[k].push_back(position(truth, at[k], 2 * std::numbers::pi * j / m));
        std::string why;
        const auto solved = fromBoundaryCurves(c, radii, 1.0, &why);
        ASSERT_TRUE(solved) << why;
        for (std::size_t k = 0; k < 4; ++k)
            for (int j = 0; j < m; ++j)
                EXPECT_LT(distance(position(*solved, at[k], 2 * std::numbers::pi * j / m),
                                   c.curves[k][std::size_t(j)]),
                          1e-9);
        // Band-limited curves fix the whole patch.
        EXPECT_LT(largestDifference(*solved, truth), 1e-8);
    }
}

TEST(PdePatch, ACapsDegenerateStartCurveStaysAPoint) {
    // C0 a point (the paper's Fig. 8), C1..C3 circles: a dome.
    BoundaryCurves c;
    const int m = 24;
    for (int j = 0; j < m; ++j) {
        const double v = 2 * std::numbers::pi * j / m;
        c.curves[0].push_back({0, 0, 1});
        for (std::size_t k = 1; k < 4; ++k) {
            const double r = std::sin(double(k) / 3 * std::numbers::pi / 2);
            const double z = std::cos(double(k) / 3 * std::numbers::pi / 2);
            c.curves[k].push_back({r * std::cos(v), r * std::sin(v), z});
        }
    }
    std::string why;
    const auto p = fromBoundaryCurves(c, 2, 1.0, &why);
    ASSERT_TRUE(p) << why;
    for (int j = 0; j < 10; ++j)
        EXPECT_LT(distance(position(*p, 0, j * 0.6), {0, 0, 1}), 1e-12);
    Model dome;
    dome.lo = {-1, -1, 0};
    dome.hi = {1, 1, 1};
    dome.patches = {*p};
    const fl::mesh::Mesh mesh = meshModel(dome, {8, 16});
    // The start ring is one vertex: 16 fewer triangles than the full grid's 8 x 16 x 2.
    EXPECT_EQ(mesh.triangleCount(), std::size_t(8 * 16 * 2 - 16));
    EXPECT_EQ(mesh.vertexCount(), std::size_t(8 * 16 + 1));
    for (const auto& n : mesh.normals)
        EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-5);
}

TEST(PdePatch, TheBoundaryCurveSolveRefusesWhatCannotFixIt) {
    BoundaryCurves c;
    for (auto& curve : c.curves)
        curve.assign(4, Vec3{0, 0, 0});
    std::string why;
    EXPECT_FALSE(fromBoundaryCurves(c, 3, 1.0, &why)); // 4 points cannot fix 3 radii
    EXPECT_NE(why.find("at least 7"), std::string::npos) << why;
    c.curves[2].push_back({0, 0, 0});
    EXPECT_FALSE(fromBoundaryCurves(c, 1, 1.0, &why));
    for (auto& curve : c.curves)
        curve.assign(8, Vec3{0, NAN, 0});
    EXPECT_FALSE(fromBoundaryCurves(c, 1, 1.0, &why));
    for (auto& curve : c.curves)
        curve.assign(8, Vec3{0, 0, 0});
    c.u1 = 0.8;
    c.u2 = 0.2;
    EXPECT_FALSE(fromBoundaryCurves(c, 1, 1.0, &why));
}

TEST(PdePatch, TheLeastSquaresFitRecoversAPatchFromItsPoints) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(0, 1);
    for (bool cap : {false, true}) {
        const Patch truth = randomPatch(4, 1.0, 21, cap);
        std::vector<Sample> samples;
        for (int i = 0; i < 3000; ++i) {
            const double u = d(rng), v = 2 * std::numbers::pi * d(rng);
            samples.push_back({u, v, position(truth, u, v), 1});
        }
        FitOptions o;
        o.radii = 4;
        o.pointAtStart = cap;
        o.ridge = 0;
        std::string why;
        const auto fit = fitToPoints(samples, o, &why);
        ASSERT_TRUE(fit) << why;
        EXPECT_LT(largestDifference(*fit, truth), 1e-6) << (cap ? "cap" : "tube");
    }
    // Too few points for the coefficients: refused with the counts.
    std::string why;
    EXPECT_FALSE(fitToPoints(std::vector<Sample>(10), FitOptions{}, &why));
    EXPECT_NE(why.find("36 coefficients"), std::string::npos) << why;
}
