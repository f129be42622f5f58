// Requirements judged over time: morphing (a shown shape's geometry at two
// moments differs), animation (a shown shape's placement differs) and
// colour (a function colour that varies over the shape or in time).
// Constant factors do not count: the checks compare what is shown.
#include "checks.h"

#include "scene/field_access.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace fl::grading {
namespace {

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", s);
    return buf;
}

const mesh::ShapeMesh* sameShape(const mesh::SceneMeshes& frame, const mesh::ShapeMesh& s) {
    for (const mesh::ShapeMesh& o : frame.shapes)
        if (o.shape == s.shape && o.geometry == s.geometry) return &o;
    return nullptr;
}

const scene::Node* functionMaterial(const mesh::ShapeMesh& s) {
    if (!s.shape) return nullptr;
    const scene::Node* appearance = scene::effectiveNode(scene::nodeField(*s.shape, "appearance"));
    const scene::Node* material =
        appearance ? scene::effectiveNode(scene::nodeField(*appearance, "material")) : nullptr;
    return material && material->type == "FMaterial" ? material : nullptr;
}

float colourSpread(const mesh::Mesh& m) {
    if (m.colours.empty()) return 0;
    float spread = 0;
    for (const auto& c : m.colours)
        for (std::size_t k = 0; k < 3; ++k)
            spread = std::max(spread, std::abs(c[k] - m.colours.front()[k]));
    return spread;
}

} // namespace

RequirementResult checkMorphing(const SubmissionView& view, const Requirement& r, Budget& budget) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const auto& frames = view.frames();
    for (const mesh::ShapeMesh& s : frames.front().shapes) {
        if (!s.field || !SubmissionView::visible(s)) continue;
        for (std::size_t i = 1; i < frames.size(); ++i) {
            const mesh::ShapeMesh* later = sameShape(frames[i], s);
            if (!later || !later->field || identicalFields(*s.field, *later->field)) continue;
            if (!(later->field->box.lo == s.field->box.lo &&
                  later->field->box.hi == s.field->box.hi))
                continue;
            // One shape into another: a witness at 1/64 of the box is enough;
            // deeper, two equal shapes would cost the whole budget to prove so.
            CompareOptions coarse;
            coarse.maxDepth = 6;
            const SolidComparison c =
                compareSolids(*s.field, *later->field, nullptr, budget, coarse);
            if (c.result != Sameness::Different) continue;
            out.met = true;
            out.points = r.points;
            out.evidence = SubmissionView::nameOf(*s.shape) + ": its geometry at " +
                           seconds(view.moments()[i]) + " differs from the one at " +
                           seconds(view.moments().front()) + " (e.g. near (" +
                           std::to_string(c.witness[0]) + ", " + std::to_string(c.witness[1]) +
                           ", " + std::to_string(c.witness[2]) + "))";
            out.locations.push_back(view.locationOf(*s.shape));
            return out;
        }
    }
    out.evidence = frames.size() < 2
                       ? "nothing in the scene changes with time: morph a shape with t (e.g. an "
                         "FTransform with operation \"morph\" and morphFactor \"0.5 - "
                         "0.5*cos(2*pi*t)\")"
                       : "no shown shape's geometry changes with time: a definition that reads t "
                         "must change the solid, not only a constant factor";
    return out;
}

RequirementResult checkAnimation(const SubmissionView& view, const Requirement& r) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const auto& frames = view.frames();
    for (const mesh::ShapeMesh& s : frames.front().shapes) {
        if (!s.shape || !SubmissionView::visible(s)) continue;
        for (std::size_t i = 1; i < frames.size(); ++i) {
            const mesh::ShapeMesh* later = sameShape(frames[i], s);
            if (!later) continue;
            double moved = 0;
            for (std::size_t k = 0; k < 16; ++k)
                moved = std::max(moved, std::abs(later->placement[k] - s.placement[k]));
            if (!(moved > 1e-9)) continue;
            out.met = true;
            out.points = r.points;
            out.evidence = SubmissionView::nameOf(*s.shape) + " is placed differently at " +
                           seconds(view.moments()[i]) + " than at " +
                           seconds(view.moments().front());
            out.locations.push_back(view.locationOf(*s.shape));
            return out;
        }
    }
    out.evidence = "nothing shown moves, turns or scales with time: give an FTransform a "
                   "translation, rotation or scale that reads t, or route a TimeSensor through "
                   "an interpolator to a Transform";
    return out;
}

RequirementResult checkFunctionColour(const SubmissionView& view, const Requirement& r) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const auto& frames = view.frames();
    std::string constant; // a function colour that does not vary
    for (const mesh::ShapeMesh& s : frames.front().shapes) {
        const scene::Node* material = functionMaterial(s);
        if (!material || !SubmissionView::visible(s) || s.mesh.colours.empty()) continue;
        bool varies = colourSpread(s.mesh) > 1e-4f;
        std::string how = "over the shape";
        for (std::size_t i = 1; i < frames.size() && !varies; ++i) {
            const mesh::ShapeMesh* later = sameShape(frames[i], s);
            if (later && later->mesh.colours.size() == s.mesh.colours.size())
                for (std::size_t v = 0; v < s.mesh.colours.size() && !varies; ++v)
                    for (std::size_t k = 0; k < 3; ++k)
                        if (std::abs(later->mesh.colours[v][k] - s.mesh.colours[v][k]) > 1e-4f) {
                            varies = true;
                            how = "in time (between " + seconds(view.moments().front()) + " and " +
                                  seconds(view.moments()[i]) + ")";
                        }
        }
        if (!varies) {
            if (constant.empty())
                constant = SubmissionView::nameOf(*material) + " at line " +
                           std::to_string(material->where.line) +
                           " gives one colour everywhere and always";
            continue;
        }
        out.met = true;
        out.points = r.points;
        out.evidence = SubmissionView::nameOf(*s.shape) + ": its FMaterial colour varies " + how;
        out.locations.push_back(view.locationOf(*material, "definition"));
        return out;
    }
    out.evidence = constant.empty()
                       ? "no shown shape has a colour defined by a function: give one an "
                         "FMaterial whose definition reads x, y, z, u, v, w or t"
                       : constant + ": its definition must depend on the point or on t";
    return out;
}

} // namespace fl::grading
