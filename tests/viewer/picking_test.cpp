// Picking finds the point on the function itself (to rounding, where the
// mesh's chords are a thousandth off), through transforms, and on standard
// shapes by their triangles; a ray that misses finds nothing.
#include "viewer/picking.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <iostream>
#include <limits>

using namespace fl;

namespace {

struct Picked {
    std::unique_ptr<scene::Scene> scene;
    mesh::SceneMeshes meshes;
};

Picked load(const std::string& body) {
    auto r = scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "pick.x3dv");
    EXPECT_TRUE(r.ok());
    Picked p;
    p.scene = std::move(r.scene);
    mesh::SceneMeshOptions o;
    o.placeInScene = false;
    p.meshes = mesh::meshScene(*p.scene, o);
    return p;
}

} // namespace

TEST(Picking, TheFunctionItselfIsHitNotItsMesh) {
    const Picked s = load(R"x(Transform { translation 1 0 0 children
        FShape { geometry FGeometry { definition "0.64 - x*x - y*y - z*z" resolution 12 } } })x");
    const viewer::Ray ray{{1.1f, 0.2f, 5}, QVector3D(0, 0, -1)};
    const auto p = viewer::pick(s.meshes, ray);
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->onFunction);
    const double x = p->point[0] - 1, y = p->point[1], z = p->point[2];
    EXPECT_NEAR(std::sqrt(x * x + y * y + z * z), 0.8, 1e-6); // a coarse mesh is ~1e-2 off
    EXPECT_NEAR(p->point[0], 1.1, 1e-6);
    EXPECT_GT(p->normal[2], 0.9); // outward, towards the eye
    EXPECT_NEAR(p->distance, 5 - z, 1e-6);
}

