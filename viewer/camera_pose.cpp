#include "camera_pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::viewer {
namespace {

constexpr float kDegrees = float(180 / std::numbers::pi);

// X3D's field of view spans the smaller side; Qt3D's the height.
float verticalFov(double fieldOfView, float aspect) {
    fieldOfView = std::clamp(fieldOfView, 1e-3, std::numbers::pi - 1e-3);
    if (aspect >= 1) return float(fieldOfView) * kDegrees;
    return float(2 * std::atan(std::tan(fieldOfView / 2) / aspect)) * kDegrees;
}

// Near and far planes that hold the scene's bounding sphere as seen from `eye`.
void clipPlanes(CameraPose& pose, const Bounds& bounds) {
    const float r = bounds.empty() ? 1.0f : bounds.radius();
    const float d = bounds.empty() ? 10.0f : (bounds.centre() - pose.position).length();
    pose.farPlane = std::max(d + 2 * r, 1.0f);
    pose.nearPlane = std::max(pose.farPlane * 1e-4f, d - 2 * r);
    pose.nearPlane = std::min(pose.nearPlane, std::max(0.01f * r, pose.farPlane * 1e-4f));
}

QVector3D toQt(const std::array<double, 3>& v) {
    return QVector3D(float(v[0]), float(v[1]), float(v[2]));
}

} // namespace

CameraPose poseForViewpoint(const mesh::ViewPoint& v, const Bounds& bounds, float aspect) {
    CameraPose pose;
    pose.position = toQt(v.position);
    // Look at the centre of rotation when it lies ahead, else just ahead.
    const QVector3D direction = toQt(v.direction);
    const QVector3D toCentre = toQt(v.centerOfRotation) - pose.position;
    const float ahead = QVector3D::dotProduct(toCentre, direction);
    pose.viewCenter = pose.position + direction * std::max(ahead, 1.0f);
    pose.up = toQt(v.up);
    pose.verticalFieldOfView = verticalFov(v.fieldOfView, aspect);
    clipPlanes(pose, bounds);
    return pose;
}

CameraPose poseToFit(const Bounds& bounds, float aspect) {
    CameraPose pose;
    const QVector3D centre = bounds.empty() ? QVector3D() : bounds.centre();
    const float r = bounds.radius();
    const double fov = std::numbers::pi / 4;
    pose.verticalFieldOfView = verticalFov(fov, aspect);
    // The bounding sphere fits the smaller side, with a little margin.
    const float distance = float(1.1 * r / std::sin(fov / 2));
    pose.position = centre + QVector3D(0, 0, distance);
    pose.viewCenter = centre;
    clipPlanes(pose, bounds);
    return pose;
}

} // namespace fl::viewer
