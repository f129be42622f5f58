// Shape kinds: a shown implicit surface, explicit solid or parametric object
// — one that really shows something in its box — and continuous level of
// detail.
#include "checks.h"

#include "scene/field_access.h"
#include "scene/function_kinds.h"

#include <cmath>
#include <cstdio>

namespace fl::grading {
namespace {

using scene::GeometryType;

// Continuous level of detail counts when the finest resolution is at least
// this many times the coarsest (docs/grading.md).
constexpr double kLodRatio = 2;

std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// An FTransform's set operation (union, difference, morph ...) over its
// children: meshed as one solid f >= 0.
bool isComposite(const mesh::ShapeMesh& s) {
    return !s.geometry && s.field && s.shape && s.shape->kind() == scene::NodeKind::FTransform;
}

bool isPdeSurface(const mesh::ShapeMesh& s) {
    return s.geometry && s.geometry->kind() == scene::NodeKind::FPdeSurface;
}

// Where a PDE shape's model comes from, for evidence: its first url, or
// "a model carried in the scene" for a data: url (base64 is no evidence).
std::string pdeSource(const mesh::ShapeMesh& s) {
    const auto urls = scene::stringsField(*s.geometry, "url");
    if (urls.empty()) return "?";
    return urls.front().rfind("data:", 0) == 0 ? "a model carried in the scene"
                                               : shortened(urls.front());
}

std::optional<GeometryType> typeOf(const mesh::ShapeMesh& s) {
    if (isComposite(s)) return GeometryType::Explicit;
    // PDE patches are parametric functions of u and v (docs/pde.md).
    if (isPdeSurface(s)) return GeometryType::Parametric;
    if (!s.geometry || s.geometry->kind() != scene::NodeKind::FGeometry) return std::nullopt;
    return scene::geometryTypeNamed(scene::stringField(*s.geometry, "type"));
}

// Signs of f on a 9 x 9 x 9 grid of its box: (some inside, some outside).
std::pair<bool, bool> signsOf(const field::ImplicitField& f, Budget& budget) {
    field::ImplicitField open = f;
    open.boundary = field::BoxBoundary::Open;
    field::FieldSampler s(open);
    bool in = false, out = false;
    constexpr int n = 9;
    for (int i = 0; i < n && !(in && out); ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                if (!budget.spend(cost(f))) return {in, out};
                const field::Vec3 p{f.box.lo[0] + f.box.size(0) * (i + 0.5) / n,
                                    f.box.lo[1] + f.box.size(1) * (j + 0.5) / n,
                                    f.box.lo[2] + f.box.size(2) * (k + 0.5) / n};
                const double v = s.value(p);
                if (!std::isfinite(v)) continue;
                (v > 0 ? in : out) = true;
            }
    return {in, out};
}

std::string definitionOf(const mesh::ShapeMesh& s) {
    if (!s.geometry) return {};
    const scene::Field* f = s.geometry->field("definition");
    return f ? shortened(scene::formulaText(*f)) : std::string{};
}

} // namespace

RequirementResult checkShapeKind(const SubmissionView& view, const Requirement& r, Budget& budget) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const GeometryType wanted = r.kind == RequirementKind::ImplicitSurface ? GeometryType::Implicit
                                : r.kind == RequirementKind::ExplicitSolid
                                    ? GeometryType::Explicit
                                    : GeometryType::Parametric;
    std::string near; // a shape of the kind that shows nothing
    for (const mesh::SceneMeshes& frame : view.frames())
        for (const mesh::ShapeMesh& s : frame.shapes) {
            if (typeOf(s) != wanted || !SubmissionView::shown(s)) continue;
            bool shows = false;
            if (wanted == GeometryType::Parametric) {
                shows = !s.mesh.empty();
            } else if (s.field) {
                const auto [in, outside] = signsOf(*s.field, budget);
                // A surface needs both sides; a solid, some inside.
                shows = wanted == GeometryType::Implicit ? in && outside : in;
            }
            const std::string name = SubmissionView::nameOf(*s.shape);
            if (!shows) {
                if (near.empty())
                    near = name + " is " + std::string(scene::geometryTypeName(wanted)) +
                           " but shows nothing in its box: " +
                           (wanted == GeometryType::Implicit   ? "f does not change sign there"
                            : wanted == GeometryType::Explicit ? "f > 0 nowhere there"
                                                               : "it has no points");
                continue;
            }
            out.met = true;
            out.points = r.points;
            if (isComposite(s)) {
                out.evidence = name + ": an explicit solid, the " +
                               scene::stringField(*s.shape, "operation") + " of its children";
                out.locations.push_back(view.locationOf(*s.shape, "operation"));
                return out;
            }
            if (isPdeSurface(s)) {
                out.evidence = name + ": parametric, the PDE patches of " + pdeSource(s);
                out.locations.push_back(view.locationOf(*s.geometry, "url"));
                return out;
            }
            out.evidence = name + ": " + std::string(scene::geometryTypeName(wanted)) + " `" +
                           definitionOf(s) + "`";
            out.locations.push_back(view.locationOf(*s.geometry, "definition"));
            return out;
        }
    const char* what = wanted == GeometryType::Implicit   ? "an implicit surface f(x,y,z,t) = 0"
                       : wanted == GeometryType::Explicit ? "an explicit (FRep) solid f >= 0"
                                                          : "a parametric curve, surface or solid";
    out.evidence = near.empty() ? std::string("no shape shown is ") + what +
                                      ": add an FShape "
                                      "whose FGeometry has type '" +
                                      std::string(scene::geometryTypeName(wanted)) + "'"
                                : near;
    return out;
}

