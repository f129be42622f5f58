#include "animator.h"

#include "event_responses.h"
#include "interpolation.h"
#include "scene/field_access.h"
#include "time_sensor.h"
#include "time_window.h"

#include <algorithm>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

namespace fl::animation {

using scene::AccessType;
using scene::FieldType;
using scene::FieldValue;
using scene::Node;
using scene::Severity;

namespace {

struct Outgoing {
    std::string fromField;
    const Node* to = nullptr;
    std::string toField;
    std::size_t id = 0; // index into the fired-this-timestamp flags
};

// One end of an IS connection: `interfaceField` of a PROTO instance and
// `field` of a node of its expansion.
struct IsLink {
    std::string interfaceField;
    const Node* other = nullptr; // the expansion node (inbound) or the instance (outbound)
    std::string field;
};

struct Event {
    const Node* node = nullptr;
    std::string field;
    FieldValue value;
};

// The name a field is stored under: an inputOutput field's events
// ("set_x", "x_changed") address the field "x".
std::string canonicalField(const Node& node, std::string_view name) {
    if (node.spec) {
        if (const scene::FieldSpec* f = scene::findFieldSpec(*node.spec, name))
            return std::string(f->name);
        return std::string(name);
    }
    if (node.proto) {
        const scene::ProtoDeclaration& p = node.proto->definition();
        if (p.interfaceField(name)) return std::string(name);
        const std::string_view base = scene::eventBaseName(name);
        if (const scene::FieldDeclaration* d = base.empty() ? nullptr : p.interfaceField(base))
            if (d->access == AccessType::InputOutput) return std::string(base);
    }
    return std::string(name);
}

const scene::FieldSpec* specOf(const Node& node, std::string_view field) {
    return node.spec ? scene::findFieldSpec(*node.spec, field) : nullptr;
}

bool hasTiming(const Node& node) {
    return node.spec && node.spec->family == scene::NodeFamily::Function &&
           scene::findFieldSpec(*node.spec, "timeBase");
}

bool isLive(const Node& node) {
    return !node.inProtoBody && !node.type.empty();
}

double firstNumber(const FieldValue& v, double fallback = 0) {
    return v.numbers.empty() ? fallback : v.numbers[0];
}

} // namespace

struct Animator::Impl final : ResponseContext {
    const scene::Scene& scene;
    AnimatorLimits limits;
    std::vector<scene::SceneDiagnostic> diagnostics;

    std::unordered_map<const Node*, std::vector<Outgoing>> routesFrom;
    std::size_t routes = 0;
    std::unordered_map<const Node*, std::vector<IsLink>> isInbound;  // instance -> expansion
    std::unordered_map<const Node*, std::vector<IsLink>> isOutbound; // expansion -> instance
    struct Sensor {
        const Node* node;
        TimeSensorState state;
    };
    std::vector<Sensor> sensors;
    std::unordered_map<const Node*, std::size_t> sensorIndex;
    std::vector<const Node*> timedNodes;

    // Mutable state: what events have set.
    std::unordered_map<const Node*, std::vector<std::pair<std::string, FieldValue>>> values;
    std::unordered_map<const Node*, int> sequencer;
    // Nodes bound by set_bind events, top last (the file's first node of each
    // kind is bound at load without being on it: see bind()).
    std::map<BindableKind, std::vector<const Node*>> bindStacks;
    std::unordered_map<const Node*, double> times;
    std::vector<char> fired;
    std::deque<Event> queue;
    std::vector<FieldChange> changes;
    std::set<std::pair<const Node*, std::string>> changeKeys;
    Instant now;
    std::int64_t previousUtcNs = std::numeric_limits<std::int64_t>::min();
    bool firstTick = true;
    std::size_t delivered = 0;
    bool cutShortReported = false;

    Impl(const scene::Scene& s, AnimatorLimits l) : scene(s), limits(l) {
        wire();
        checkScene();
        fired.assign(routes, 0);
        computeTimes();
    }

    // ---- wiring --------------------------------------------------------------

    void addRoute(const scene::Route& r) {
        if (!r.fromNode || !r.toNode) return;
        routesFrom[r.fromNode].push_back({canonicalField(*r.fromNode, r.fromField), r.toNode,
                                          canonicalField(*r.toNode, r.toField), routes++});
    }

    void wire() {
        for (const scene::Scene* s : scene::scenesShownBy(scene))
            wireScene(*s);
    }

