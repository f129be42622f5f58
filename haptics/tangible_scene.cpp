#include "tangible_scene.h"

#include "mesh/scene_meshing.h"
#include "scene/field_access.h"

#include <unordered_map>

namespace fl::haptics {

const EffectField* TangibleShape::effect(scene::TangibleKind kind) const {
    for (const EffectField& e : effects)
        if (e.kind == kind) return &e;
    return nullptr;
}

namespace {

// The shapes' fields as the viewer meshes them: the same walk, the same clock,
// no triangles worth the name (resolution 4: only the fields are kept).
mesh::SceneMeshes fieldsAt(const scene::Scene& scene, const animation::Animator& clock,
                           const animation::Instant& moment) {
    mesh::SceneMeshOptions o;
    o.animator = &clock;
    o.instant = moment;
    o.useFileResolution = false;
    o.mesh.resolution = 4;
    o.mesh.threads = 1;
    o.standardShapes = false;
    o.placeInScene = false;
    return mesh::meshScene(scene, o);
}

} // namespace

TangibleScene makeTangibleScene(const scene::Scene& scene, const scene::EffectsPlan& plan,
                                const animation::Animator& clock,
                                const animation::Instant& moment) {
    TangibleScene out;
    out.moment = moment;
    if (!plan.needsHaptics) return out;
    std::unordered_map<const scene::Node*, const scene::PlanEntry*> tangible;
    for (const scene::PlanEntry& e : plan.entries)
        if (e.node && !e.tangible.empty()) tangible[e.node] = &e;
    const mesh::SceneMeshes meshes = fieldsAt(scene, clock, moment);
    std::unordered_map<const scene::Node*, bool> placed;
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        const auto it = tangible.find(s.shape);
        if (it == tangible.end()) continue;
        placed[s.shape] = true;
        const scene::PlanEntry& entry = *it->second;
        if (!s.error.empty()) {
            out.notes.push_back(s.name + ": " + s.error);
            continue;
        }
        if (!s.field && !(s.functionGeometry && s.geometry)) {
            out.notes.push_back(s.name + ": not a function shape: polygon contact is not "
                                         "rendered yet");
            continue;
        }
        const field::Affine toScene = field::Affine::fromMatrix(s.placement);
        const auto toShape = toScene.inverse();
        if (!toShape) {
            out.notes.push_back(s.name + ": its transform has a zero scale: it cannot be touched");
            continue;
        }
        TangibleShape shape;
        shape.name = s.name;
        shape.shape = s.shape;
        shape.field = s.field;
        shape.container = s.field ? s.field->box : s.domain;
        shape.toScene = toScene;
        shape.toShape = *toShape;
        for (const scene::TangibleEffect& t : entry.tangible) {
            if (!t.node) continue;
            const formula::Tape* tape = scene.definition(*t.node, "definition");
            if (!tape) continue; // did not compile: the checker has said why
            EffectField e;
            e.kind = t.kind;
            e.tape = *tape;
            e.componentBox = {t.domainMin, t.domainMax};
            e.timing = clock.timing(*t.node);
            e.readsTime = tape->usesInput[std::size_t(formula::Input::T)];
            e.location = scene.locationOf(*t.node);
            shape.surface = shape.surface || t.kind == scene::TangibleKind::Friction ||
                            t.kind == scene::TangibleKind::Tension;
            shape.effects.push_back(std::move(e));
        }
        if (shape.effects.empty()) continue;
        if (!shape.field) {
            // A parametric solid has no f to sign: its inside is its domain box.
            out.notes.push_back(s.name +
                                ": a parametric solid: its density and force act in its "
                                "domain box" +
                                (shape.surface ? "; its surface needs polygon contact, not "
                                                 "rendered yet"
                                               : ""));
            shape.surface = false;
        }
        out.geometryVaries = out.geometryVaries || (entry.timeVarying & scene::kGeometry) ||
                             (entry.timeVarying & scene::kDisplacement) ||
                             (entry.timeVarying & scene::kTransform);
        out.shapes.push_back(std::move(shape));
    }
    for (const scene::PlanEntry& e : plan.entries)
        if (e.node && !e.tangible.empty() && !placed.count(e.node))
            out.notes.push_back(e.name + " (" + e.location + "): " +
                                (e.appliesToSiblings
                                     ? "lends its physics to standard shapes: polygon contact is "
                                       "not rendered yet"
                                     : "not shown at this moment"));
    return out;
}

TangibleScene makeTangibleScene(const scene::Scene& scene, double sceneSeconds) {
    const std::int64_t ns = animation::secondsToNanoseconds(sceneSeconds);
    const animation::Instant moment{ns, ns, 0};
    animation::Animator clock(scene);
    clock.tick(moment);
    return makeTangibleScene(scene, scene::makeEffectsPlan(scene), clock, moment);
}

} // namespace fl::haptics
