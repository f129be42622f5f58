#pragma once
// The status bar's accuracy figure: after each new frame, how far the
// largest function shape's mesh on screen is from its true surface (max
// distance, a fraction of its box diagonal: mesh/mesh_error.h), measured on
// a worker thread — only the newest frame is measured, the interface never
// waits.
#include "mesh/scene_meshing.h"

#include <QObject>

#include <memory>
#include <mutex>
#include <thread>

namespace fl::suite {

class ScreenErrorMeter : public QObject {
    Q_OBJECT
  public:
    explicit ScreenErrorMeter(QObject* parent = nullptr);
    ~ScreenErrorMeter() override;

    void measure(std::shared_ptr<const mesh::SceneMeshes> frame);
    bool busy() const;

  Q_SIGNALS:
    // "max error 1.2e-03 of the diagonal (FShape MELON)"; empty: nothing to measure.
    void measured(const QString& text);

  private:
    void start(std::shared_ptr<const mesh::SceneMeshes> frame);

    mutable std::mutex mutex_;
    std::thread worker_;
    bool working_ = false;
    std::shared_ptr<const mesh::SceneMeshes> pending_;
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace fl::suite
