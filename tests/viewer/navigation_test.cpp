// Camera moves as the user expects: orbiting keeps the distance and comes
// back after a full turn, zooming never passes the centre, panning keeps the
// direction, walking keeps the eye level, looking stops short of the zenith.
#include "viewer/navigation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fl::viewer;

namespace {

CameraPose front() {
    CameraPose p;
    p.position = {0, 1, 10};
    p.viewCenter = {0, 1, 0};
    p.up = {0, 1, 0};
    return p;
}

void expectNear(const QVector3D& a, const QVector3D& b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x(), b.x(), tolerance);
    EXPECT_NEAR(a.y(), b.y(), tolerance);
    EXPECT_NEAR(a.z(), b.z(), tolerance);
}

} // namespace

TEST(Navigation, OrbitKeepsTheDistanceAndTwoHalfTurnsComeBack) {
    const QSize view(800, 600);
    CameraPose p = front();
    p = orbit(p, 400, 0, view); // a quarter turn: half the width
    EXPECT_NEAR((p.position - p.viewCenter).length(), 10, 1e-4);
    expectNear(p.position, {-10, 1, 0});
    p = orbit(orbit(orbit(p, 400, 0, view), 400, 0, view), 400, 0, view);
    expectNear(p.position, front().position);
    // Up and down too, and the centre never moves.
    const CameraPose tilted = orbit(front(), 0, 200, view);
    EXPECT_NEAR((tilted.position - tilted.viewCenter).length(), 10, 1e-4);
    EXPECT_EQ(tilted.viewCenter, front().viewCenter);
    EXPECT_GT(tilted.position.y(), 1); // dragging down looks from above
}

TEST(Navigation, ZoomApproachesButNeverPassesTheCentre) {
    CameraPose p = zoom(front(), 1);
    EXPECT_NEAR((p.position - p.viewCenter).length(), 8.5, 1e-4);
    p = zoom(p, 500);
    EXPECT_GT(p.position.z(), 0);
    EXPECT_EQ(zoom(front(), -1).viewCenter, front().viewCenter);
}

TEST(Navigation, PanMovesEyeAndCentreTogether) {
    const CameraPose p = pan(front(), 100, 0, QSize(800, 600));
    EXPECT_LT(p.position.x(), 0); // the scene follows the pointer to the right
    expectNear(p.viewCenter - p.position, front().viewCenter - front().position);
}

TEST(Navigation, WalkingKeepsTheEyeLevelAndLookingStopsShortOfTheZenith) {
    CameraPose p = front();
    p.viewCenter = {0, 3, 0}; // looking a little up
    const CameraPose walked = walk(p, 2, 0);
    EXPECT_NEAR(walked.position.y(), 1, 1e-5);
    EXPECT_NEAR(walked.position.z(), 8, 1e-5);
    const CameraPose sidestep = walk(front(), 0, 1);
    EXPECT_NEAR(sidestep.position.x(), 1, 1e-5);
    const CameraPose up = look(front(), 0, 10); // far past straight up
    const QVector3D dir = (up.viewCenter - up.position).normalized();
    EXPECT_LT(dir.y(), 1.0f);
    EXPECT_GT(dir.y(), 0.99f);
    const CameraPose right = look(front(), 1.5707963f, 0);
    expectNear((right.viewCenter - right.position).normalized(), {1, 0, 0});
}
