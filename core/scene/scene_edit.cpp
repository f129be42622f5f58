#include "scene_edit.h"

#include "field_access.h"
#include "scene_writer.h"

#include <algorithm>

namespace fl::scene {

void SceneEdit::add(TextEdit edit) {
    // Before the first edit at a lower offset: later offsets stay first, and
    // one at an offset already edited comes after those asked for before it.
    const auto at = std::find_if(edits_.begin(), edits_.end(),
                                 [&](const TextEdit& e) { return e.offset < edit.offset; });
    edits_.insert(at, std::move(edit));
}

bool SceneEdit::setNumbers(const Node& node, std::string_view field,
                           const std::vector<double>& numbers, std::string* why) {
    std::string value;
    for (double v : numbers)
        value += (value.empty() ? "" : " ") + formatNumber(v);
    auto e = setNumbersFieldEdit(scene_, node, field, value, why);
    if (!e) return false;
    add(std::move(*e));
    return true;
}

bool SceneEdit::setStrings(const Node& node, std::string_view field,
                           const std::vector<std::string>& strings, std::string* why) {
    auto e = setStringsFieldEdit(scene_, node, field, strings, why);
    if (!e) return false;
    add(std::move(*e));
    return true;
}

std::string SceneEdit::appliedTo(std::string_view text) const {
    std::string out(text);
    for (const TextEdit& e : edits_)
        out = applied(out, e);
    return out;
}

std::optional<SceneEdit> resolutionEdit(const Scene& scene, const Node& geometry, double resolution,
                                        std::string* why) {
    SceneEdit edit(scene);
    if (!edit.setNumbers(geometry, "resolution", {resolution}, why)) return std::nullopt;
    // The chosen accuracy is a floor: the level of detail may refine near
    // the camera (up to the range's finest end), never coarsen below it.
    if (boolField(geometry, "lod")) {
        const auto range = numbersField(geometry, "lodRange");
        const double finest = std::max(range.size() == 2 ? range[1] : 256.0, resolution);
        if (!edit.setNumbers(geometry, "lodRange", {resolution, finest}, why)) return std::nullopt;
    }
    return edit;
}

} // namespace fl::scene
