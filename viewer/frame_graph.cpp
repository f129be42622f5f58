#include "frame_graph.h"

#include <Qt3DRender/QCameraLens>
#include <Qt3DRender/QCameraSelector>
#include <Qt3DRender/QClearBuffers>
#include <Qt3DRender/QFilterKey>
#include <Qt3DRender/QNoDraw>
#include <Qt3DRender/QRenderPassFilter>
#include <Qt3DRender/QRenderSurfaceSelector>
#include <Qt3DRender/QRenderTarget>
#include <Qt3DRender/QRenderTargetOutput>
#include <Qt3DRender/QRenderTargetSelector>
#include <Qt3DRender/QSortPolicy>
#include <Qt3DRender/QTechniqueFilter>
#include <Qt3DRender/QTexture>
#include <Qt3DRender/QViewport>

#include "surface_material.h" // pass keys

namespace fl::viewer {
namespace {

Qt3DRender::QRenderTarget* offscreenTarget(QSize size, Qt3DCore::QNode* parent) {
    auto* target = new Qt3DRender::QRenderTarget(parent);
    auto output = [&](Qt3DRender::QRenderTargetOutput::AttachmentPoint point,
                      Qt3DRender::QAbstractTexture::TextureFormat format) {
        auto* out = new Qt3DRender::QRenderTargetOutput(target);
        out->setAttachmentPoint(point);
        auto* texture = new Qt3DRender::QTexture2D(out);
        texture->setSize(size.width(), size.height());
        texture->setFormat(format);
        out->setTexture(texture);
        target->addOutput(out);
    };
    output(Qt3DRender::QRenderTargetOutput::Color0, Qt3DRender::QAbstractTexture::RGBA8_UNorm);
    output(Qt3DRender::QRenderTargetOutput::Depth, Qt3DRender::QAbstractTexture::D24);
    return target;
}

Qt3DRender::QRenderPassFilter* passFilter(const char* pass, Qt3DCore::QNode* parent) {
    auto* filter = new Qt3DRender::QRenderPassFilter(parent);
    auto* key = new Qt3DRender::QFilterKey(filter);
    key->setName(QString::fromLatin1(kPassKey));
    key->setValue(QString::fromLatin1(pass));
    filter->addMatch(key);
    return filter;
}

} // namespace

FrameGraph buildFrameGraph(QObject* surface, QSize offscreenSize, QColor background,
                           const std::vector<Qt3DRender::QParameter*>& parameters,
                           Qt3DCore::QNode* cameraParent) {
    FrameGraph fg;
    auto* surfaceSelector = new Qt3DRender::QRenderSurfaceSelector;
    surfaceSelector->setSurface(surface);
    fg.root = surfaceSelector;
    Qt3DRender::QFrameGraphNode* top = surfaceSelector;
    const bool offscreen = offscreenSize.isValid();
    if (offscreen) {
        surfaceSelector->setExternalRenderTargetSize(offscreenSize);
        auto* targetSelector = new Qt3DRender::QRenderTargetSelector(surfaceSelector);
        targetSelector->setTarget(offscreenTarget(offscreenSize, targetSelector));
        top = targetSelector;
    }
    auto* viewport = new Qt3DRender::QViewport(top);
    fg.camera = new Qt3DRender::QCamera(cameraParent);
    auto* cameraSelector = new Qt3DRender::QCameraSelector(viewport);
    cameraSelector->setCamera(fg.camera);
    auto* techniques = new Qt3DRender::QTechniqueFilter(cameraSelector);
    for (auto* p : parameters)
        techniques->addParameter(p);

    auto* clear = fg.clear = new Qt3DRender::QClearBuffers(techniques);
    clear->setBuffers(Qt3DRender::QClearBuffers::ColorDepthBuffer);
    clear->setClearColor(background);
    new Qt3DRender::QNoDraw(clear);

    passFilter(kOpaquePass, techniques);
    // See-through shapes last, farthest first, so what is behind shows through.
    fg.capture = new Qt3DRender::QRenderCapture(techniques);
    auto* sort = new Qt3DRender::QSortPolicy(fg.capture);
    sort->setSortTypes(
        QList<Qt3DRender::QSortPolicy::SortType>{Qt3DRender::QSortPolicy::BackToFront});
    passFilter(kTransparentPass, sort);
    return fg;
}

void applyPose(Qt3DRender::QCamera* camera, const CameraPose& pose, float aspect) {
    camera->lens()->setPerspectiveProjection(pose.verticalFieldOfView, aspect, pose.nearPlane,
                                             pose.farPlane);
    camera->setPosition(pose.position);
    camera->setUpVector(pose.up);
    camera->setViewCenter(pose.viewCenter);
}

} // namespace fl::viewer
