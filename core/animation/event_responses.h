#pragma once
// What standard nodes do when an event arrives at an input that does more than
// set a field: interpolators and sequencers answer set_fraction with
// value_changed, the event utilities (BooleanFilter, BooleanToggle,
// BooleanTrigger, IntegerTrigger, TimeTrigger) turn one event into another.
#include "scene/scene.h"

#include <string_view>

namespace fl::animation {

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
};

// True when the node type responds to events at `field` (the event was
// handled); false when the event just sets the field.
bool respond(const scene::Node& node, std::string_view field, const scene::FieldValue& in,
             ResponseContext& context);

scene::FieldValue singleValue(scene::FieldType type, double number);

} // namespace fl::animation
