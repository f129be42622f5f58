#pragma once
// The Haptics panel (issue 16 §3): feel the scene. It starts the servo loop
// only when the effects plan says something is tangible; it hands the loop a
// snapshot of the tangible shapes at the scene's moment (made on a worker,
// made again as time moves shapes); it shows the device, the loop's rate and
// jitter, the contact and a live graph of the force. Without a haptic
// device the mouse stands in: the tool goes to the point under the cursor,
// pressed a little into the surface, and the view draws the tool, the proxy
// and the force as an arrow.
#include "force_graph.h"
#include "panel.h"
#include "platform/newest_only_worker.h"

#include "field/box3.h"
#include "field/vec3.h"

#include <QPointF>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;

namespace fl::mesh {
struct SceneMeshes;
}

namespace fl::haptics {
class HapticDevice;
class PointerDevice;
class ServoLoop;
struct DeviceEntry;
struct TangibleScene;
} // namespace fl::haptics

namespace fl::suite {

// What the view draws of the touch: scene coordinates, newtons.
struct TouchMarks {
    field::Vec3 tool{}, proxy{}, force{};
    double maxForce = 1;
    bool contact = false;
};

class HapticsPanel : public Panel {
    Q_OBJECT
  public:
    explicit HapticsPanel(QWidget* parent = nullptr);
    ~HapticsPanel() override;

    // The devices connected, listed again (the mouse is always the first choice).
    void findDevices();
    QComboBox* devices() const { return devices_; }
    // Starts and stops feeling: the loop with the chosen device (the mouse's
    // stand-in, or a connected device mapped onto the scene's tangible box).
    void start();
    void stop();
    bool feeling() const;
    // Something in the current scene is tangible.
    bool tangible() const { return tangible_; }
    // Snapshot work running or waiting.
    bool busy() const override { return worker_.busy() || colourer_.busy(); }

    // Its place in the window: the mouse over the view is the tool while
    // feeling; the view draws the tool, the proxy and the force; each frame
    // is coloured by friction or density when asked; the timeline's time.
    void attach(PanelContext& context) override;
    // The mouse at this pixel of the view: the tool to the surface under it.
    void touchPixel(QPointF pixel);

    // The mouse over the view: the point under it on a surface and the
    // surface's outward normal there (scene coordinates); none: off the shapes.
    void touchAt(std::optional<field::Vec3> point, field::Vec3 normal = {});

    // Friction or density shown as colour on the surfaces (or nothing): the
    // window hands each frame to colour(); the coloured copy comes back by
    // frameColoured.
    QComboBox* showOnSurface() const { return show_; }
    bool colours() const;
    void colour(std::shared_ptr<const mesh::SceneMeshes> frame);

    QPushButton* feelButton() const { return feel_; }
    // What the panel says: devices found (or none), a device that failed, the scene.
    QLabel* notes() const { return notes_; }
    QLabel* status() const { return status_; }
    ForceGraph* graph() const { return graph_; }
    // Refreshes the status and the graph now (the timer does it 30 times a second).
    void refresh();

  public Q_SLOTS:
    void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene) override;
    // The scene's time (the timeline): shapes that move are snapshotted again.
    void setSceneTime(double seconds);

  protected:
    void showEvent(QShowEvent* event) override;

  Q_SIGNALS:
    void touchChanged(std::optional<fl::suite::TouchMarks> marks);
    void frameColoured(std::shared_ptr<const fl::mesh::SceneMeshes> frame);
    void showOnSurfaceChanged(); // the window shows the frame again, coloured or not

  private:
    PanelContext* context_ = nullptr;
    std::shared_ptr<const mesh::SceneMeshes> lastFrame_; // the view's, uncoloured
    struct Request {
        std::shared_ptr<const scene::Scene> scene;
        double seconds = 0;
    };
    void requestSnapshot();

    QPushButton* feel_;
    QPushButton* rescan_;
    QComboBox* devices_;
    QComboBox* show_;
    QSlider* depth_;
    QLabel *status_, *contact_, *notes_;
    ForceGraph* graph_;
    QTimer refresh_;
    std::shared_ptr<const scene::Scene> scene_;
    bool tangible_ = false;
    bool geometryVaries_ = false;
    double seconds_ = 0, snapshotSeconds_ = -1;
    std::vector<haptics::DeviceEntry> found_;
    bool scanned_ = false;                          // USB looked at (first shown, or Find devices)
    std::unique_ptr<haptics::HapticDevice> device_; // the one the loop runs
    haptics::PointerDevice* pointer_ = nullptr;     // device_, when it is the mouse's
    double maxForce_ = 1;
    field::Box3 tangibleBox_;
    std::unique_ptr<haptics::ServoLoop> loop_;
    std::shared_ptr<const haptics::TangibleScene> snapshot_;
    double sceneSize_ = 1;
    platform::NewestOnlyWorker<Request, std::shared_ptr<const haptics::TangibleScene>> worker_;
    struct ColourRequest {
        std::shared_ptr<const mesh::SceneMeshes> frame;
        std::shared_ptr<const haptics::TangibleScene> tangible;
        int kind = 0; // scene::TangibleKind
    };
    platform::NewestOnlyWorker<ColourRequest, std::shared_ptr<const mesh::SceneMeshes>> colourer_;
};

} // namespace fl::suite
