// Filling 2D contours (planar_fill.h): the area the fill rule says, every
// triangle counter-clockwise and inside, no T-junctions, grid-sized cells.
#include "mesh/planar_fill.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>

using namespace fl::mesh;

namespace {

double triangleArea2(const PlanarFill& f, const Triangle& t) {
    const Point2& a = f.points[t[0]];
    const Point2& b = f.points[t[1]];
    const Point2& c = f.points[t[2]];
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}

double filledArea(const PlanarFill& f) {
    double a = 0;
    for (const Triangle& t : f.triangles)
        a += triangleArea2(f, t) / 2;
    return a;
}

// Winding number of a point: the reference the fill is checked against.
int windingAt(const std::vector<Contour2>& contours, Point2 p) {
    int w = 0;
    for (const Contour2& c : contours)
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Point2& a = c[i];
            const Point2& b = c[(i + 1) % c.size()];
            const double cross = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
            if (a[1] <= p[1] && b[1] > p[1] && cross > 0) ++w;
            if (a[1] > p[1] && b[1] <= p[1] && cross < 0) --w;
        }
    return w;
}

Contour2 square(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Contour2 reversed(Contour2 c) {
    std::reverse(c.begin(), c.end());
    return c;
}

void expectCounterClockwise(const PlanarFill& f) {
    for (const Triangle& t : f.triangles)
        EXPECT_GT(triangleArea2(f, t), 0);
}

// Interior edges are used twice in opposite directions; an edge used once
// is on the boundary. A T-junction shows as a once-used edge whose middle
// holds another point: the summed length of once-used edges then exceeds
// the outline's.
double boundaryLength(const PlanarFill& f) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const Triangle& t : f.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            auto back = uses.find({b, a});
            if (back != uses.end() && back->second > 0)
                --back->second;
            else
                ++uses[{a, b}];
        }
    double length = 0;
    for (const auto& [edge, count] : uses)
        if (count > 0)
            length += count * std::hypot(f.points[edge.second][0] - f.points[edge.first][0],
                                         f.points[edge.second][1] - f.points[edge.first][1]);
    return length;
}

} // namespace

TEST(PlanarFill, SquareFillsItsArea) {
    const PlanarFill f = fillContours({square(0, 0, 2, 1)}, FillRule::NonZero);
    EXPECT_NEAR(filledArea(f), 2.0, 1e-12);
    EXPECT_EQ(f.triangles.size(), 2u);
    expectCounterClockwise(f);
}

TEST(PlanarFill, ClockwiseContourFillsTheSameWay) {
    const PlanarFill f = fillContours({reversed(square(0, 0, 2, 1))}, FillRule::NonZero);
    EXPECT_NEAR(filledArea(f), 2.0, 1e-12);
    expectCounterClockwise(f);
}

TEST(PlanarFill, HoleIsLeftOutByBothRules) {
    const Contour2 outer = square(0, 0, 4, 4);
    const Contour2 hole = reversed(square(1, 1, 3, 3));
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        const PlanarFill f = fillContours({outer, hole}, rule);
        EXPECT_NEAR(filledArea(f), 16.0 - 4.0, 1e-12);
        expectCounterClockwise(f);
        EXPECT_NEAR(boundaryLength(f), 16.0 + 8.0, 1e-9) << "T-junction or gap";
    }
}

TEST(PlanarFill, OverlapsFollowTheRule) {
    // Two squares the same way round overlap in a 1x1 square.
    const std::vector<Contour2> two = {square(0, 0, 2, 2), square(1, 1, 3, 3)};
    EXPECT_NEAR(filledArea(fillContours(two, FillRule::NonZero)), 7.0, 1e-12);
    EXPECT_NEAR(filledArea(fillContours(two, FillRule::EvenOdd)), 6.0, 1e-12);
}

TEST(PlanarFill, SelfIntersectingBowTieIsSplitAtItsCrossing) {
    // Two triangles meeting at (1, 1), each of area 1.
    const Contour2 bowTie = {{0, 0}, {2, 2}, {2, 0}, {0, 2}};
    for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
        const PlanarFill f = fillContours({bowTie}, rule);
        EXPECT_NEAR(filledArea(f), 2.0, 1e-12);
        expectCounterClockwise(f);
    }
}

TEST(PlanarFill, PentagramCentreDependsOnTheRule) {
    Contour2 star;
    for (int k = 0; k < 5; ++k) {
        const double a = std::numbers::pi / 2 + k * 4 * std::numbers::pi / 5;
        star.push_back({std::cos(a), std::sin(a)});
    }
    const double nonZero = filledArea(fillContours({star}, FillRule::NonZero));
    const double evenOdd = filledArea(fillContours({star}, FillRule::EvenOdd));
    // The centre pentagon (winding 2) is in for non-zero, out for even-odd.
    const double inner = 0.3819660112501051; // circumradius of the inner pentagon
    const double pentagon = 2.5 * inner * inner * std::sin(2 * std::numbers::pi / 5);
    EXPECT_NEAR(nonZero - evenOdd, pentagon, 1e-9);
}