    void wireScene(const scene::Scene& scene) {
        for (const scene::Route& r : scene.routes)
            addRoute(r);
        scene.forEachNode([&](const Node& n) {
            if (!isLive(n)) return;
            for (const scene::Route& r : n.expansionRoutes)
                addRoute(r);
            if (n.kind() == scene::NodeKind::TimeSensor) {
                sensorIndex[&n] = sensors.size();
                sensors.push_back({&n, {}});
            }
            if (hasTiming(n)) timedNodes.push_back(&n);
            if (n.instance) wireIs(n);
        });
    }

    void wireIs(const Node& clone) {
        const scene::ProtoDeclaration& proto = clone.instance->proto->definition();
        for (const scene::Field& f : clone.fields)
            for (const std::string& is : f.isReferences) { // events fan in and out
                const scene::FieldDeclaration* decl = proto.interfaceField(is);
                if (!decl) continue;
                const std::string field = canonicalField(clone, f.name);
                if (scene::canWrite(decl->access))
                    isInbound[clone.instance].push_back({is, &clone, field});
                if (scene::canRead(decl->access))
                    isOutbound[&clone].push_back({is, clone.instance, field});
            }
    }

    void warn(int file, scene::FilePos pos, std::string message, std::string suggestion = {}) {
        diagnostics.push_back({Severity::Warning, scene.pathOf(file), pos, std::move(message),
                               std::move(suggestion)});
    }

    void checkScene() {
        for (const scene::Scene* s : scene::scenesShownBy(scene))
            checkScene(*s);
    }

    void checkScene(const scene::Scene& scene) {
        scene.forEachNode([&](const Node& n) {
            if (!isLive(n) || n.instance) return; // expansions: warned once, at the body
            if (const auto kind = interpolatorKind(n.kind())) {
                const std::vector<double> key = value(n, "key").numbers;
                const std::vector<double> keyValue = value(n, "keyValue").numbers;
                if (key.empty() && keyValue.empty()) return; // X3D's default: idle, not wrong
                const std::string why = checkKeys(*kind, key, keyValue);
                if (!why.empty())
                    warn(n.file, n.where, n.type + ": " + why + "; it will send no values");
            }
        });
        // A TimeSensor's or TouchSensor's times are UTC seconds (X3D); a
        // function node on scene time would read them as ~56 years from now.
        auto checkRoute = [&](const scene::Route& r) {
            if (!r.fromNode || !r.toNode || !r.fromNode->spec || !hasTiming(*r.toNode)) return;
            const scene::FieldSpec* from = specOf(*r.fromNode, r.fromField);
            const std::string to = canonicalField(*r.toNode, r.toField);
            if (!from || from->type != FieldType::SFTime || (to != "startTime" && to != "stopTime"))
                return;
            if (r.fromNode->spec->family != scene::NodeFamily::Standard) return;
            if (scene::stringField(*r.toNode, "timeBase") != "scene") return;
            warn(r.file, r.where,
                 "ROUTE sends " + r.fromNode->type + "." + r.fromField +
                     " (UTC seconds, as every X3D time) to " + r.toNode->type + "." + r.toField +
                     ", whose timeBase is \"scene\" (seconds since the scene started)",
                 "give the " + r.toNode->type + " timeBase \"utc\"");
        };
        for (const scene::Route& r : scene.routes)
            checkRoute(r);
    }

    // ---- values ----------------------------------------------------------------

    FieldValue value(const Node& node, std::string_view name) const override {
        const std::string field = canonicalField(node, name);
        if (auto it = values.find(&node); it != values.end())
            for (const auto& [n, v] : it->second)
                if (n == field) return v;
        if (const scene::Field* f = node.field(field)) return f->value;
        if (node.spec) return scene::fieldValue(node, field);
        if (node.proto)
            if (const scene::FieldDeclaration* d = node.proto->definition().interfaceField(field))
                return d->value;
        return {};
    }

    void store(const Node& node, const std::string& field, const FieldValue& v) {
        auto& list = values[&node];
        bool found = false;
        for (auto& [n, old] : list)
            if (n == field) {
                old = v;
                found = true;
            }
        if (!found) list.emplace_back(field, v);
        if (changeKeys.emplace(&node, field).second) changes.push_back({&node, field});
    }

    // ---- the cascade -------------------------------------------------------------

    void emit(const Node& node, std::string_view name, const FieldValue& v) override {
        const std::string field(name);
        store(node, field, v); // the last value an output sent, for value()
        if (auto it = routesFrom.find(&node); it != routesFrom.end())
            for (const Outgoing& o : it->second)
                if (o.fromField == field && !fired[o.id]) {
                    fired[o.id] = 1;
                    queue.push_back({o.to, o.toField, v});
                }
        if (auto it = isOutbound.find(&node); it != isOutbound.end())
            for (const IsLink& l : it->second)
                if (l.field == field) emit(*l.other, l.interfaceField, v);
    }