RequirementResult checkPdeSurface(const SubmissionView& view, const Requirement& r) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    std::string near; // an FPdeSurface that shows nothing, and why
    for (const mesh::SceneMeshes& frame : view.frames())
        for (const mesh::ShapeMesh& s : frame.shapes) {
            if (!isPdeSurface(s) || !SubmissionView::shown(s)) continue;
            const std::string name = SubmissionView::nameOf(*s.shape);
            if (s.mesh.empty()) {
                if (near.empty())
                    near = name + " has an FPdeSurface that shows nothing" +
                           (s.error.empty() ? std::string() : ": " + shortened(s.error));
                continue;
            }
            out.met = true;
            out.points = r.points;
            out.evidence = name + ": PDE patches from " + pdeSource(s) + ", " +
                           std::to_string(s.mesh.triangleCount()) + " triangles";
            out.locations.push_back(view.locationOf(*s.geometry, "url"));
            return out;
        }
    out.evidence = near.empty() ? "no FPdeSurface is shown: fit a mesh with `functionlab pde fit "
                                  "MESH.obj -o MODEL.pde` and show it with an FShape whose "
                                  "geometry is an FPdeSurface naming it"
                                : near;
    return out;
}

RequirementResult checkLevelOfDetail(const SubmissionView& view, const Requirement& r) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    const mesh::ShapeMesh* narrow = nullptr; // a range chosen, but one that hardly varies
    for (const auto [moment, shape] : view.firstShown()) {
        const mesh::ShapeMesh& s = *shape;
        // Drawn with level of detail: its own FGeometry's, or for a combined
        // shape its first child's with lod TRUE (ShapeMesh::levelOfDetail).
        const scene::Node* lod = s.levelOfDetail;
        if (!typeOf(s) || !lod) continue;
        // The default (lod TRUE, 8 to 256) is every shape's: the requirement
        // asks that the student chose the range.
        // A range that really varies: the finest at least twice the coarsest
        // (docs/grading.md; the viewer re-meshes at 25% changes).
        const auto range = scene::numbersField(*lod, "lodRange");
        if (!lod->field("lodRange") || range.size() != 2 ||
            !(range[0] > 0 && range[1] >= kLodRatio * range[0])) {
            if (range.size() == 2 && lod->field("lodRange") && !narrow) narrow = &s;
            continue;
        }
        out.met = true;
        out.points = r.points;
        out.evidence = SubmissionView::nameOf(*s.shape) +
                       ": continuous level of detail from resolution " + numberText(range[0]) +
                       " to " + numberText(range[1]);
        out.locations.push_back(view.locationOf(*lod, "lodRange"));
        return out;
    }
    if (narrow) {
        const auto range = scene::numbersField(*narrow->levelOfDetail, "lodRange");
        out.evidence = SubmissionView::nameOf(*narrow->shape) + "'s lodRange " +
                       numberText(range[0]) + " " + numberText(range[1]) +
                       " hardly varies: the finest resolution must be at least twice the "
                       "coarsest (e.g. lodRange 8 128)";
        out.locations.push_back(view.locationOf(*narrow->levelOfDetail, "lodRange"));
        return out;
    }
    out.evidence = "no function shape is drawn with continuous level of detail: set lod TRUE "
                   "and lodRange to the coarsest and finest resolution (e.g. lodRange 8 128)";
    return out;
}

} // namespace fl::grading
