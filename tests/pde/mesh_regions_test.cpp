// Cutting meshes into the regions PDE patches stand for, and laying a tube
// on (u, v): which regions are annuli, the bands of a sphere and of an open
// cylinder, and the annulus map's laws (u from 0 on one loop to 1 on the
// other, by length; v once round; every face counter-clockwise in (u, v)).
#include "pde/annulus_map.h"
#include "pde/mesh_regions.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace fl;
using namespace fl::pde;
using namespace fl::pde::test;

namespace {

Faces allFaces(const Mesh& m) {
    Faces f(m.triangles.size());
    std::iota(f.begin(), f.end(), 0u);
    return f;
}

} // namespace

TEST(PdeRegions, AnOpenCylinderIsAnAnnulusAndNeitherADiskNorASphereIs) {
    const Mesh tube = cylinder();
    const auto g = buildFaceGraph(tube, nullptr);
    ASSERT_TRUE(g);
    const auto loops = annulusBoundaries(*g, allFaces(tube));
    ASSERT_TRUE(loops);
    EXPECT_EQ((*loops)[0].size(), 96u);
    EXPECT_EQ((*loops)[1].size(), 96u);
    EXPECT_FALSE(diskBoundary(*g, allFaces(tube)));
    const Mesh ball = sphere(12, 24);
    const auto gb = buildFaceGraph(ball, nullptr);
    ASSERT_TRUE(gb);
    EXPECT_FALSE(annulusBoundaries(*gb, allFaces(ball))); // closed: no loop
    // A cap of it is a disk, not an annulus.
    Faces cap;
    for (std::uint32_t f = 0; f < ball.triangles.size(); ++f)
        if (gb->centroid[f][2] > 0.5) cap.push_back(f);
    EXPECT_TRUE(diskBoundary(*gb, cap));
    EXPECT_FALSE(annulusBoundaries(*gb, cap));
}

TEST(PdeRegions, ASpheresBandsAreTwoCapsAndTubesCutAlongItsRings) {
    const Mesh ball = sphere(24, 48);
    const auto g = buildFaceGraph(ball, nullptr);
    ASSERT_TRUE(g);
    const Bands ballBands(*g, allFaces(ball));
    for (std::size_t count : {2u, 3u, 4u, 6u}) {
        const std::vector<Faces> b = ballBands.cut(count);
        ASSERT_EQ(b.size(), count);
        std::size_t faces = 0;
        for (std::size_t i = 0; i < count; ++i) {
            faces += b[i].size();
            const bool end = i == 0 || i + 1 == count;
            EXPECT_EQ(bool(diskBoundary(*g, b[i])), end) << count << " " << i;
            EXPECT_EQ(bool(annulusBoundaries(*g, b[i])), !end) << count << " " << i;
            // A ring strip's two triangles go together: every loop is a ring
            // of the sphere (one z), 48 vertices long.
            const auto loops = annulusBoundaries(*g, b[i]);
            if (loops)
                for (const auto& loop : *loops) {
                    EXPECT_EQ(loop.size(), 48u);
                    for (std::uint32_t v : loop)
                        EXPECT_EQ(ball.positions[v][2], ball.positions[loop[0]][2]);
                }
        }
        EXPECT_EQ(faces, ball.triangles.size());
    }
    // An open cylinder's bands are all tubes.
    const Mesh tube = cylinder();
    const auto gt = buildFaceGraph(tube, nullptr);
    for (const Faces& b : Bands(*gt, allFaces(tube)).cut(3))
        EXPECT_TRUE(annulusBoundaries(*gt, b));
}

