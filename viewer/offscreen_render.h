#pragma once
// One frame of a meshed scene drawn off screen into an image (functionlab
// render, thumbnails, GUI tests). It needs an OpenGL 3.3 context, so a
// display: under CI, xvfb-run gives one.
#include "camera_pose.h"
#include "mesh/scene_meshing.h"

#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>

#include <optional>

namespace fl::viewer {

struct OffscreenRequest {
    QSize size{800, 600};
    // The viewpoint by name (description or DEF); empty: the first, or a
    // view of the whole scene when there is none.
    QString viewpoint;
    std::optional<CameraPose> pose; // overrides the viewpoint
    int timeoutMs = 20000;
};

// A QGuiApplication must exist. Returns nothing, with `error` set, when no
// frame came (no OpenGL, an unknown viewpoint, a timeout).
std::optional<QImage> renderOffscreen(const mesh::SceneMeshes& meshes,
                                      const OffscreenRequest& request, QString& error);

// The pose a request resolves to (the same rule the viewer binds with).
std::optional<CameraPose> poseFor(const mesh::SceneView& view, const Bounds& bounds,
                                  const QString& viewpoint, float aspect, QString& error);

} // namespace fl::viewer
