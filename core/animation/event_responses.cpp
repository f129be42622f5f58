#include "event_responses.h"

#include "interpolation.h"

#include <algorithm>

namespace fl::animation {

using scene::FieldType;
using scene::FieldValue;
using scene::Node;

FieldValue singleValue(FieldType type, double number) {
    FieldValue v;
    v.type = type;
    v.numbers = {number};
    return v;
}

namespace {

FieldType valueChangedType(const Node& node) {
    if (!node.spec) return FieldType::Unknown;
    const scene::FieldSpec* spec = scene::findFieldSpec(*node.spec, "value_changed");
    return spec ? spec->type : FieldType::Unknown;
}

bool first(const FieldValue& v) {
    return !v.numbers.empty() && v.numbers[0] != 0;
}

// set_fraction on an interpolator or sequencer; next/previous on a sequencer.
bool interpolate(const Node& node, InterpolatorKind kind, std::string_view field,
                 const FieldValue& in, ResponseContext& ctx) {
    const bool sequencer = kind == InterpolatorKind::Boolean || kind == InterpolatorKind::Integer;
    const std::vector<double> key = ctx.value(node, "key").numbers;
    const std::vector<double> keyValue = ctx.value(node, "keyValue").numbers;
    if (!checkKeys(kind, key, keyValue).empty()) return true; // warned at load; no output
    FieldValue out;
    out.type = valueChangedType(node);
    if (field == "set_fraction") {
        const double f = in.numbers.empty() ? 0 : in.numbers[0];
        out.numbers = animation::interpolate(kind, key, keyValue, f);
        if (sequencer) {
            const auto upper = std::upper_bound(key.begin(), key.end(), f);
            ctx.sequencerIndex(node) = upper == key.begin() ? 0 : int(upper - key.begin()) - 1;
        }
    } else if (sequencer && (field == "next" || field == "previous")) {
        if (!first(in)) return true; // only TRUE steps
        const int n = int(key.size());
        int& i = ctx.sequencerIndex(node);
        i = field == "next" ? (i + 1) % n : (i + n - 1) % n; // both wrap around
        out.numbers = {keyValue[std::size_t(i)]};
    } else {
        return false;
    }
    ctx.emit(node, "value_changed", out);
    return true;
}

} // namespace

std::optional<BindableKind> bindableKindOf(scene::NodeKind node) {
    using scene::NodeKind;
    switch (node) {
    case NodeKind::Viewpoint:
    case NodeKind::OrthoViewpoint:
        return BindableKind::Viewpoint;
    case NodeKind::NavigationInfo:
        return BindableKind::NavigationInfo;
    case NodeKind::Background:
    case NodeKind::TextureBackground:
        return BindableKind::Background;
    case NodeKind::Fog:
        return BindableKind::Fog;
    default: // not a bindable node
        return std::nullopt;
    }
}

bool respond(const Node& node, std::string_view field, const FieldValue& in, ResponseContext& ctx) {
    if (const auto kind = interpolatorKind(node.kind()))
        return interpolate(node, *kind, field, in, ctx);
    if (field == "set_bind")
        if (const auto kind = bindableKindOf(node.kind())) {
            ctx.bind(node, *kind, first(in));
            return true;
        }
    using scene::NodeKind;
    const NodeKind type = node.kind();
    if (type == NodeKind::BooleanFilter && field == "set_boolean") {
        const bool b = first(in);
        ctx.emit(node, b ? "inputTrue" : "inputFalse", singleValue(FieldType::SFBool, b));
        ctx.emit(node, "inputNegate", singleValue(FieldType::SFBool, !b));
        return true;
    }
    if (type == NodeKind::BooleanToggle && field == "set_boolean") {
        if (first(in))
            ctx.set(node, "toggle",
                    singleValue(FieldType::SFBool, !first(ctx.value(node, "toggle"))));
        return true;
    }
    if (type == NodeKind::BooleanTrigger && field == "set_triggerTime") {
        ctx.emit(node, "triggerTrue", singleValue(FieldType::SFBool, 1));
        return true;
    }
    if (type == NodeKind::IntegerTrigger && field == "set_boolean") {
        if (first(in)) {
            const FieldValue key = ctx.value(node, "integerKey");
            ctx.emit(node, "triggerValue",
                     singleValue(FieldType::SFInt32, key.numbers.empty() ? -1 : key.numbers[0]));
        }
        return true;
    }
    if (type == NodeKind::TimeTrigger && field == "set_boolean") {
        ctx.emit(node, "triggerTime", singleValue(FieldType::SFTime, ctx.nowSeconds()));
        return true;
    }
    return false;
}

} // namespace fl::animation
