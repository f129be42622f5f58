#pragma once
// The point of a scene under the cursor. On implicit, explicit and combined
// function shapes it is found on the function itself — the field each shape
// was meshed from, marched along the ray by field/ray_march.h (the same march
// haptic contact and the grader use), so the point is on f = 0 to rounding,
// not on the mesh's chords — and elsewhere on the nearest triangle.
#include "camera_pose.h"
#include "mesh/scene_meshing.h"
#include "scene/scene.h"

#include <QPointF>
#include <QSize>
#include <QVector3D>

#include <optional>
#include <string>
#include <vector>

namespace fl::viewer {

struct Ray {
    QVector3D origin;
    QVector3D direction; // unit
};

// The ray from the eye through a pixel (0, 0 top left) of a view of `viewport`.
Ray rayThroughPixel(const CameraPose& pose, QSize viewport, QPointF pixel);

struct Pick {
    std::array<double, 3> point{};  // in the scene
    std::array<double, 3> normal{}; // unit, outward (an implicit surface: towards the eye)
    double distance = 0;            // along the ray
    std::string shape;              // the ShapeMesh's name
    std::size_t shapeIndex = 0;     // which of the SceneMeshes' shapes
    bool onFunction = false;        // found on f = 0 (else on a triangle)
    // The TouchSensors a click here triggers (the ShapeMesh's).
    std::vector<const scene::Node*> touchSensors;
};

std::optional<Pick> pick(const mesh::SceneMeshes& meshes, const Ray& ray);

} // namespace fl::viewer
