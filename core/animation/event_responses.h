#pragma once
// What standard nodes do when an event arrives at an input that does more than
// set a field: interpolators and sequencers answer set_fraction with
// value_changed, the event utilities (BooleanFilter, BooleanToggle,
// BooleanTrigger, IntegerTrigger, TimeTrigger) turn one event into another,
// and bindable nodes (viewpoints, NavigationInfo, backgrounds, Fog) answer
// set_bind by moving on their binding stack.
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace fl::animation {

// X3D 7.2.2: each kind of bindable node has its own binding stack; all
// viewpoint types share one, Background and TextureBackground another.
enum class BindableKind : std::uint8_t { Viewpoint, NavigationInfo, Background, Fog };
std::optional<BindableKind> bindableKindOf(scene::NodeKind node);

class ResponseContext {
  public:
    virtual ~ResponseContext() = default;
    virtual scene::FieldValue value(const scene::Node& node, std::string_view field) const = 0;
    virtual void set(const scene::Node& node, std::string_view field,
                     const scene::FieldValue& value) = 0; // store, and send field_changed
    virtual void emit(const scene::Node& node, std::string_view field,
                      const scene::FieldValue& value) = 0;    // an output event
    virtual double nowSeconds() const = 0;                    // X3D time of this timestamp
    virtual int& sequencerIndex(const scene::Node& node) = 0; // the key a sequencer last sent
    // set_bind TRUE (`on`) or FALSE at a bindable node of `kind`.
    virtual void bind(const scene::Node& node, BindableKind kind, bool on) = 0;
};

// True when the node type responds to events at `field` (the event was
// handled); false when the event just sets the field.
bool respond(const scene::Node& node, std::string_view field, const scene::FieldValue& in,
             ResponseContext& context);

scene::FieldValue singleValue(scene::FieldType type, double number);

} // namespace fl::animation
