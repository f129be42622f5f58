#pragma once
// Where the camera stands: from one of the scene's Viewpoints (X3D: its field
// of view covers the smaller side of the image), or placed to show the whole
// scene when it has none. Plain math, no rendering.
#include "mesh/scene_view.h"
#include "render_scene.h" // Bounds

#include <QVector3D>

namespace fl::viewer {

struct CameraPose {
    QVector3D position{0, 0, 10};
    QVector3D viewCenter{0, 0, 0};
    QVector3D up{0, 1, 0};
    float verticalFieldOfView = 45; // degrees, as Qt3D's lens wants it
    float nearPlane = 0.1f, farPlane = 1000;
};

// `aspect`: width / height of the image.
CameraPose poseForViewpoint(const mesh::ViewPoint& viewpoint, const Bounds& bounds, float aspect);
// Looking along -z at the scene's centre, far enough back to see all of it.
CameraPose poseToFit(const Bounds& bounds, float aspect);

} // namespace fl::viewer
