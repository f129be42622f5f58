#pragma once
// The status bar's accuracy figure: after each new frame, how far a function
// shape's mesh on screen is from its true surface (max distance, a fraction
// of its box diagonal: mesh/mesh_error.h) — the shape under the cursor, or
// the largest one when the cursor is over none — measured on a worker
// thread. Only the newest request is measured; the interface never waits.
#include "mesh/scene_meshing.h"

#include "platform/newest_only_worker.h"

#include <QObject>

#include <memory>

namespace fl::scene {
struct Node;
}

namespace fl::suite {

class ScreenErrorMeter : public QObject {
    Q_OBJECT
  public:
    explicit ScreenErrorMeter(QObject* parent = nullptr);

    // A new frame on screen: measured for the focused shape (or the largest).
    void measure(std::shared_ptr<const mesh::SceneMeshes> frame);
    // The FShape under the cursor (null: none, the largest is measured). The
    // last frame is measured again when the focus changes.
    void focusOn(const scene::Node* shape);
    const scene::Node* focus() const { return focus_; }
    bool busy() const { return worker_.busy(); }

    struct Request {
        std::shared_ptr<const mesh::SceneMeshes> frame;
        const scene::Node* focus = nullptr;
    };

  Q_SIGNALS:
    // "max error 1.2e-03 of the diagonal (FShape MELON)"; empty: nothing to measure.
    void measured(const QString& text);

  private:
    std::shared_ptr<const mesh::SceneMeshes> frame_;
    const scene::Node* focus_ = nullptr;
    platform::NewestOnlyWorker<Request, QString> worker_;
};

} // namespace fl::suite
