#pragma once
// Moving the camera, as pure functions of a pose and the user's input, so
// every rule is testable without a window. Examine: orbit about the view
// centre, pan across the view, zoom towards the centre. Walk: first person,
// moving on the level of the eye and turning the head.
#include "camera_pose.h"

#include <QSize>

namespace fl::viewer {

// A drag of (dx, dy) pixels across a view of `viewport` turns the camera
// about the centre: a drag across the whole width is half a turn.
CameraPose orbit(const CameraPose& pose, float dx, float dy, QSize viewport);
// A drag moves the scene with the pointer (at the distance of the centre).
CameraPose pan(const CameraPose& pose, float dx, float dy, QSize viewport);
// Wheel steps (positive: closer); each step 15% of the distance; never past the centre.
CameraPose zoom(const CameraPose& pose, float steps);

// Walk `forward` and `right` (scene units) level with the ground (the up vector).
CameraPose walk(const CameraPose& pose, float forward, float right);
// Turn the head: yaw to the right and pitch up, in radians; pitch stops short of straight up/down.
CameraPose look(const CameraPose& pose, float yaw, float pitch);

} // namespace fl::viewer
