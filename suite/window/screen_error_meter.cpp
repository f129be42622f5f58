#include "screen_error_meter.h"

#include "mesh/mesh_error.h"
#include "mesh/scene_meshing.h"

namespace fl::suite {

namespace {

bool measurable(const mesh::ShapeMesh& s) {
    return s.field && s.error.empty() && !s.mesh.isPointCloud() && s.mesh.triangleCount() > 0 &&
           mesh::isDrawn(s); // an invisible shape's error is no one's concern
}

// How far the focused function shape — else the largest — is from its true surface.
QString errorOfShapeOnScreen(const ScreenErrorMeter::Request& request) {
    const mesh::ShapeMesh* chosen = nullptr;
    for (const mesh::ShapeMesh& s : request.frame->shapes) {
        if (!measurable(s)) continue;
        if (request.focus && s.shape == request.focus) {
            chosen = &s;
            break;
        }
        if (!chosen || s.mesh.triangleCount() > chosen->mesh.triangleCount()) chosen = &s;
    }
    if (!chosen) return {};
    // Its mesh is in its own coordinates, the field's.
    const mesh::SurfaceError e = mesh::measureSurfaceError(*chosen->field, chosen->mesh);
    const std::string name =
        chosen->shape ? chosen->shape->type +
                            (chosen->shape->defName.empty() ? "" : " " + chosen->shape->defName)
                      : std::string("shape");
    return ScreenErrorMeter::tr("max error %1 of the diagonal (%2)")
        .arg(e.max, 0, 'e', 1)
        .arg(QString::fromStdString(name));
}

} // namespace

ScreenErrorMeter::ScreenErrorMeter(QObject* parent)
    : QObject(parent), worker_(this, errorOfShapeOnScreen,
                               [this](const Request&, QString text) { Q_EMIT measured(text); }) {}

void ScreenErrorMeter::measure(std::shared_ptr<const mesh::SceneMeshes> frame) {
    frame_ = std::move(frame);
    if (frame_) worker_.request({frame_, focus_});
}

void ScreenErrorMeter::focusOn(const scene::Node* shape) {
    if (shape == focus_) return;
    focus_ = shape;
    if (frame_) worker_.request({frame_, focus_});
}

} // namespace fl::suite