TEST(PdeRegions, TheAnnulusMapRunsUByLengthAndVOnceRoundWithFacesCounterClockwise) {
    const Mesh tube = cylinder(); // z from -1 to 1, radius 0.5, faces facing out
    const auto g = buildFaceGraph(tube, nullptr);
    const Faces all = allFaces(tube);
    const auto loops = annulusBoundaries(*g, all);
    ASSERT_TRUE(loops);
    const auto map = mapToAnnulus(*g, all, (*loops)[0], (*loops)[1]);
    ASSERT_TRUE(map);
    // u: 0 on the start loop, 1 on the end loop, by length between (the
    // cylinder's z, linearly).
    const double zStart = tube.positions[map->start[0]][2], zEnd = tube.positions[map->end[0]][2];
    ASSERT_NE(zStart, zEnd);
    for (const auto& [f, corners] : map->faces) {
        for (std::size_t k = 0; k < 3; ++k) {
            const double z = tube.positions[tube.triangles[f][k]][2];
            EXPECT_NEAR(corners[k][0], (z - zStart) / (zEnd - zStart), 0.02);
        }
        // Counter-clockwise in (u, v): the surface's Xu x Xv faces out as its faces do.
        const double area = (corners[1][0] - corners[0][0]) * (corners[2][1] - corners[0][1]) -
                            (corners[2][0] - corners[0][0]) * (corners[1][1] - corners[0][1]);
        EXPECT_GT(area, 0);
        // v changes by about a column's angle across a face: no face spans the cut.
        for (std::size_t k = 1; k < 3; ++k)
            EXPECT_LT(std::abs(corners[k][1] - corners[0][1]), 0.2);
    }
    // Each loop in the order v increases, once round: 2π in all.
    for (const auto* loop : {&map->start, &map->end}) {
        std::unordered_map<std::uint32_t, double> v;
        for (const auto& [f, corners] : map->faces)
            for (std::size_t k = 0; k < 3; ++k)
                v[tube.triangles[f][k]] = corners[k][1];
        double turned = 0;
        for (std::size_t i = 0; i < loop->size(); ++i) {
            double step = v[(*loop)[(i + 1) % loop->size()]] - v[(*loop)[i]];
            step -= 2 * kPi * std::round(step / (2 * kPi));
            EXPECT_GT(step, 0);
            turned += step;
        }
        EXPECT_NEAR(turned, 2 * kPi, 1e-9);
    }
}

TEST(PdeRegions, ByLengthTheParameterOfASpheresCapIsItsAngle) {
    // Faces of a cap of 60 degrees at u = tan(θ/2) / tan(30°) (the conformal
    // radius) come out at u = θ / 60°: LengthParameter undoes the crowding.
    const Mesh ball = sphere(48, 96);
    FaceParameters faces;
    const double top = kPi / 3;
    for (std::uint32_t f = 0; f < ball.triangles.size(); ++f) {
        std::array<std::array<double, 2>, 3> c{};
        bool in = true;
        for (std::size_t k = 0; k < 3; ++k) {
            const auto& p = ball.positions[ball.triangles[f][k]];
            const double theta = std::acos(std::clamp(double(p[2]), -1.0, 1.0));
            in = in && theta <= top + 1e-9;
            c[k] = {std::tan(theta / 2) / std::tan(top / 2),
                    std::atan2(double(p[1]), double(p[0]))};
        }
        for (std::size_t k = 1; k < 3; ++k)
            c[k][1] += 2 * kPi * std::round((c[0][1] - c[k][1]) / (2 * kPi));
        for (std::size_t k = 0; k < 3; ++k) // at the pole, v is the others'
            if (c[k][0] < 1e-12) c[k][1] = (c[(k + 1) % 3][1] + c[(k + 2) % 3][1]) / 2;
        if (in) faces[f] = c;
    }
    const LengthParameter byLength(ball, faces);
    EXPECT_EQ(byLength(0), 0);
    EXPECT_DOUBLE_EQ(byLength(1), 1);
    // Within 2 % (the faces go to slices of u by their centres, and a
    // face near the border spans several); the conformal radius is 3.5 % off
    // at θ = 0.5, so the check can fail.
    for (double theta = 0.1; theta < top; theta += 0.1) {
        const double conformal = std::tan(theta / 2) / std::tan(top / 2);
        EXPECT_NEAR(byLength(conformal), theta / top, 0.02) << theta;
    }
    EXPECT_GT(std::abs(std::tan(0.5 / 2) / std::tan(top / 2) - 0.5 / top), 0.03);
}