TEST(Picking, StandardShapesByTheirTrianglesAndTheNearestWins) {
    const Picked s = load(R"x(
        Transform { translation 0 0 2 children Shape { geometry Box { size 1 1 1 } } }
        FShape { geometry FGeometry { definition "0.25 - x*x - y*y - z*z" } })x");
    const auto p = viewer::pick(s.meshes, {{0.1f, 0.1f, 10}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->onFunction);
    EXPECT_NEAR(p->point[2], 2.5, 1e-6); // the box's front face, before the ball
    EXPECT_NEAR(p->normal[2], 1, 1e-6);
    EXPECT_FALSE(viewer::pick(s.meshes, {{5, 5, 10}, QVector3D(0, 0, -1)}));
}

TEST(Picking, APixelsRayGoesThroughWhatItShows) {
    viewer::CameraPose pose;
    pose.position = {0, 0, 10};
    const viewer::Ray centre = viewer::rayThroughPixel(pose, QSize(800, 600), QPointF(400, 300));
    EXPECT_NEAR(centre.direction.z(), -1, 1e-5);
    const viewer::Ray right = viewer::rayThroughPixel(pose, QSize(800, 600), QPointF(800, 300));
    EXPECT_GT(right.direction.x(), 0.3); // the right edge of a 45 degree, 4:3 view
    const viewer::Ray top = viewer::rayThroughPixel(pose, QSize(800, 600), QPointF(400, 0));
    EXPECT_NEAR(top.direction.y() / -top.direction.z(), std::tan(22.5 * M_PI / 180), 1e-4);
}

TEST(Picking, RaysFromInfinityOrNowhereFindNothingAndReturn) {
    const Picked s =
        load(R"x(FShape { geometry FGeometry { definition "0.25 - x*x - y*y - z*z" } })x");
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(viewer::pick(s.meshes, {{inf, 0, 0}, QVector3D(-1, 0, 0)}));
    EXPECT_FALSE(viewer::pick(s.meshes, {{0, 0, 5}, QVector3D(nan, 0, -1)}));
    // Very far away, the coordinates' last digit (~1e14 at 1e30) is larger
    // than the scene: nothing can be placed on it, so nothing is picked (a
    // triangle test used to return the ball's centre with a backward normal).
    EXPECT_FALSE(viewer::pick(s.meshes, {{1e30f, 0, 0}, QVector3D(-1, 0, 0)}));
    // Far, but not too far to tell: the ball's near side, facing the eye.
    const auto distant = viewer::pick(s.meshes, {{1e9f, 0, 0}, QVector3D(-1, 0, 0)});
    ASSERT_TRUE(distant);
    EXPECT_NEAR(distant->point[0], 0.5, 1e-4);
    EXPECT_GT(distant->normal[0], 0.9);
}

TEST(Picking, AnImplicitSurfacesNormalFacesTheEyeFromEitherSide) {
    // The paper's sphere, negative inside: -grad f points into it, but an
    // implicit surface has no outside, so the picked normal faces the eye.
    const Picked s = load(R"x(COMPONENT FunctionLab:1
        FShape { geometry FGeometry { type "implicit" definition "x^2 + y^2 + z^2 - 0.5" } })x");
    const auto front = viewer::pick(s.meshes, {{0.1f, 0.1f, 5}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(front);
    EXPECT_TRUE(front->onFunction);
    EXPECT_GT(front->normal[2], 0.9);
    const auto back = viewer::pick(s.meshes, {{0.1f, 0.1f, -5}, QVector3D(0, 0, 1)});
    ASSERT_TRUE(back);
    EXPECT_LT(back->normal[2], -0.9);
    // An explicit solid keeps its outward normal: here, into the cavity.
    const Picked solid = load(R"x(COMPONENT FunctionLab:1
        FShape { geometry FGeometry { type "explicit" definition "x^2 + y^2 + z^2 - 0.5" } })x");
    const auto box = viewer::pick(solid.meshes, {{0.1f, 0.1f, 5}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(box);
    EXPECT_NEAR(box->point[2], 1, 1e-6); // the box face closing the solid
    EXPECT_GT(box->normal[2], 0.9);
}

// A shape combined by an FTransform has no FGeometry of its own: it is
// picked on the combined field (the union's farther ball is hidden by the
// nearer one).
TEST(Picking, CombinedShapesArePickedOnTheirField) {
    const Picked s = load(R"x(FTransform { operation "union" children [
        FShape { geometry FGeometry { type "explicit" definition "0.25 - (x-0.3)^2 - y^2 - z^2"
                                      resolution 10 } }
        FShape { geometry FGeometry { type "explicit" definition "0.25 - (x+0.3)^2 - y^2 - z^2"
                                      resolution 10 } } ] })x");
    const auto p = viewer::pick(s.meshes, {{0.7f, 0, 5}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->onFunction);
    const double x = p->point[0] - 0.3;
    EXPECT_NEAR(std::sqrt(x * x + p->point[2] * p->point[2]), 0.5, 1e-9);
}

// A displacement texture moves the surface: the pick is on the displaced
// surface, which the mesh shows, not on the bare definition.
TEST(Picking, DisplacedSurfacesArePickedWhereTheyAreShown) {
    const Picked s = load(R"x(FShape {
        geometry FGeometry { type "explicit" definition "0.25 - x*x - y*y - z*z" resolution 16 }
        appearance FAppearance { texture FTexture3D { definition "0.1" } } })x");
    const auto p = viewer::pick(s.meshes, {{0, 0, 5}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->onFunction);
    EXPECT_NEAR(p->point[2], std::sqrt(0.35), 1e-9); // 0.35 - z^2 = 0
}

// Issue 29 §4: what is not drawn (transparency 1) catches no click, function
// shape or standard; a shape partly seen is hit only where it is seen.
TEST(Picking, WhatIsNotDrawnIsNotHit) {
    const Picked s = load(R"x(
        DEF WIND FShape { geometry FGeometry { definition "4 - x*x - y*y - z*z" resolution 12
                                                 domainMin -3 -3 -3 domainMax 3 3 3 }
                          appearance Appearance { material Material { transparency 1 } } }
        DEF GLASS Shape { geometry Box { size 3 3 3 }
                          appearance Appearance { material Material { transparency 1 } } }
        DEF BLADE FShape { geometry FGeometry { definition "0.25 - x*x - y*y - z*z" resolution 12 } })x");
    ASSERT_EQ(s.meshes.shapes.size(), 3u);
    EXPECT_FALSE(mesh::isDrawn(s.meshes.shapes[0]));
    EXPECT_FALSE(mesh::isDrawn(s.meshes.shapes[1]));
    EXPECT_TRUE(mesh::isDrawn(s.meshes.shapes[2]));
    const auto p = viewer::pick(s.meshes, {{0, 0, 10}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(p);
    EXPECT_EQ(p->shapeIndex, 2u) << p->shape; // through the wind and the glass
    EXPECT_NEAR(p->point[2], 0.5, 1e-6);
    // Nearly transparent is still drawn: it is hit.
    const Picked faint = load(R"x(Shape { geometry Box { size 3 3 3 }
        appearance Appearance { material Material { transparency 0.95 } } })x");
    const auto q = viewer::pick(faint.meshes, {{0, 0, 10}, QVector3D(0, 0, -1)});
    ASSERT_TRUE(q);
    EXPECT_NEAR(q->point[2], 1.5, 1e-6);
}
