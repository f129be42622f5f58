#pragma once
// Where the value of a field comes from. The file gives one answer
// (FileFields); the one clock gives the answer at a moment, after the scene's
// ROUTEs have run (animation::Animator). Code that turns a scene into
// something — meshes, pictures, forces, grades — reads through this seam, so
// the same moment gives the same state whoever asks (DESIGN §3, one clock).
#include "scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

class FieldSource {
  public:
    virtual ~FieldSource() = default;
    // The field's value: set at this moment, else the file's, else the default.
    virtual FieldValue value(const Node& node, std::string_view field) const = 0;
    // True when an event has set a field of `node` (at or before this
    // moment), so its values may differ from the file's. What reads only
    // unset nodes can be kept from one moment to the next: a Box under a
    // turning Transform is tessellated once.
    virtual bool holdsEventValues(const Node& node) const = 0;

    // The same value, read as one kind (as the free functions of field_access.h).
    double number(const Node& node, std::string_view field, std::size_t index = 0,
                  double fallback = 0.0) const;
    std::vector<double> numbers(const Node& node, std::string_view field) const;
    bool flag(const Node& node, std::string_view field) const;
    std::string string(const Node& node, std::string_view field) const;
    std::vector<std::string> strings(const Node& node, std::string_view field) const;
    const Node* node(const Node& node, std::string_view field) const;
    std::vector<const Node*> nodes(const Node& node, std::string_view field) const;
};

// The values written in the file, the catalogue's defaults filled in.
class FileFields final : public FieldSource {
  public:
    FieldValue value(const Node& node, std::string_view field) const override;
    bool holdsEventValues(const Node&) const override { return false; }
};

} // namespace fl::scene
