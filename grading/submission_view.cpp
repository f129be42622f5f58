#include "submission_view.h"

#include "field/affine.h"
#include "scene/effects_plan.h"
#include "scene/field_access.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace fl::grading {

namespace {
// A shape placed smaller than this (scene units, its box's diagonal), or
// whose placement shrinks volumes by more than this factor, is not shown.
constexpr double kLeastPlacedSize = 1e-3;
constexpr double kLeastPlacedVolumeScale = 1e-12;
} // namespace

double longestCycle(const scene::Scene& scene) {
    double longest = 0;
    for (const scene::Scene* s : scene::scenesShownBy(scene))
        s->forEachNode([&](const scene::Node& n) {
            if (n.inProtoBody || !n.field("cycleInterval")) return;
            const double c = scene::numberField(n, "cycleInterval");
            if (std::isfinite(c)) longest = std::max(longest, c);
        });
    return std::clamp(longest, 0.0, 600.0);
}

SubmissionView::SubmissionView(const scene::Scene& scene, int moments)
    : scene_(scene), lines_(scene) {
    const scene::EffectsPlan plan = scene::makeEffectsPlan(scene);
    const double cycle = longestCycle(scene);
    const double span = cycle > 0 ? cycle : 1;
    const int count = plan.timeVarying == scene::kStatic ? 1 : std::max(2, moments);
    for (int i = 0; i < count; ++i)
        // Evenly over the cycle, the end left out (a loop's end is its start).
        moments_.push_back(span * i / count);
    for (double seconds : moments_) {
        mesh::SceneMeshOptions o;
        o.sceneSeconds = seconds;
        o.placeInScene = false; // placements say what moves
        o.useFileResolution = false;
        o.mesh.resolution = 6; // the checker samples fields; meshes only carry colours
        o.mesh.threads = 1;    // one core per submission, the same answer every time
        o.segments = 8;
        frames_.push_back(mesh::meshScene(scene, o));
    }
}

bool SubmissionView::visible(const mesh::ShapeMesh& shape) {
    if (!shape.error.empty()) return false;
    const bool tangible = shape.shape && shape.shape->field("physics") &&
                          scene::effectiveNode(scene::nodeField(*shape.shape, "physics"));
    if (tangible || shape.mesh.colours.empty()) return true;
    return std::any_of(shape.mesh.colours.begin(), shape.mesh.colours.end(),
                       [](const auto& c) { return c[3] > 0; });
}

bool SubmissionView::shown(const mesh::ShapeMesh& shape) {
    if (!visible(shape)) return false;
    // The placement takes shape coordinates to the scene's.
    const field::Affine placement = field::Affine::fromMatrix(shape.placement);
    const double det = placement.determinant();
    if (!std::isfinite(det) || std::abs(det) < kLeastPlacedVolumeScale) return false;
    // Its size as placed: its box (its field's, else its mesh's) through the
    // placement.
    field::Box3 box;
    if (shape.field)
        box = shape.field->box;
    else if (!shape.mesh.positions.empty())
        box = mesh::pointBounds(shape.mesh.positions);
    else
        return true; // nothing to measure (a tangible shape without a mesh): placed as it is
    const field::Box3 placed = field::boundsOf(box, placement);
    return field::length(field::minus(placed.hi, placed.lo)) >= kLeastPlacedSize;
}

std::vector<SubmissionView::FirstShown> SubmissionView::firstShown() const {
    std::vector<FirstShown> out;
    std::set<std::pair<const scene::Node*, const scene::Node*>> seen;
    for (std::size_t i = 0; i < frames_.size(); ++i)
        for (const mesh::ShapeMesh& s : frames_[i].shapes)
            if (shown(s) && seen.insert({s.shape, s.geometry}).second) out.push_back({i, &s});
    return out;
}

const mesh::ShapeMesh* SubmissionView::shownAt(std::size_t moment,
                                               const mesh::ShapeMesh& shape) const {
    if (moment >= frames_.size()) return nullptr;
    for (const mesh::ShapeMesh& o : frames_[moment].shapes)
        if (o.shape == shape.shape && o.geometry == shape.geometry) return shown(o) ? &o : nullptr;
    return nullptr;
}

Location SubmissionView::locationOf(const scene::Node& node) const {
    return {scene_.pathOf(node.file), node.where.line, node.where.column};
}

Location SubmissionView::locationOf(const scene::Node& node, std::string_view name) const {
    const scene::Field* f = node.field(name);
    if (!f) return locationOf(node);
    return {scene_.pathOf(f->file >= 0 ? f->file : node.file), f->where.line, f->where.column};
}

const mesh::DefinitionText* SubmissionView::textSource(const mesh::ShapeMesh& shape,
                                                       std::int32_t origin) const {
    if (!shape.field || origin < 0 || std::size_t(origin) >= shape.field->tape.origins.size())
        return nullptr;
    const int source = shape.field->tape.origins[std::size_t(origin)].source;
    if (source < 0 || std::size_t(source) >= shape.texts.size()) return nullptr;
    return &shape.texts[std::size_t(source)];
}

Location SubmissionView::locationOf(const mesh::ShapeMesh& shape, std::int32_t origin,
                                    std::size_t within) const {
    const mesh::DefinitionText* text = textSource(shape, origin);
    if (!text || !text->node) return shape.shape ? locationOf(*shape.shape) : Location{};
    const scene::Field* field = text->node->field(text->field);
    if (!field || field->value.strings.empty()) return locationOf(*text->node, text->field);
    const formula::SourceRange& r = shape.field->tape.origins[std::size_t(origin)];
    const scene::FilePos pos = scene::formulaTextPosition(
        *field, std::min(r.begin.offset + within, std::max(r.end.offset, r.begin.offset)), lines_);
    const int file =
        field->value.stringOrigins.empty() ? field->file : field->value.stringOrigins.front().file;
    return {scene_.pathOf(file >= 0 ? file : text->node->file), pos.line, pos.column};
}

std::string SubmissionView::textOf(const mesh::ShapeMesh& shape, std::int32_t origin) const {
    const mesh::DefinitionText* text = textSource(shape, origin);
    if (!text || !text->node) return {};
    const scene::Field* field = text->node->field(text->field);
    if (!field || field->value.strings.empty()) return {};
    const std::string source = scene::formulaText(*field);
    const formula::SourceRange& r = shape.field->tape.origins[std::size_t(origin)];
    if (r.begin.offset >= source.size() || r.end.offset <= r.begin.offset) return {};
    return source.substr(r.begin.offset, std::min(r.end.offset, source.size()) - r.begin.offset);
}

std::string SubmissionView::nameOf(const scene::Node& node) {
    if (!node.defName.empty()) return node.type + " " + node.defName;
    return "the " + node.type + " at line " + std::to_string(node.where.line);
}

std::string SubmissionView::nameAndLine(const scene::Node& node) {
    if (node.defName.empty()) return nameOf(node);
    return nameOf(node) + " at line " + std::to_string(node.where.line);
}

std::string shortened(std::string text, std::size_t limit) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    // Collapse runs of spaces a multi-line definition leaves.
    text.erase(
        std::unique(text.begin(), text.end(), [](char a, char b) { return a == ' ' && b == ' '; }),
        text.end());
    if (text.size() > limit) text = text.substr(0, limit - 3) + "...";
    return text;
}

} // namespace fl::grading
