#pragma once
// The status bar's accuracy figure: after each new frame, how far the
// largest function shape's mesh on screen is from its true surface (max
// distance, a fraction of its box diagonal: mesh/mesh_error.h), measured on
// a worker thread — only the newest frame is measured, the interface never
// waits.
#include "mesh/scene_meshing.h"

#include "newest_only_worker.h"

#include <QObject>

#include <memory>

namespace fl::suite {

class ScreenErrorMeter : public QObject {
    Q_OBJECT
  public:
    explicit ScreenErrorMeter(QObject* parent = nullptr);

    void measure(std::shared_ptr<const mesh::SceneMeshes> frame) {
        worker_.request(std::move(frame));
    }
    bool busy() const { return worker_.busy(); }

  Q_SIGNALS:
    // "max error 1.2e-03 of the diagonal (FShape MELON)"; empty: nothing to measure.
    void measured(const QString& text);

  private:
    NewestOnlyWorker<std::shared_ptr<const mesh::SceneMeshes>, QString> worker_;
};

} // namespace fl::suite