TEST(PlanarFill, RandomStarPolygonsMatchTheirAreaAndWinding) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> radius(0.2, 1.0);
    for (int shape = 0; shape < 50; ++shape) {
        const int n = 3 + shape % 40;
        Contour2 c;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * std::numbers::pi * k / n;
            const double r = radius(rng);
            c.push_back({r * std::cos(a), r * std::sin(a)});
        }
        const PlanarFill f = fillContours({c}, FillRule::NonZero);
        EXPECT_NEAR(filledArea(f), signedArea2(c) / 2, 1e-9) << "shape " << shape;
        expectCounterClockwise(f);
        double perimeter = 0;
        for (std::size_t i = 0; i < c.size(); ++i)
            perimeter += std::hypot(c[(i + 1) % n][0] - c[i][0], c[(i + 1) % n][1] - c[i][1]);
        EXPECT_NEAR(boundaryLength(f), perimeter, 1e-9) << "shape " << shape;
        for (const Triangle& t : f.triangles) {
            const Point2 centre = {(f.points[t[0]][0] + f.points[t[1]][0] + f.points[t[2]][0]) / 3,
                                   (f.points[t[0]][1] + f.points[t[1]][1] + f.points[t[2]][1]) / 3};
            EXPECT_NE(windingAt({c}, centre), 0) << "shape " << shape;
        }
    }
}

TEST(PlanarFill, RandomSelfCrossingPolygonsMatchTheWindingRule) {
    // Random points joined in order cross themselves many times; the area
    // the fill gives must match a fine point sampling of the winding rule.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(0, 1);
    for (int shape = 0; shape < 12; ++shape) {
        Contour2 c;
        for (int k = 0; k < 8; ++k)
            c.push_back({coord(rng), coord(rng)});
        for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
            const PlanarFill f = fillContours({c}, rule);
            expectCounterClockwise(f);
            const int n = 300;
            int in = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const int w = windingAt({c}, {(i + 0.5) / n, (j + 0.5) / n});
                    in += rule == FillRule::EvenOdd ? (w % 2 != 0) : (w != 0);
                }
            EXPECT_NEAR(filledArea(f), double(in) / (n * n), 0.01) << "shape " << shape;
        }
    }
}

TEST(PlanarFill, GridBoundsTheCells) {
    FillGrid grid;
    for (int k = 0; k <= 10; ++k) {
        grid.xs.push_back(k * 0.1);
        grid.ys.push_back(k * 0.1);
    }
    Contour2 disc;
    for (int k = 0; k < 64; ++k) {
        const double a = 2 * std::numbers::pi * k / 64;
        disc.push_back({0.5 + 0.45 * std::cos(a), 0.5 + 0.45 * std::sin(a)});
    }
    const PlanarFill f = fillContours({disc}, FillRule::NonZero, grid);
    EXPECT_NEAR(filledArea(f), signedArea2(disc) / 2, 1e-9);
    expectCounterClockwise(f);
    for (const Triangle& t : f.triangles)
        for (int k = 0; k < 3; ++k) {
            const Point2& a = f.points[t[k]];
            const Point2& b = f.points[t[(k + 1) % 3]];
            EXPECT_LE(std::abs(a[0] - b[0]), 0.1 + 1e-12);
            EXPECT_LE(std::abs(a[1] - b[1]), 0.1 + 1e-12);
        }
    // A grid cell inside the disc is filled by its own corners.
    bool hasGridCorner = false;
    for (const Point2& p : f.points)
        hasGridCorner |= std::abs(p[0] - 0.5) < 1e-12 && std::abs(p[1] - 0.5) < 1e-12;
    EXPECT_TRUE(hasGridCorner);
}

TEST(PlanarFill, BadInputGivesNothingOrIsSkipped) {
    EXPECT_TRUE(fillContours({}, FillRule::NonZero).triangles.empty());
    EXPECT_TRUE(fillContours({{{0, 0}, {1, 1}}}, FillRule::NonZero).triangles.empty());
    EXPECT_TRUE(fillContours({{{0, 0}, {1, 0}, {2, 0}}}, FillRule::NonZero).triangles.empty());
    const double nan = std::nan("");
    const PlanarFill f =
        fillContours({{{0, 0}, {1, 0}, {nan, 5}, {1, 1}, {0, 1}}}, FillRule::NonZero);
    EXPECT_NEAR(filledArea(f), 1.0, 1e-12);
}

TEST(PlanarFill, HugeCoordinatesAreIgnoredAndComplexOutlinesRefused) {
    // Beyond 1e150 a slope overflows: such points are left out.
    const PlanarFill huge =
        fillContours({{{-1e308, -1e308}, {1e308, 1e308}, {-1e308, 1e308}, {0, 0}, {1, 0}, {1, 1}}},
                     FillRule::EvenOdd);
    for (const Point2& p : huge.points)
        EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]));
    // A zig-zag crossing itself millions of times: refused, quickly.
    Contour2 zigzag;
    for (int k = 0; k < 30000; ++k)
        zigzag.push_back({k % 2 ? 1.0 : 0.0, k * 1e-4 + (k % 2 ? 0.5 : 0)});
    const PlanarFill refused = fillContours({zigzag}, FillRule::EvenOdd);
    EXPECT_FALSE(refused.problem.empty());
    EXPECT_TRUE(refused.triangles.empty());
}
