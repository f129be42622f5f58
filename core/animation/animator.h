#pragma once
// Runs a scene's animation with X3D semantics: TimeSensors send events at each
// tick, events cascade along ROUTEs (each ROUTE at most once per timestamp, as
// ISO/IEC 19775-1 §4.4.8.3 breaks loops), interpolators, sequencers and the
// event utilities answer, PROTO instances pass events through their IS
// connections, and every function node's t follows its timing fields on its
// own clock. Scripts are never run: events sent to them are dropped.
//
// The animator never changes the scene; it keeps the values events have set
// and answers `value()` with them (or the file's value). The viewer reads
// `changes()` after each tick to update only what moved.
#include "clock.h"
#include "scene/field_source.h"
#include "scene/scene.h"
#include "time_window.h"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fl::animation {

struct FieldChange {
    const scene::Node* node = nullptr;
    std::string field; // the field's own name ("rotation", not "set_rotation")
};

// A function node's timing as the clock holds it now (events included): its
// t at any later moment, without the animator — what the haptic servo thread
// evaluates at each tick between two snapshots of the scene.
struct FunctionTiming {
    TimeWindow window;
    double spanStart = 0, spanEnd = 1;
    TimeBase base = TimeBase::Scene;
    double at(const Instant& now) const {
        return functionTime(window, spanStart, spanEnd, now.nanosecondsOn(base));
    }
};

struct AnimatorLimits {
    // Events one timestamp may deliver before the cascade is cut short (with
    // a warning). ROUTEs fire once per timestamp, so only huge scenes reach it.
    std::size_t maxEventsPerTimestamp = 1'000'000;
};

// It is the scene's one clock (DESIGN §3): as a FieldSource it answers "what
// does this field hold now" for meshing, rendering and the wings.
class Animator final : public scene::FieldSource {
  public:
    explicit Animator(const scene::Scene& scene, AnimatorLimits limits = {});
    ~Animator() override;
    Animator(const Animator&) = delete;
    Animator& operator=(const Animator&) = delete;

    // Problems found while wiring the scene (interpolator keys that cannot be
    // used, UTC times routed into scene-time nodes, cascades cut short ...).
    const std::vector<scene::SceneDiagnostic>& diagnostics() const;

    // One timestamp: TimeSensors advance to `now`, their events cascade, then
    // every function node's t is computed.
    void tick(const Instant& now);
    // An event from outside (the viewer's TouchSensor touchTime, a slider),
    // delivered at `now` with its cascade. False when the node has no such
    // field that accepts events.
    bool send(const scene::Node& node, std::string_view field, const scene::FieldValue& value,
              const Instant& now);
    // An output event of a sensor the viewer drives (a TouchSensor's
    // touchTime, a ProximitySensor's position), with its cascade. False when
    // the node has no such output.
    bool sensorOutput(const scene::Node& node, std::string_view field,
                      const scene::FieldValue& value, const Instant& now);
    // Back to the file's values with every sensor inactive: what seeking
    // backwards does (events from user input are forgotten).
    void reset();

    // The field's current value: set by events, else the file's, else the default.
    scene::FieldValue value(const scene::Node& node, std::string_view field) const override;
    bool holdsEventValues(const scene::Node& node) const override;
    // A function node's t at the last tick (timeSpan[0] before the first).
    double time(const scene::Node& functionNode) const;
    FunctionTiming timing(const scene::Node& functionNode) const;
    // Fields set since the last tick or send began, each once.
    const std::vector<FieldChange>& changes() const;
    std::size_t eventsDelivered() const; // in the last timestamp
    std::size_t routeCount() const;      // scene ROUTEs and those of PROTO expansions
    std::size_t timeSensorCount() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace fl::animation
