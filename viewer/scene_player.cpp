#include "scene_player.h"
#include "animation/event_responses.h"
#include "text_outliner.h"

#include <exception>
#include <string>

namespace fl::viewer {

ScenePlayer::ScenePlayer(const animation::WallClock* clock, QObject* parent)
    : QObject(parent), ownClock_(clock ? nullptr : std::make_unique<animation::SystemWallClock>()),
      clock_(clock ? *clock : *ownClock_), timeline_(clock_),
      worker_(
          this, [this](const Request& r) { return meshFrame(r); },
          [this](const Request& r, const Frame& frame) { finished(r, frame); }) {
    timeline_.pause();
    timeline_.seek(0);
    timer_.setInterval(33);
    connect(&timer_, &QTimer::timeout, this, &ScenePlayer::tick);
}

ScenePlayer::~ScenePlayer() = default; // the worker stops its frame and joins

void ScenePlayer::setScene(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    inputs_.clear(); // they name the old scene's nodes
    plan_ = scene_ ? scene::makeEffectsPlan(*scene_) : scene::EffectsPlan{};
    resolutions_.clear(); // they name the old scene's nodes
    worker_.cancel();     // the frame in progress is for the old scene
    cache_.clear();
    request();
}

void ScenePlayer::play() {
    timeline_.play();
    timer_.start();
}

void ScenePlayer::pause() {
    timeline_.pause();
    timer_.stop();
    Q_EMIT timeChanged(sceneSeconds());
}

void ScenePlayer::seek(double seconds) {
    timeline_.seek(animation::secondsToNanoseconds(seconds));
    // What the user did after the moment sought has not happened there.
    const std::int64_t now = timeline_.now().sceneNs;
    std::erase_if(inputs_, [&](const Input& i) { return i.at.sceneNs > now; });
    Q_EMIT timeChanged(sceneSeconds());
    request();
}

void ScenePlayer::setSpeed(double speed) {
    if (speed > 0) timeline_.setSpeed(speed);
}

double ScenePlayer::sceneSeconds() const {
    return double(timeline_.now().sceneNs) / double(animation::kNanosecondsPerSecond);
}

void ScenePlayer::setResolution(double resolution) {
    resolution_ = resolution;
    request();
}

void ScenePlayer::setResolutions(std::unordered_map<const scene::Node*, double> resolutions) {
    resolutions_ = std::move(resolutions);
    request();
}

void ScenePlayer::setParameters(std::vector<std::pair<std::string, double>> values) {
    parameters_ = std::move(values);
    request();
}

void ScenePlayer::refresh() {
    request();
}

bool ScenePlayer::touch(const scene::Node& sensor) {
    if (!scene_ || sensor.kind() != scene::NodeKind::TouchSensor) return false;
    bool ours = false;
    for (const scene::Scene* s : scene::scenesShownBy(*scene_))
        s->forEachNode([&](const scene::Node& n) { ours = ours || &n == &sensor; });
    if (!ours) return false;
    const animation::Instant now = timeline_.now();
    using animation::singleValue;
    // X3D 20.4.4: pressing sends isActive TRUE, releasing over the geometry
    // isActive FALSE and touchTime (UTC seconds, as every SFTime).
    inputs_.push_back({&sensor, "isActive", singleValue(scene::FieldType::SFBool, 1), now});
    inputs_.push_back({&sensor, "isActive", singleValue(scene::FieldType::SFBool, 0), now});
    inputs_.push_back(
        {&sensor, "touchTime", singleValue(scene::FieldType::SFTime, now.x3dSeconds()), now});
    request();
    return true;
}

void ScenePlayer::tick() {
    Q_EMIT timeChanged(sceneSeconds());
    // A static scene looks the same at every moment: nothing to redo.
    if (scene_ && plan_.timeVarying != scene::kStatic) request();
}

bool ScenePlayer::busy() const {
    return worker_.busy();
}

// A request while a frame is being meshed replaces any older waiting one:
// stale frames are dropped, never queued.
void ScenePlayer::request() {
    if (!scene_) return;
    worker_.request({scene_, timeline_.now(), inputs_, resolution_, parameters_, resolutions_});
}

ScenePlayer::Frame ScenePlayer::meshFrame(const Request& r) {
    mesh::SceneMeshOptions o;
    o.instant = r.instant;
    o.sceneSeconds = double(r.instant.sceneNs) / double(animation::kNanosecondsPerSecond);
    o.placeInScene = false;
    o.cache = &cache_;
    o.text = qtTextOutliner();
    o.mesh.cancel = worker_.cancelFlag();
    o.mesh.threads = 1; // the interface keeps a core
    o.parameters = r.parameters;
    o.resolutions = r.resolutions;
    if (r.resolution > 0) {
        o.useFileResolution = false;
        o.mesh.resolution = r.resolution;
    }
    mesh::SceneMeshes made;
    try {
        // The one clock for this frame, replayed from the start: the
        // user's events at their moments, then this moment. Its own
        // animator per frame, so the interface never waits on a worker.
        animation::Animator clock(*r.scene);
        for (const Input& input : r.inputs)
            clock.sensorOutput(*input.node, input.field, input.value, input.at);
        clock.tick(r.instant);
        o.animator = &clock;
        made = mesh::meshScene(*r.scene, o);
    } catch (const std::exception& e) {
        // Out of memory on a hostile scene, say: the interface stays up
        // and says so; an empty frame replaces the scene.
        made = mesh::SceneMeshes{};
        made.notes.push_back(std::string("meshing stopped: ") + e.what());
    }
    made.source = r.scene; // keeps the nodes the meshes point at alive
    return {std::make_shared<const mesh::SceneMeshes>(std::move(made)), o.sceneSeconds};
}

void ScenePlayer::finished(const Request& r, const Frame& frame) {
    // A frame of a scene that has since been replaced is not shown.
    bool cancelled = false;
    for (const auto& s : frame.meshes->shapes)
        cancelled = cancelled || s.cancelled;
    if (r.scene == scene_ && !cancelled) {
        ++delivered_;
        Q_EMIT meshesReady(frame.meshes, frame.seconds);
    }
}

} // namespace fl::viewer
