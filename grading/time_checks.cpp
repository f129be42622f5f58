// Requirements judged over time: morphing (a shown shape's geometry at two
// moments differs), animation (a shown shape's placement differs) and
// colour (a function colour that varies over the shape or in time).
// Constant factors do not count: the checks compare what is shown.
#include "checks.h"
#include "shape_samples.h"

#include "mesh/colouring.h"

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

// The FMaterial that colours the shape by a formula: the appearance it was
// drawn with (an FTransform's combined shape takes its first child's), and a
// definition the scene compiled — a plain FMaterial gives no colour function.
const scene::Node* functionMaterial(const SubmissionView& view, const mesh::ShapeMesh& s) {
    const scene::Node* material =
        s.appearance ? scene::effectiveNode(scene::nodeField(*s.appearance, "material")) : nullptr;
    if (!material || material->kind() != scene::NodeKind::FMaterial) return nullptr;
    return view.scene().definition(*material, "definition") ? material : nullptr;
}

// How far the colours stray from the first one (0 for none).
float colourSpread(const std::vector<std::array<float, 4>>& colours) {
    if (colours.empty()) return 0;
    float spread = 0;
    for (const auto& c : colours)
        for (std::size_t k = 0; k < 3; ++k)
            spread = std::max(spread, std::abs(c[k] - colours.front()[k]));
    return spread;
}

} // namespace

RequirementResult checkMorphing(const SubmissionView& view, const Requirement& r, Budget& budget) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const auto& frames = view.frames();
    for (const auto [first, shape] : view.firstShown()) {
        const mesh::ShapeMesh& s = *shape;
        if (!s.field) continue;
        for (std::size_t i = first + 1; i < frames.size(); ++i) {
            const mesh::ShapeMesh* later = view.shownAt(i, s);
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
                           seconds(view.moments()[first]) + " (e.g. near (" +
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
    for (const auto [first, shape] : view.firstShown()) {
        const mesh::ShapeMesh& s = *shape;
        if (!s.shape) continue;
        for (std::size_t i = first + 1; i < frames.size(); ++i) {
            const mesh::ShapeMesh* later = view.shownAt(i, s);
            if (!later) continue;
            double moved = 0;
            for (std::size_t k = 0; k < 16; ++k)
                moved = std::max(moved, std::abs(later->placement[k] - s.placement[k]));
            if (!(moved > 1e-9)) continue;
            out.met = true;
            out.points = r.points;
            out.evidence = SubmissionView::nameOf(*s.shape) + " is placed differently at " +
                           seconds(view.moments()[i]) + " than at " +
                           seconds(view.moments()[first]);
            out.locations.push_back(view.locationOf(*s.shape));
            return out;
        }
    }
    out.evidence = "nothing shown moves, turns or scales with time: give an FTransform a "
                   "translation, rotation or scale that reads t, or route a TimeSensor through "
                   "an interpolator to a Transform";
    return out;
}

// Where a shape's colour is looked at: its mesh's vertices, or — a shape too
// small for the checker's coarse mesh (a ball of radius 0.2 in a box of 2) —
// points inside its field on a finer grid of its box, coloured as the viewer
// colours them.
struct ColourSamples {
    std::vector<mesh::Vec3f> points; // empty: the mesh's own vertices
    std::vector<std::array<float, 4>> colours;
};

std::vector<std::array<float, 4>> coloursAt(const mesh::ShapeMesh& s,
                                            const std::vector<mesh::Vec3f>& points) {
    if (points.empty()) return s.mesh.colours;
    if (!s.colourField) return {};
    mesh::Mesh m;
    m.positions = points;
    mesh::applyColour(m, *s.colourField);
    return m.colours;
}

RequirementResult checkFunctionColour(const SubmissionView& view, const Requirement& r,
                                      Budget& budget) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const auto& frames = view.frames();
    std::string constant; // a function colour that does not vary
    std::string onlyInTime;
    for (const auto [first, shape] : view.firstShown()) {
        const mesh::ShapeMesh& s = *shape;
        const scene::Node* material = functionMaterial(view, s);
        if (!material) continue;
        std::vector<mesh::Vec3f> points; // none: the mesh's vertices
        if (s.mesh.colours.empty() && s.field && s.colourField)
            points = pointsInside(*s.field, budget);
        const auto here = coloursAt(s, points);
        if (here.empty()) continue;
        // Over the shape at some moment it is shown, else between moments.
        std::string overShape = colourSpread(here) > 1e-4f ? "over the shape" : "";
        std::string inTime;
        for (std::size_t i = first + 1; i < frames.size() && overShape.empty(); ++i) {
            const mesh::ShapeMesh* later = view.shownAt(i, s);
            if (!later) continue;
            const auto then = coloursAt(*later, points);
            if (colourSpread(then) > 1e-4f) {
                overShape = "over the shape (at " + seconds(view.moments()[i]) + ")";
                break;
            }
            if (!inTime.empty() || then.size() != here.size()) continue;
            for (std::size_t v = 0; v < here.size() && inTime.empty(); ++v)
                for (std::size_t k = 0; k < 3; ++k)
                    if (std::abs(then[v][k] - here[v][k]) > 1e-4f) {
                        inTime = "in time (between " + seconds(view.moments()[first]) + " and " +
                                 seconds(view.moments()[i]) + ")";
                        break;
                    }
        }
        if (overShape.empty() && !inTime.empty() && r.variesOverShape) {
            // The colour changes with t but is one colour over the shape.
            if (onlyInTime.empty())
                onlyInTime = SubmissionView::nameAndLine(*material) +
                             " changes only in time: at any moment it is one colour over the "
                             "shape";
            continue;
        }
        const std::string how = !overShape.empty() ? overShape : inTime;
        if (how.empty()) {
            if (constant.empty())
                constant =
                    SubmissionView::nameAndLine(*material) + " gives the shape one colour, always";
            continue;
        }
        out.met = true;
        out.points = r.points;
        out.evidence = SubmissionView::nameOf(*s.shape) + ": its FMaterial colour varies " + how;
        out.locations.push_back(view.locationOf(*material, "definition"));
        return out;
    }
    const std::string needed = r.variesOverShape ? "x, y, z, u, v or w" : "x, y, z, u, v, w or t";
    out.evidence = !onlyInTime.empty() ? onlyInTime + ": its definition must depend on the point"
                   : constant.empty()
                       ? "no shown shape has a colour defined by a function: give one an "
                         "FMaterial whose definition reads " +
                             needed
                       : constant + ": its definition must depend on the point" +
                             (r.variesOverShape ? std::string() : std::string(" or on t"));
    return out;
}

} // namespace fl::grading
