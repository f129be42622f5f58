// The tangible requirement: a shown shape you can feel — FPhysics with
// friction, tension, density or a force field, each a compiled function in
// its own domain box (the effects plan lists them, as the haptic loop will).
//
// An effect counts where it can be felt, as the haptic loop feels it: at some
// point of the shown solid, at some moment the checker looks at, friction,
// tension or density above zero, or a force that is not zero. So "0*x", an
// effect on an empty solid (-1 + 0*x), one that is zero wherever the shape is,
// and physics under a zero scale do not count; a standard Box made tangible by
// the FShape without geometry beside it (the paper's way) does.
#include "checks.h"
#include "shape_samples.h"

#include "animation/animator.h"
#include "field/affine.h"
#include "field/domain_mapping.h"
#include "formula/eval_scalar.h"
#include "scene/effects_plan.h"
#include "scene/field_access.h"

#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace fl::grading {

namespace {

// Less than this is not felt (a friction coefficient, a fraction of the
// device's force, a damping fraction, a force in its units).
constexpr double kLeastFelt = 1e-6;
constexpr std::size_t kMostPoints = 64;

bool isFelt(scene::TangibleKind kind, const double* v) {
    if (kind == scene::TangibleKind::Force) {
        bool any = false;
        for (int k = 0; k < 3; ++k) {
            if (!std::isfinite(v[k])) return false;
            any = any || std::abs(v[k]) > kLeastFelt;
        }
        return any;
    }
    return std::isfinite(v[0]) && v[0] > kLeastFelt;
}

// One shown shape with effects, as the haptic loop takes it (haptics/
// tangible_scene.cpp): the points of its solid, in its own coordinates, and
// the frame its effects' domain boxes are mapped from.
struct Touchable {
    const scene::PlanEntry* entry = nullptr; // whose effects: its own, or its lender's
    std::vector<field::Vec3> points;
    field::Box3 geometryBox;
    field::Affine effectFrame; // the shape's coordinates to those of geometryBox
};

// At most kMostPoints of them, evenly picked, in double precision.
std::vector<field::Vec3> spread(const std::vector<mesh::Vec3f>& from) {
    std::vector<field::Vec3> out;
    for (const mesh::Vec3f& p : evenlyPicked(from, kMostPoints))
        out.push_back({p[0], p[1], p[2]});
    return out;
}

// A function shape's own effects: inside its solid (its field's f >= 0), or
// for a parametric solid on its surface (its mesh).
std::optional<Touchable> ownEffects(const mesh::ShapeMesh& s, const scene::PlanEntry& entry,
                                    Budget& budget) {
    Touchable t;
    t.entry = &entry;
    if (s.field) {
        t.points = spread(pointsInside(*s.field, budget, kMostPoints));
        t.geometryBox = s.field->box;
    } else if (s.functionGeometry) {
        t.points = spread(s.mesh.positions);
        t.geometryBox = s.domain;
    }
    if (t.points.empty()) return std::nullopt; // an empty solid, or not a function shape
    return t;
}

// A standard shape felt through the physics its group's FShape lends it:
// its vertices, taken into the lender's frame and box.
std::optional<Touchable> lentEffects(const mesh::SceneMeshes& frame, const mesh::ShapeMesh& s,
                                     const scene::PlanEntry& lender) {
    if (s.mesh.positions.empty()) return std::nullopt;
    field::Affine lenderToScene;
    for (const mesh::SceneMeshes::Lender& l : frame.lenders)
        if (l.shape == lender.node) lenderToScene = field::Affine::fromMatrix(l.placement);
    const auto sceneToLender = lenderToScene.inverse();
    if (!sceneToLender) return std::nullopt;
    Touchable t;
    t.entry = &lender;
    t.points = spread(s.mesh.positions);
    t.effectFrame = *sceneToLender * field::Affine::fromMatrix(s.placement);
    t.geometryBox =
        mesh::boundingBoxOf(*lender.node)
            .value_or(field::boundsOf(mesh::pointBounds(s.mesh.positions), t.effectFrame));
    return t;
}

// Every scene second the view judges, as the one clock gives each function
// node its t: a clock per moment, made when an effect reads t.
class EffectTime {
  public:
    explicit EffectTime(const SubmissionView& view) : view_(view) {}
    double at(std::size_t moment, const scene::Node& effect) {
        auto& clock = clocks_[moment];
        if (!clock) {
            clock = std::make_unique<animation::Animator>(view_.scene());
            clock->tick(instant(moment));
        }
        return clock->timing(effect).at(instant(moment));
    }

