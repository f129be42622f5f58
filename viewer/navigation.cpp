#include "navigation.h"

#include <QQuaternion>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::viewer {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

QVector3D rightOf(const CameraPose& p) {
    QVector3D r = QVector3D::crossProduct(p.viewCenter - p.position, p.up);
    return r.lengthSquared() > 0 ? r.normalized() : QVector3D(1, 0, 0);
}

// The up vector made square to the view direction.
QVector3D trueUp(const CameraPose& p) {
    const QVector3D forward = (p.viewCenter - p.position).normalized();
    QVector3D up = p.up - forward * QVector3D::dotProduct(p.up, forward);
    return up.lengthSquared() > 1e-12f ? up.normalized() : QVector3D(0, 1, 0);
}

} // namespace

CameraPose orbit(const CameraPose& pose, float dx, float dy, QSize viewport) {
    const float width = float(std::max(viewport.width(), 1));
    const float yaw = -dx / width * kPi, pitch = -dy / width * kPi;
    const QVector3D up = trueUp(pose);
    const QQuaternion turn = QQuaternion::fromAxisAndAngle(up, yaw * 180 / kPi) *
                             QQuaternion::fromAxisAndAngle(rightOf(pose), pitch * 180 / kPi);
    CameraPose out = pose;
    out.position = pose.viewCenter + turn.rotatedVector(pose.position - pose.viewCenter);
    out.up = turn.rotatedVector(up);
    return out;
}

CameraPose pan(const CameraPose& pose, float dx, float dy, QSize viewport) {
    const float distance = (pose.viewCenter - pose.position).length();
    // The height of the view at the centre's distance, in scene units per pixel.
    const float perPixel = 2 * distance * std::tan(pose.verticalFieldOfView * kPi / 360) /
                           float(std::max(viewport.height(), 1));
    const QVector3D shift = (-dx * rightOf(pose) + dy * trueUp(pose)) * perPixel;
    CameraPose out = pose;
    out.position += shift;
    out.viewCenter += shift;
    return out;
}

CameraPose zoom(const CameraPose& pose, float steps) {
    const QVector3D toCentre = pose.viewCenter - pose.position;
    const float distance = toCentre.length();
    const float next =
        std::max(distance * std::pow(0.85f, steps), 1e-6f * std::max(distance, 1.0f));
    CameraPose out = pose;
    out.position = pose.viewCenter - toCentre.normalized() * next;
    return out;
}

CameraPose walk(const CameraPose& pose, float forward, float right) {
    const QVector3D up = pose.up.normalized();
    QVector3D ahead = pose.viewCenter - pose.position;
    ahead -= up * QVector3D::dotProduct(ahead, up); // level
    ahead = ahead.lengthSquared() > 0 ? ahead.normalized() : QVector3D(0, 0, -1);
    const QVector3D side = QVector3D::crossProduct(ahead, up).normalized();
    const QVector3D step = ahead * forward + side * right;
    CameraPose out = pose;
    out.position += step;
    out.viewCenter += step;
    return out;
}

CameraPose look(const CameraPose& pose, float yaw, float pitch) {
    const QVector3D up = pose.up.normalized();
    const QVector3D toCentre = pose.viewCenter - pose.position;
    const float distance = toCentre.length();
    QVector3D forward = toCentre.normalized();
    // Keep at least ~1 degree from straight up or down.
    const float current = std::asin(std::clamp(QVector3D::dotProduct(forward, up), -1.0f, 1.0f));
    const float limit = kPi / 2 - 0.02f;
    pitch = std::clamp(current + pitch, -limit, limit) - current;
    const QVector3D right = QVector3D::crossProduct(forward, up).normalized();
    forward =
        QQuaternion::fromAxisAndAngle(up, -yaw * 180 / kPi)
            .rotatedVector(
                QQuaternion::fromAxisAndAngle(right, pitch * 180 / kPi).rotatedVector(forward));
    CameraPose out = pose;
    out.viewCenter = pose.position + forward * distance;
    return out;
}

} // namespace fl::viewer
