#include "screen_error_meter.h"

#include "mesh/mesh_error.h"

namespace fl::suite {

ScreenErrorMeter::ScreenErrorMeter(QObject* parent) : QObject(parent) {}

ScreenErrorMeter::~ScreenErrorMeter() {
    *alive_ = false;
    if (worker_.joinable()) worker_.join();
}

bool ScreenErrorMeter::busy() const {
    std::lock_guard lock(mutex_);
    return working_ || pending_;
}

void ScreenErrorMeter::measure(std::shared_ptr<const mesh::SceneMeshes> frame) {
    std::lock_guard lock(mutex_);
    if (working_) {
        pending_ = std::move(frame); // only the newest counts
        return;
    }
    working_ = true;
    if (worker_.joinable()) worker_.join();
    start(std::move(frame));
}

void ScreenErrorMeter::start(std::shared_ptr<const mesh::SceneMeshes> frame) {
    worker_ = std::thread([this, frame, alive = alive_] {
        // The largest function shape on screen, its mesh in its own coordinates.
        const mesh::ShapeMesh* largest = nullptr;
        for (const mesh::ShapeMesh& s : frame->shapes)
            if (s.field && s.error.empty() && !s.mesh.isPointCloud() &&
                s.mesh.triangleCount() > 0 &&
                (!largest || s.mesh.triangleCount() > largest->mesh.triangleCount()))
                largest = &s;
        QString text;
        if (largest) {
            const mesh::SurfaceError e = mesh::measureSurfaceError(*largest->field, largest->mesh);
            text = tr("max error %1 of the diagonal (%2)")
                       .arg(e.max, 0, 'e', 1)
                       .arg(QString::fromStdString(largest->shape
                                                       ? largest->shape->type +
                                                             (largest->shape->defName.empty()
                                                                  ? ""
                                                                  : " " + largest->shape->defName)
                                                       : std::string("shape")));
        }
        QMetaObject::invokeMethod(
            this,
            [this, text, alive] {
                if (!*alive) return;
                std::shared_ptr<const mesh::SceneMeshes> next;
                {
                    std::lock_guard lock(mutex_);
                    next = std::move(pending_);
                    pending_.reset();
                    working_ = next != nullptr;
                }
                Q_EMIT measured(text);
                if (next) {
                    if (worker_.joinable()) worker_.join();
                    start(std::move(next));
                }
            },
            Qt::QueuedConnection);
    });
}

} // namespace fl::suite
