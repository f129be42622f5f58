// The tangible requirement: a shown shape you can feel — FPhysics with
// friction, tension, density or a force field, each a compiled function in
// its own domain box (the effects plan lists them, as the haptic loop will).
#include "checks.h"

#include "scene/effects_plan.h"

#include <set>

namespace fl::grading {

RequirementResult checkTangible(const SubmissionView& view, const Requirement& r) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const scene::EffectsPlan plan = scene::makeEffectsPlan(view.scene());
    std::set<const scene::Node*> shown;
    for (const mesh::SceneMeshes& frame : view.frames())
        for (const mesh::ShapeMesh& s : frame.shapes)
            if (s.shape && s.error.empty()) shown.insert(s.shape);
    std::string best;
    std::size_t bestKinds = 0;
    for (const scene::PlanEntry& e : plan.entries) {
        if (!e.node || !shown.count(e.node) || e.tangible.empty()) continue;
        std::set<scene::TangibleKind> kinds;
        std::vector<Location> where;
        std::string names;
        for (const scene::TangibleEffect& t : e.tangible) {
            // An effect counts with a definition that compiled.
            if (!t.node || !view.scene().definition(*t.node, "definition")) continue;
            if (kinds.insert(t.kind).second)
                names += (names.empty() ? "" : ", ") + std::string(scene::tangibleKindName(t.kind));
            where.push_back(view.locationOf(*t.node, "definition"));
        }
        if (kinds.size() > bestKinds) {
            bestKinds = kinds.size();
            best = SubmissionView::nameOf(*e.node) + ": " + names;
            out.locations = where;
        }
    }
    out.met = int(bestKinds) >= r.minimum && bestKinds > 0;
    out.points = out.met ? r.points : 0;
    if (out.met) {
        out.evidence = best + " — tangible through its FPhysics";
    } else {
        out.evidence = bestKinds == 0
                           ? "no shown shape is tangible: give an FShape an FPhysics with "
                             "FFriction, FTension, FDensity or FForce, each with a definition"
                           : best + ": " + std::to_string(bestKinds) + " kind(s) of effect; " +
                                 std::to_string(r.minimum) + " are needed";
        if (bestKinds == 0) out.locations.clear();
    }
    return out;
}

} // namespace fl::grading
