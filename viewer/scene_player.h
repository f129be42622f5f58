#pragma once
// Plays a scene: keeps its timeline (play, pause, seek, speed), and meshes it
// for the moment shown on a worker thread, so the interface never waits.
// Only the newest request counts: while one frame is being meshed, later
// requests replace each other and the stale ones are dropped, never queued.
// The effects plan decides what a tick costs: a static scene is never asked
// again, shapes whose geometry does not read t come from the mesh cache.
#include "animation/clock.h"
#include "mesh/mesh_cache.h"
#include "mesh/scene_meshing.h"
#include "platform/newest_only_worker.h"
#include "scene/effects_plan.h"
#include "scene/scene.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>
#include <optional>
#include <unordered_map>

namespace fl::viewer {

class ScenePlayer : public QObject {
    Q_OBJECT
  public:
    // `clock`: the wall clock (tests inject a manual one); null: the system's.
    explicit ScenePlayer(const animation::WallClock* clock = nullptr, QObject* parent = nullptr);
    ~ScenePlayer() override;

    // A new scene (the editor's latest good parse): meshed at the current moment.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    const scene::EffectsPlan& plan() const { return plan_; }

    void play();
    void pause();
    bool playing() const { return timeline_.playing(); }
    void seek(double sceneSeconds);
    void setSpeed(double speed);
    double speed() const { return timeline_.speed(); }
    double sceneSeconds() const;
    // Meshing for every shape at this resolution instead of each FGeometry's
    // own (0: the file's); the viewer's level of detail sets it.
    void setResolution(double resolution);
    // Per FGeometry: the level of detail's choice (meshed again at once).
    void setResolutions(std::unordered_map<const scene::Node*, double> resolutions);
    // Values for the formulas' named parameters (the sliders): meshed again at once.
    void setParameters(std::vector<std::pair<std::string, double>> values);
    // Mesh the current moment again now (after a seek while paused, say).
    void refresh();
    // A click on a shape under `sensor` (a TouchSensor) at the current moment:
    // isActive TRUE, then FALSE with touchTime, and their ROUTEs (the fan
    // starts turning). Kept with the moment and replayed into every later
    // frame; seeking back before it forgets it. False when the sensor is not
    // of the scene being played.
    bool touch(const scene::Node& sensor);
    std::size_t inputsKept() const { return inputs_.size(); }
    // Advance the timeline and ask for a frame if the scene varies with time;
    // the timer calls it about 30 times a second while playing.
    void tick();

    // Meshes made (cache misses) since the scene was set: a clock playing
    // for a minute makes none after its first frame.
    std::size_t meshesMade() const { return cache_.misses(); }
    std::size_t framesDelivered() const { return delivered_; }
    bool busy() const;

  Q_SIGNALS:
    void meshesReady(std::shared_ptr<const fl::mesh::SceneMeshes> meshes, double sceneSeconds);
    void timeChanged(double sceneSeconds);

  private:
    // One event from the user, delivered to the one clock at its moment.
    struct Input {
        const scene::Node* node = nullptr;
        std::string field;
        scene::FieldValue value;
        animation::Instant at;
    };
    struct Request {
        std::shared_ptr<const scene::Scene> scene;
        animation::Instant instant;
        std::vector<Input> inputs; // up to `instant`, oldest first
        double resolution = 0;
        std::vector<std::pair<std::string, double>> parameters;
        std::unordered_map<const scene::Node*, double> resolutions;
    };
    struct Frame {
        std::shared_ptr<const mesh::SceneMeshes> meshes;
        double seconds = 0;
    };
    void request();
    Frame meshFrame(const Request& r); // on the worker
    void finished(const Request& r, const Frame& frame);

    std::unique_ptr<animation::WallClock> ownClock_;
    const animation::WallClock& clock_;
    animation::SceneTimeline timeline_;
    std::shared_ptr<const scene::Scene> scene_;
    std::vector<Input> inputs_; // the user's events on scene_, oldest first
    scene::EffectsPlan plan_;
    double resolution_ = 0;
    std::vector<std::pair<std::string, double>> parameters_;
    std::unordered_map<const scene::Node*, double> resolutions_;
    mesh::MeshCache cache_;
    QTimer timer_;

    std::size_t delivered_ = 0;
    // Last: it stops and joins its job before what the job reads goes.
    platform::NewestOnlyWorker<Request, Frame> worker_;
};

} // namespace fl::viewer
