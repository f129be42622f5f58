#pragma once
// A submission as the checker sees it: the scene shown at a few moments by
// the one clock (meshScene decides what is shown — Switch choices, PROTOs
// never instantiated, Inline — and gives each function shape its field
// exactly as drawn), and the way back from a node or an instruction to the
// file, line and column a student wrote it at.
#include "requirement.h"

#include "mesh/scene_meshing.h"
#include "scene/scene.h"
#include "scene/source_map.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fl::grading {

class SubmissionView {
  public:
    // `moments`: how many moments of the scene's time are judged (evenly
    // over its longest cycle; one when nothing varies with time).
    SubmissionView(const scene::Scene& scene, int moments = 9);

    const scene::Scene& scene() const { return scene_; }
    const std::vector<double>& moments() const { return moments_; } // scene seconds
    const std::vector<mesh::SceneMeshes>& frames() const { return frames_; }

    // Is this shape shown at all? Fully transparent and without physics: no.
    static bool visible(const mesh::ShapeMesh& shape);
    // Visible, and placed where it can be seen: not under a scale of zero,
    // nor flattened, nor shrunk below a thousandth of a unit (docs/grading.md,
    // "What shown means"). Every check counts only what is shown.
    static bool shown(const mesh::ShapeMesh& shape);

    // Each shape once (its FShape and geometry), at the first judged moment
    // it is shown: a shape hidden at t = 0 (grown from a scale of zero) is
    // judged from the moment it appears.
    struct FirstShown {
        std::size_t moment = 0; // index into frames() and moments()
        const mesh::ShapeMesh* shape = nullptr;
    };
    std::vector<FirstShown> firstShown() const;
    // The same shape at another moment, when it is shown then (else null).
    const mesh::ShapeMesh* shownAt(std::size_t moment, const mesh::ShapeMesh& shape) const;

    Location locationOf(const scene::Node& node) const;
    Location locationOf(const scene::Node& node, std::string_view field) const;
    // An instruction of a shape's field: where its text was written, and the text.
    // `within`: that many bytes into the instruction's text (an operator
    // inside its expression).
    Location locationOf(const mesh::ShapeMesh& shape, std::int32_t origin,
                        std::size_t within = 0) const;
    std::string textOf(const mesh::ShapeMesh& shape, std::int32_t origin) const;
    // The text a field's instruction came from (ShapeMesh::texts), or null.
    const mesh::DefinitionText* textSource(const mesh::ShapeMesh& shape, std::int32_t origin) const;
    // "FShape BALL" or "the FShape at line 12".
    static std::string nameOf(const scene::Node& node);
    // "FMaterial M at line 10", or "the FMaterial at line 10": the line once.
    static std::string nameAndLine(const scene::Node& node);

  private:
    const scene::Scene& scene_;
    std::vector<double> moments_;
    std::vector<mesh::SceneMeshes> frames_;
    mutable scene::LineIndexes lines_;
};

// The longest cycleInterval of anything timed in the scene (0: none), at most
// 600 s: the span of time a checker or a report looks at.
double longestCycle(const scene::Scene& scene);

// A formula shortened for a message: one line, at most `limit` characters.
std::string shortened(std::string text, std::size_t limit = 60);

} // namespace fl::grading
