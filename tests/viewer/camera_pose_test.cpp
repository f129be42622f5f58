// Where the camera stands, without drawing: X3D viewpoints (field of view
// over the smaller side) and a view that fits a scene without one.
#include "viewer/camera_pose.h"

#include <QMatrix4x4>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace fl::viewer;

namespace {

Bounds box(QVector3D lo, QVector3D hi) {
    Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

// Whether p projects inside the image of the pose.
bool inView(const CameraPose& pose, float aspect, QVector3D p) {
    QMatrix4x4 projection, view;
    projection.perspective(pose.verticalFieldOfView, aspect, pose.nearPlane, pose.farPlane);
    view.lookAt(pose.position, pose.viewCenter, pose.up);
    const QVector4D c = projection * view * QVector4D(p, 1);
    return c.w() > 0 && std::abs(c.x() / c.w()) <= 1 && std::abs(c.y() / c.w()) <= 1 &&
           c.z() / c.w() >= -1 && c.z() / c.w() <= 1;
}

} // namespace

TEST(CameraPose, AViewpointKeepsItsPlaceDirectionAndFieldOfView) {
    fl::mesh::ViewPoint v;
    v.position = {1, 2, 3};
    v.direction = {0, 0, -1};
    v.fieldOfView = std::numbers::pi / 3;
    const CameraPose wide = poseForViewpoint(v, box({-1, -1, -1}, {1, 1, 1}), 2.0f);
    EXPECT_EQ(wide.position, QVector3D(1, 2, 3));
    EXPECT_NEAR(wide.verticalFieldOfView, 60, 1e-4); // the height is the smaller side
    EXPECT_LT(wide.viewCenter.z(), 3);
    // Portrait: the width is smaller, so the vertical angle is wider.
    const CameraPose tall = poseForViewpoint(v, box({-1, -1, -1}, {1, 1, 1}), 0.5f);
    EXPECT_NEAR(std::tan(tall.verticalFieldOfView * std::numbers::pi / 360) * 0.5,
                std::tan(std::numbers::pi / 6), 1e-5);
}

TEST(CameraPose, FittingShowsTheWholeSceneWhateverItsSizeAndShape) {
    for (float scale : {1e-3f, 1.0f, 1e3f})
        for (float aspect : {0.5f, 1.0f, 2.0f}) {
            const Bounds b = box(QVector3D(-1, -2, -0.5f) * scale, QVector3D(3, 1, 0.5f) * scale);
            const CameraPose pose = poseToFit(b, aspect);
            for (int c = 0; c < 8; ++c) {
                const QVector3D corner(c & 1 ? b.hi.x() : b.lo.x(), c & 2 ? b.hi.y() : b.lo.y(),
                                       c & 4 ? b.hi.z() : b.lo.z());
                EXPECT_TRUE(inView(pose, aspect, corner)) << scale << " " << aspect << " " << c;
            }
        }
    // An empty scene still gets a usable camera.
    const CameraPose empty = poseToFit(Bounds{}, 1);
    EXPECT_GT(empty.farPlane, empty.nearPlane);
}
