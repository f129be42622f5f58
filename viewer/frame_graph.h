#pragma once
// The frame graph every view uses: clear to the background, draw the opaque
// pass, then the transparent pass sorted back to front, with the scene-wide
// parameters (lights, clip plane) given to every pass. On screen it draws to
// a window; off screen to a texture, with a capture at the end.
#include "camera_pose.h"

#include <QColor>
#include <QSize>
#include <Qt3DRender/QCamera>
#include <Qt3DRender/QClearBuffers>
#include <Qt3DRender/QFrameGraphNode>
#include <Qt3DRender/QParameter>
#include <Qt3DRender/QRenderCapture>

#include <vector>

class QSurface;
class QObject;

namespace fl::viewer {

struct FrameGraph {
    Qt3DRender::QFrameGraphNode* root = nullptr;
    Qt3DRender::QRenderCapture* capture = nullptr; // a frame as an image, on request
    Qt3DRender::QCamera* camera = nullptr;
    Qt3DRender::QClearBuffers* clear = nullptr; // its colour is the background
};

// `surface`: the window, or an offscreen surface (then `offscreenSize`
// sizes the texture drawn into). The camera is made under `cameraParent`.
FrameGraph buildFrameGraph(QObject* surface, QSize offscreenSize, QColor background,
                           const std::vector<Qt3DRender::QParameter*>& parameters,
                           Qt3DCore::QNode* cameraParent);

void applyPose(Qt3DRender::QCamera* camera, const CameraPose& pose, float aspect);

} // namespace fl::viewer
