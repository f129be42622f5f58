#include "offscreen_render.h"

#include "frame_graph.h"
#include "render_scene.h"

#include <QEventLoop>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QTimer>
#include <Qt3DCore/QAspectEngine>
#include <Qt3DRender/QRenderAspect>
#include <Qt3DRender/QRenderSettings>

namespace fl::viewer {

std::optional<CameraPose> poseFor(const mesh::SceneView& view, const Bounds& bounds,
                                  const QString& viewpoint, float aspect, QString& error) {
    if (viewpoint.isEmpty())
        return view.viewpoints.empty() ? poseToFit(bounds, aspect)
                                       : poseForViewpoint(view.viewpoints.front(), bounds, aspect);
    QStringList names;
    for (const mesh::ViewPoint& v : view.viewpoints) {
        if (QString::fromStdString(v.name) == viewpoint) return poseForViewpoint(v, bounds, aspect);
        names << QString::fromStdString(v.name);
    }
    error = QStringLiteral("no viewpoint named '%1'; the scene has: %2")
                .arg(viewpoint, names.isEmpty() ? QStringLiteral("none") : names.join(", "));
    return std::nullopt;
}

std::optional<QImage> renderOffscreen(const mesh::SceneMeshes& meshes,
                                      const OffscreenRequest& request, QString& error) {
    if (!request.size.isValid() || request.size.width() > 16384 || request.size.height() > 16384) {
        error = QStringLiteral("the image size must lie in 1x1 .. 16384x16384");
        return std::nullopt;
    }
    {
        QOpenGLContext probe;
        probe.setFormat(QSurfaceFormat::defaultFormat());
        if (!probe.create()) {
            error = QStringLiteral("no OpenGL here: run under a display (or xvfb-run)");
            return std::nullopt;
        }
    }
    QOffscreenSurface surface;
    surface.setFormat(QSurfaceFormat::defaultFormat());
    surface.create();
    if (!surface.isValid()) {
        error =
            QStringLiteral("cannot create an OpenGL surface: run under a display (or xvfb-run)");
        return std::nullopt;
    }
    auto* root = new Qt3DCore::QEntity;
    RenderScene scene(root);
    scene.setMeshes(std::make_shared<const mesh::SceneMeshes>(meshes));
    const float aspect = float(request.size.width()) / float(request.size.height());
    std::optional<CameraPose> pose = request.pose;
    if (!pose) pose = poseFor(meshes.view, scene.bounds(), request.viewpoint, aspect, error);
    if (!pose) {
        delete root;
        return std::nullopt;
    }
    const auto& sky = meshes.view.background;
    const QColor background = QColor::fromRgbF(sky[0], sky[1], sky[2]);
    FrameGraph fg =
        buildFrameGraph(&surface, request.size, background, scene.frameParameters(), root);
    applyPose(fg.camera, *pose, aspect);
    auto* settings = new Qt3DRender::QRenderSettings(root);
    settings->setActiveFrameGraph(fg.root);
    settings->setRenderPolicy(Qt3DRender::QRenderSettings::Always);
    root->addComponent(settings);

    Qt3DCore::QAspectEngine engine;
    engine.registerAspect(new Qt3DRender::QRenderAspect());
    engine.setRootEntity(Qt3DCore::QEntityPtr(root));

    // The first frames may come before every buffer is uploaded: take the
    // third capture.
    std::optional<QImage> image;
    QEventLoop loop;
    int captures = 0;
    std::function<void()> request_ = [&] {
        Qt3DRender::QRenderCaptureReply* reply = fg.capture->requestCapture();
        QObject::connect(reply, &Qt3DRender::QRenderCaptureReply::completed, &loop, [&, reply] {
            ++captures;
            if (captures >= 3) {
                image = reply->image().convertToFormat(QImage::Format_ARGB32);
                loop.quit();
            } else {
                request_();
            }
            reply->deleteLater();
        });
    };
    QTimer::singleShot(0, &loop, request_);
    QTimer::singleShot(request.timeoutMs, &loop, [&] { loop.quit(); });
    loop.exec();
    if (!image)
        error = QStringLiteral("no frame was drawn in %1 ms (is OpenGL 3.3 available?)")
                    .arg(request.timeoutMs);
    return image;
}

} // namespace fl::viewer