  private:
    animation::Instant instant(std::size_t moment) const {
        mesh::SceneMeshOptions o;
        o.sceneSeconds = view_.moments()[moment];
        return mesh::momentOf(o);
    }
    const SubmissionView& view_;
    std::map<std::size_t, std::unique_ptr<animation::Animator>> clocks_;
};

// Is the effect felt at one of the shape's points at this moment?
bool feltOn(const Touchable& shape, const scene::TangibleEffect& effect, const formula::Tape& tape,
            double t, Budget& budget) {
    formula::ScalarEvaluator evaluator(tape);
    const field::Box3 component{effect.domainMin, effect.domainMax};
    double values[3] = {0, 0, 0};
    for (const field::Vec3& p : shape.points) {
        if (!budget.spend(tape.code.size() + 1)) return false;
        const auto v =
            field::componentView(shape.effectFrame.point(p), shape.geometryBox, component);
        evaluator.evaluateAll({v[0], v[1], v[2], t, v[3], v[4], v[5]}, values);
        if (isFelt(effect.kind, values)) return true;
    }
    return false;
}

struct Felt {
    const scene::Node* lender = nullptr; // the FShape that lends a standard shape its physics
    std::set<scene::TangibleKind> kinds;
    std::vector<Location> where;
};

} // namespace

RequirementResult checkTangible(const SubmissionView& view, const Requirement& r, Budget& budget) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const scene::EffectsPlan plan = scene::makeEffectsPlan(view.scene());
    std::map<const scene::Node*, const scene::PlanEntry*> own;
    for (const scene::PlanEntry& e : plan.entries)
        if (e.node && !e.tangible.empty() && !e.appliesToSiblings) own[e.node] = &e;
    const auto lent = scene::lentPhysics(view.scene(), plan);
    EffectTime time(view);

    // Per shape (its node), the kinds felt at any moment.
    std::map<const scene::Node*, Felt> felt;
    std::set<const scene::Node*> written; // effects written for a shown shape, felt or not
    std::string emptySolid;
    for (std::size_t i = 0; i < view.frames().size(); ++i) {
        const mesh::SceneMeshes& frame = view.frames()[i];
        for (const mesh::ShapeMesh& s : frame.shapes) {
            if (!s.shape || !SubmissionView::shown(s)) continue;
            std::optional<Touchable> shape;
            if (const auto b = lent.find(s.shape); b != lent.end())
                shape = lentEffects(frame, s, *b->second);
            else if (const auto o = own.find(s.shape); o != own.end())
                shape = ownEffects(s, *o->second, budget);
            else
                continue;
            if (!shape) {
                if (emptySolid.empty() && s.field)
                    emptySolid = SubmissionView::nameOf(*s.shape) +
                                 " has physics, but its solid is empty (f >= 0 nowhere in its "
                                 "box): there is nothing to feel";
                continue;
            }
            Felt& f = felt[s.shape];
            if (shape->entry->node != s.shape) f.lender = shape->entry->node;
            for (const scene::TangibleEffect& e : shape->entry->tangible) {
                if (!e.node || f.kinds.count(e.kind)) continue;
                const formula::Tape* tape = view.scene().definition(*e.node, "definition");
                if (!tape) continue; // it did not compile: the scene's check says why
                written.insert(s.shape);
                const double t = e.timeVarying ? time.at(i, *e.node) : 0;
                if (!feltOn(*shape, e, *tape, t, budget)) continue;
                f.kinds.insert(e.kind);
                f.where.push_back(view.locationOf(*e.node, "definition"));
            }
        }
    }

    const scene::Node* best = nullptr;
    const Felt* bestFelt = nullptr;
    for (const auto& [node, f] : felt)
        if (!bestFelt || f.kinds.size() > bestFelt->kinds.size()) {
            best = node;
            bestFelt = &f;
        }
    const std::size_t bestKinds = bestFelt ? bestFelt->kinds.size() : 0;
    out.met = bestKinds > 0 && int(bestKinds) >= r.minimum;
    out.points = out.met ? r.points : 0;
    if (bestKinds > 0) {
        const Felt& f = *bestFelt;
        std::string names;
        for (scene::TangibleKind k : f.kinds)
            names += (names.empty() ? "" : ", ") + std::string(scene::tangibleKindName(k));
        out.locations = f.where;
        const std::string what =
            SubmissionView::nameOf(*best) +
            (f.lender ? " (physics lent by " + SubmissionView::nameAndLine(*f.lender) + ")" : "") +
            ": " + names;
        out.evidence = out.met
                           ? what + " — felt through its FPhysics"
                           : what + ": " + std::to_string(bestKinds) + " kind(s) of effect felt; " +
                                 std::to_string(r.minimum) + " are needed";
    } else if (!emptySolid.empty() && written.empty()) {
        out.evidence = emptySolid;
    } else if (!written.empty()) {
        out.evidence = "no effect can be felt on a shown shape: each is zero (or less) "
                       "wherever the shape's solid is — give friction, tension or density a "
                       "value above 0, or a force that is not 0, where the shape is";
    } else {
        out.evidence = "no shown shape is tangible: give an FShape an FPhysics with "
                       "FFriction, FTension, FDensity or FForce, each with a definition";
    }
    if (budget.exceeded && !out.met) ++budget.cutShort;
    return out;
}

} // namespace fl::grading