    void set(const Node& node, std::string_view name, const FieldValue& v) override {
        const std::string field(name);
        store(node, field, v);
        emit(node, field, v);
    }

    double nowSeconds() const override { return now.x3dSeconds(); }
    int& sequencerIndex(const Node& node) override { return sequencer[&node]; }

    // X3D 7.2.2: TRUE puts the node on top of its stack (the old top sends
    // isBound FALSE); FALSE takes it off (the node below, if any, is bound
    // again). The first node of each kind, bound at load, is below every
    // event's: readers fall back to it when no node says isBound.
    void bind(const Node& node, BindableKind kind, bool on) override {
        std::vector<const Node*>& stack = bindStacks[kind];
        const Node* top = stack.empty() ? nullptr : stack.back();
        auto bound = [&](const Node& n, bool b) {
            set(n, "isBound", singleValue(scene::FieldType::SFBool, b));
            if (b) set(n, "bindTime", singleValue(scene::FieldType::SFTime, nowSeconds()));
        };
        if (on) {
            if (top == &node) return;
            std::erase(stack, &node);
            if (top) bound(*top, false);
            stack.push_back(&node);
            bound(node, true);
        } else if (top == &node) {
            stack.pop_back();
            bound(node, false);
            if (!stack.empty()) bound(*stack.back(), true);
        } else {
            std::erase(stack, &node);
        }
    }

    // X3D ignores startTime / cycleInterval changes while a time-dependent
    // node is active, and a stopTime at or before its startTime.
    bool ignoresTimingEvent(const Node& node, const std::string& field, const FieldValue& v) {
        const bool sensor = node.kind() == scene::NodeKind::TimeSensor;
        if (!sensor && !hasTiming(node)) return false;
        if (field != "startTime" && field != "cycleInterval" && field != "stopTime") return false;
        bool active = false;
        if (sensor) {
            active = sensors[sensorIndex.at(&node)].state.active;
        } else {
            active = evaluateWindow(windowOf(node), nowOn(node)).phase == Phase::Active;
        }
        if (!active) return false;
        if (field != "stopTime") return true;
        return firstNumber(v) <= firstNumber(value(node, "startTime"));
    }

    void deliver(const Event& e) {
        const Node& node = *e.node;
        if (node.kind() == scene::NodeKind::Script) return; // never executed (warned at load)
        if (node.proto) {
            store(node, e.field, e.value);
            if (auto it = isInbound.find(&node); it != isInbound.end())
                for (const IsLink& l : it->second)
                    if (l.interfaceField == e.field) queue.push_back({l.other, l.field, e.value});
            return;
        }
        const scene::FieldSpec* spec = specOf(node, e.field);
        if (!spec || !scene::canWrite(spec->access)) return;
        if (respond(node, e.field, e.value, *this)) return;
        if (ignoresTimingEvent(node, e.field, e.value)) return;
        if (spec->access == AccessType::InputOutput)
            set(node, e.field, e.value);
        else
            store(node, e.field, e.value);
    }

    void cascade() {
        while (!queue.empty()) {
            if (++delivered > limits.maxEventsPerTimestamp) {
                if (!cutShortReported)
                    warn(0, {},
                         "an event cascade delivered more than " +
                             std::to_string(limits.maxEventsPerTimestamp) +
                             " events at one moment; the rest were dropped");
                cutShortReported = true;
                queue.clear();
                return;
            }
            const Event e = std::move(queue.front());
            queue.pop_front();
            deliver(e);
        }
    }

    void beginTimestamp(const Instant& at) {
        now = at;
        std::fill(fired.begin(), fired.end(), 0);
        changes.clear();
        changeKeys.clear();
        delivered = 0;
    }

    // ---- time ----------------------------------------------------------------------

    TimeWindow windowOf(const Node& node) const {
        return timeWindowOf(
            firstNumber(value(node, "startTime")), firstNumber(value(node, "stopTime")),
            firstNumber(value(node, "cycleInterval"), 1), firstNumber(value(node, "loop")) != 0);
    }

    std::int64_t nowOn(const Node& node) const {
        const auto base = parseTimeBase(scene::stringField(node, "timeBase"));
        return now.nanosecondsOn(base.value_or(TimeBase::Scene));
    }

