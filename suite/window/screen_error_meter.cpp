#include "screen_error_meter.h"

#include "mesh/mesh_error.h"

namespace fl::suite {

namespace {

// How far the largest function shape on screen is from its true surface.
QString errorOfLargestShape(const std::shared_ptr<const mesh::SceneMeshes>& frame) {
    const mesh::ShapeMesh* largest = nullptr;
    for (const mesh::ShapeMesh& s : frame->shapes)
        if (s.field && s.error.empty() && !s.mesh.isPointCloud() && s.mesh.triangleCount() > 0 &&
            (!largest || s.mesh.triangleCount() > largest->mesh.triangleCount()))
            largest = &s;
    if (!largest) return {};
    // Its mesh is in its own coordinates, the field's.
    const mesh::SurfaceError e = mesh::measureSurfaceError(*largest->field, largest->mesh);
    const std::string name =
        largest->shape ? largest->shape->type +
                             (largest->shape->defName.empty() ? "" : " " + largest->shape->defName)
                       : std::string("shape");
    return ScreenErrorMeter::tr("max error %1 of the diagonal (%2)")
        .arg(e.max, 0, 'e', 1)
        .arg(QString::fromStdString(name));
}

} // namespace

ScreenErrorMeter::ScreenErrorMeter(QObject* parent)
    : QObject(parent), worker_(this, errorOfLargestShape,
                               [this](const std::shared_ptr<const mesh::SceneMeshes>&,
                                      QString text) { Q_EMIT measured(text); }) {}

} // namespace fl::suite
