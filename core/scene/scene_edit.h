#pragma once
// One way to change a scene a person wrote, for every tool that does (the
// classroom's chat commands, the Accuracy panel's "Write into the scene"):
// a set of field changes, each made as an edit of the text where the field
// is written (field_text_edit.h), so comments, layout and every other value
// stay as typed. The edits are kept later offsets first, so applying them in
// order leaves each one's offset valid; two edits at one place keep the
// order they were asked for.
#include "field_text_edit.h"
#include "scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

class SceneEdit {
  public:
    // Edits of files[0] of `scene` (the text it was read from).
    explicit SceneEdit(const Scene& scene) : scene_(scene) {}

    // Each false, with `why`, when the field cannot be edited in the text
    // (the node is not written there: built by code, in an Inline's file,
    // inside a PROTO body or expansion); the edit is then unchanged.
    bool setNumbers(const Node& node, std::string_view field, const std::vector<double>& numbers,
                    std::string* why = nullptr);
    bool setStrings(const Node& node, std::string_view field,
                    const std::vector<std::string>& strings, std::string* why = nullptr);

    bool empty() const { return edits_.empty(); }
    // Later offsets first (apply in this order).
    const std::vector<TextEdit>& edits() const { return edits_; }
    // `text` (the scene's text) with every edit applied.
    std::string appliedTo(std::string_view text) const;

  private:
    void add(TextEdit edit);
    const Scene& scene_;
    std::vector<TextEdit> edits_;
};

// What writing a shape's meshing resolution changes: `resolution`, and with
// lod TRUE the coarsest end of `lodRange` (its finest end kept, at least the
// resolution), so the view is never less accurate than the choice. None, with
// `why`, when the geometry is not written in the text.
std::optional<SceneEdit> resolutionEdit(const Scene& scene, const Node& geometry, double resolution,
                                        std::string* why = nullptr);

} // namespace fl::scene