    void computeTimes() {
        for (const Node* n : timedNodes) {
            const FieldValue span = value(*n, "timeSpan");
            const double a = span.numbers.size() > 0 ? span.numbers[0] : 0;
            const double b = span.numbers.size() > 1 ? span.numbers[1] : 1;
            times[n] = firstTick ? a : functionTime(windowOf(*n), a, b, nowOn(*n));
        }
    }

    TimeSensorFields sensorFields(const Node& n) const {
        auto number = [&](const char* f) { return firstNumber(value(n, f)); };
        return {number("enabled") != 0, number("loop") != 0, number("cycleInterval"),
                number("startTime"),    number("stopTime"),  number("pauseTime"),
                number("resumeTime")};
    }

    void advanceSensors() {
        for (Sensor& s : sensors) {
            const Node& node = *s.node;
            advanceTimeSensor(s.state, sensorFields(node), now.utcNs, previousUtcNs, firstTick,
                              [&](std::string_view field, double v) {
                                  const scene::FieldSpec* spec = specOf(node, field);
                                  if (spec) emit(node, field, singleValue(spec->type, v));
                              });
            cascade();
        }
    }

    // After an outside event: its cascade, then the sensors at the same
    // moment (a startTime set to now starts a sensor now), then t.
    void finishTimestamp() {
        cascade();
        advanceSensors();
        firstTick = false;
        computeTimes();
        previousUtcNs = now.utcNs;
    }

    void tick(const Instant& at) {
        beginTimestamp(at);
        finishTimestamp();
    }
};

Animator::Animator(const scene::Scene& scene, AnimatorLimits limits)
    : impl_(std::make_unique<Impl>(scene, limits)) {}
Animator::~Animator() = default;

const std::vector<scene::SceneDiagnostic>& Animator::diagnostics() const {
    return impl_->diagnostics;
}

void Animator::tick(const Instant& now) {
    impl_->tick(now);
}

bool Animator::send(const Node& node, std::string_view field, const FieldValue& value,
                    const Instant& now) {
    Impl& m = *impl_;
    const std::string name = canonicalField(node, field);
    bool accepts = false;
    if (const scene::FieldSpec* spec = specOf(node, name))
        accepts = scene::canWrite(spec->access);
    else if (node.proto)
        if (const scene::FieldDeclaration* d = node.proto->definition().interfaceField(name))
            accepts = scene::canWrite(d->access);
    if (!accepts) return false;
    m.beginTimestamp(now);
    m.queue.push_back({&node, name, value});
    m.finishTimestamp();
    return true;
}

bool Animator::sensorOutput(const Node& node, std::string_view field, const FieldValue& value,
                            const Instant& now) {
    Impl& m = *impl_;
    const std::string name = canonicalField(node, field);
    const scene::FieldSpec* spec = specOf(node, name);
    if (!spec || !scene::canRead(spec->access)) return false;
    m.beginTimestamp(now);
    m.emit(node, name, value);
    m.finishTimestamp();
    return true;
}

void Animator::reset() {
    Impl& m = *impl_;
    m.values.clear();
    m.sequencer.clear();
    m.bindStacks.clear();
    m.queue.clear();
    m.changes.clear();
    m.changeKeys.clear();
    for (auto& s : m.sensors)
        s.state = {};
    m.firstTick = true;
    m.previousUtcNs = std::numeric_limits<std::int64_t>::min();
    m.computeTimes();
}

FieldValue Animator::value(const Node& node, std::string_view field) const {
    return impl_->value(node, field);
}

bool Animator::holdsEventValues(const Node& node) const {
    return impl_->values.count(&node) > 0;
}

double Animator::time(const Node& node) const {
    auto it = impl_->times.find(&node);
    return it == impl_->times.end() ? 0.0 : it->second;
}

FunctionTiming Animator::timing(const Node& node) const {
    FunctionTiming out;
    out.window = impl_->windowOf(node);
    const FieldValue span = impl_->value(node, "timeSpan");
    if (span.numbers.size() > 0) out.spanStart = span.numbers[0];
    if (span.numbers.size() > 1) out.spanEnd = span.numbers[1];
    out.base = parseTimeBase(scene::stringField(node, "timeBase")).value_or(TimeBase::Scene);
    return out;
}

const std::vector<FieldChange>& Animator::changes() const {
    return impl_->changes;
}
std::size_t Animator::eventsDelivered() const {
    return impl_->delivered;
}
std::size_t Animator::routeCount() const {
    return impl_->routes;
}
std::size_t Animator::timeSensorCount() const {
    return impl_->sensors.size();
}

} // namespace fl::animation
