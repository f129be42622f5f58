#include "tangible_scene.h"

#include "mesh/scene_meshing.h"
#include "scene/field_access.h"

#include <optional>
#include <unordered_map>

namespace fl::haptics {

const EffectField* TangibleShape::effect(scene::TangibleKind kind) const {
    for (const EffectField& e : effects)
        if (e.kind == kind) return &e;
    return nullptr;
}

namespace {

// Touched by its triangles: an FGeometry with collision "polygonal", and
// every PDE surface (it has no function of the point to push against).
bool polygonal(const scene::Node* geometry) {
    return geometry && ((geometry->kind() == scene::NodeKind::FGeometry &&
                         scene::stringField(*geometry, "collision") == "polygonal") ||
                        geometry->kind() == scene::NodeKind::FPdeSurface);
}

// The shapes as the viewer meshes them: the same walk, the same clock. Function
// shapes felt by their function need no triangles worth the name (resolution
// 4: only their fields are kept); those with collision "polygonal" are meshed
// at their own resolution, and standard shapes as the viewer draws them.
mesh::SceneMeshes shapesAt(const scene::Scene& scene, const scene::EffectsPlan& plan,
                           const animation::Animator& clock, const animation::Instant& moment) {
    mesh::SceneMeshOptions o;
    o.animator = &clock;
    o.instant = moment;
    o.useFileResolution = false;
    o.mesh.resolution = 4;
    o.mesh.threads = 1;
    o.placeInScene = false;
    for (const scene::PlanEntry& e : plan.entries) {
        if (!e.node || e.tangible.empty()) continue;
        const scene::Node* g = scene::effectiveNode(clock.node(*e.node, "geometry"));
        if (polygonal(g)) o.resolutions[g] = scene::numberField(*g, "resolution", 0, 32);
    }
    return mesh::meshScene(scene, o);
}

EffectField effectOf(const scene::Scene& scene, const animation::Animator& clock,
                     const scene::TangibleEffect& t, const formula::Tape& tape) {
    EffectField e;
    e.kind = t.kind;
    e.tape = tape;
    e.componentBox = {t.domainMin, t.domainMax};
    e.timing = clock.timing(*t.node);
    e.readsTime = tape.usesInput[std::size_t(formula::Input::T)];
    e.location = scene.locationOf(*t.node);
    return e;
}

// Where a lending FShape stands (the meshing walk says), else the scene's frame.
field::Affine lenderPlacement(const mesh::SceneMeshes& meshes, const scene::Node* lender) {
    for (const mesh::SceneMeshes::Lender& l : meshes.lenders)
        if (l.shape == lender) return field::Affine::fromMatrix(l.placement);
    return {};
}

bool isSurfaceKind(scene::TangibleKind k) {
    return k == scene::TangibleKind::Friction || k == scene::TangibleKind::Tension;
}

} // namespace

namespace {

// A standard shape felt through the physics its group's FShape lends it.
std::optional<TangibleShape> borrowing(const scene::Scene& scene, const animation::Animator& clock,
                                       const mesh::ShapeMesh& s, const scene::PlanEntry& lender,
                                       const field::Affine& lenderToScene) {
    const field::Affine toScene = field::Affine::fromMatrix(s.placement);
    const auto toShape = toScene.inverse();
    if (!toShape) return std::nullopt;
    TangibleShape shape;
    shape.name = s.name;
    shape.shape = s.shape;
    shape.toScene = toScene;
    shape.toShape = *toShape;
    auto bvh = std::make_shared<const TriangleBvh>(s.mesh);
    shape.container = bvh->bounds();
    shape.triangles = std::move(bvh);
    // The lender's box, in the lender's own coordinates (those of its group):
    // this shape's point taken there.
    const auto sceneToLender = lenderToScene.inverse();
    if (!sceneToLender) return std::nullopt;
    shape.effectFrame = *sceneToLender * toScene;
    shape.geometryBox = mesh::boundingBoxOf(*lender.node)
                            .value_or(field::boundsOf(shape.container, shape.effectFrame));
    for (const scene::TangibleEffect& t : lender.tangible)
        if (t.node)
            if (const formula::Tape* tape = scene.definition(*t.node, "definition")) {
                shape.effects.push_back(effectOf(scene, clock, t, *tape));
                shape.surface = shape.surface || isSurfaceKind(t.kind);
            }
    if (shape.effects.empty()) return std::nullopt;
    return shape;
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
    const mesh::SceneMeshes meshes = shapesAt(scene, plan, clock, moment);
    const auto lent = scene::lentPhysics(scene, plan);
    std::unordered_map<const scene::Node*, bool> placed;
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        // A standard shape that borrows its group's physics: felt by its triangles.
        if (const auto b = lent.find(s.shape); b != lent.end()) {
            if (s.error.empty() && !s.mesh.isPointCloud() && !s.mesh.isLines() &&
                s.mesh.triangleCount() > 0)
                if (auto shape = borrowing(scene, clock, s, *b->second,
                                           lenderPlacement(meshes, b->second->node))) {
                    placed[b->second->node] = true;
                    out.geometryVaries =
                        out.geometryVaries || (b->second->timeVarying & scene::kTransform);
                    out.shapes.push_back(std::move(*shape));
                }
            continue;
        }
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
        shape.geometryBox = shape.container;
        if (polygonal(s.geometry) && !s.mesh.isPointCloud() && s.mesh.triangleCount() > 0)
            shape.triangles = std::make_shared<const TriangleBvh>(s.mesh);
        shape.toScene = toScene;
        shape.toShape = *toShape;
        for (const scene::TangibleEffect& t : entry.tangible) {
            if (!t.node) continue;
            const formula::Tape* tape = scene.definition(*t.node, "definition");
            if (!tape) continue; // did not compile: the checker has said why
            shape.surface = shape.surface || isSurfaceKind(t.kind);
            shape.effects.push_back(effectOf(scene, clock, t, *tape));
        }
        if (shape.effects.empty()) continue;
        if (!shape.field && !shape.triangles) {
            // A parametric solid has no f to sign: without its triangles
            // (collision "polygonal") its inside is its domain box.
            out.notes.push_back(s.name + ": a parametric solid without collision \"polygonal\": "
                                         "its density and force act in its domain box, and its "
                                         "surface is not felt");
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
                                     ? "lends its physics, but no standard shape is grouped with it"
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
