#include "force_model.h"

#include "field/domain_mapping.h"
#include "formula/eval_scalar.h"
#include "triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fl::haptics {

using field::Vec3;

ForceSettings settingsFor(const DeviceLimits& limits, double rateHz) {
    ForceSettings s;
    s.stiffness = 0.5 * limits.maxStiffness;
    s.damping = limits.maxDamping;
    // Twice Colgate & Brown's least damping for a passive sampled wall, within
    // what the device can render.
    s.contactDamping = std::min(s.stiffness / rateHz, limits.maxDamping);
    s.maxForce = limits.maxForce;
    return s;
}

struct ForceModel::ShapeState {
    explicit ShapeState(const TangibleShape& s) : shape(&s) {
        if (s.field) sampler.emplace(*s.field);
        for (const EffectField& e : s.effects)
            evaluators.emplace_back(e.tape);
        surface = surfaceContactFor(s, sampler ? &*sampler : nullptr);
    }
    ShapeState(const ShapeState&) = delete; // `surface` holds the sampler's address
    ShapeState& operator=(const ShapeState&) = delete;
    const TangibleShape* shape;
    std::optional<field::FieldSampler> sampler;       // none for a parametric container
    std::vector<formula::ScalarEvaluator> evaluators; // one per effect
    std::unique_ptr<SurfaceContact> surface;          // none: only the inside acts
    ContactState c;
};

class ForceModel::ShapeMaterial final : public SurfaceMaterial {
  public:
    ShapeMaterial(ForceModel& model, ShapeState& s, const animation::Instant& moment)
        : model_(model), s_(s), moment_(moment) {}
    double frictionAt(const Vec3& p) override {
        double f[3];
        return model_.effectAt(s_, scene::TangibleKind::Friction, p, moment_, f)
                   ? std::max(f[0], 0.0)
                   : 0.0;
    }

  private:
    ForceModel& model_;
    ShapeState& s_;
    const animation::Instant& moment_;
};

namespace {

std::string pointText(const Vec3& p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g, %.6g)", p[0], p[1], p[2]);
    return buffer;
}

std::string kindTitle(scene::TangibleKind kind) {
    switch (kind) {
    case scene::TangibleKind::Friction:
        return "FFriction";
    case scene::TangibleKind::Tension:
        return "FTension";
    case scene::TangibleKind::Density:
        return "FDensity";
    case scene::TangibleKind::Force:
        return "FForce";
    }
    return "effect";
}

} // namespace

ForceModel::ForceModel(ForceSettings settings) : settings_(settings) {}
ForceModel::~ForceModel() = default;

void ForceModel::setScene(std::shared_ptr<const TangibleScene> scene) {
    std::vector<std::unique_ptr<ShapeState>> next;
    if (scene)
        for (const TangibleShape& s : scene->shapes) {
            auto state = std::make_unique<ShapeState>(s);
            for (const auto& old : states_)
                if (old->shape->shape == s.shape) // the same FShape: its contact goes on
                    state->c = old->c;
            next.push_back(std::move(state));
        }
    states_ = std::move(next); // the old snapshot's states go before it may
    scene_ = std::move(scene);
}

void ForceModel::report(const std::string& key, const std::string& text) {
    if (reported_.insert(key).second) reports_.push_back(text);
}

bool ForceModel::effectAt(ShapeState& s, scene::TangibleKind kind, const Vec3& p,
                          const animation::Instant& moment, double* values) {
    const TangibleShape& shape = *s.shape;
    for (std::size_t i = 0; i < shape.effects.size(); ++i) {
        const EffectField& e = shape.effects[i];
        if (e.kind != kind) continue;
        const auto v =
            field::componentView(shape.effectFrame.point(p), shape.geometryBox, e.componentBox);
        const double t = e.timing.at(moment);
        const formula::Point point{v[0], v[1], v[2], t, v[3], v[4], v[5]};
        s.evaluators[i].evaluateAll(point, values);
        const std::size_t n = kind == scene::TangibleKind::Force ? 3 : 1;
        for (std::size_t k = 0; k < n; ++k)
            if (!std::isfinite(values[k])) {
                report(shape.name + kindTitle(kind), kindTitle(kind) + " (" + e.location +
                                                         ") is not a number at " +
                                                         pointText(shape.toScene.point(p)) +
                                                         ": it adds nothing where that happens");
                return false;
            }
        return true;
    }
    return false;
}

Vec3 ForceModel::surfaceForce(ShapeState& s, const ToolSample& tool) {
    const TangibleShape& shape = *s.shape;
    Vec3 surfaceForce = field::scaled(field::minus(shape.toScene.point(s.c.proxy), tool.position),
                                      settings_.stiffness);
    const double pressing = field::length(surfaceForce); // the spring alone
    // Damping along the normal, moving in or out: a sampled spring
    // gives back energy unless b > K·T/2 (Colgate & Brown).
    if (s.c.hasNormal && settings_.contactDamping > 0) {
        const field::Vec3 n = shape.toScene.vector(s.c.lastNormal);
        const double nn = field::dot(n, n);
        if (nn > 0)
            surfaceForce =
                field::minus(surfaceForce, field::scaled(n, settings_.contactDamping *
                                                                field::dot(tool.velocity, n) / nn));
    }
    if (double tension[3];
        effectAt(s, scene::TangibleKind::Tension, s.c.proxy, tool.moment, tension) &&
        tension[0] >= 0) {
        if (tension[0] > 1)
            report(shape.name + "tension>1",
                   "FTension is a fraction of the device's maximum force; " + shape.name +
                       "'s is above 1 and is taken as 1 (the surface then "
                       "holds up to the device's limit)");
        const double popAt = std::min(tension[0], 1.0) * settings_.maxForce;
        if (pressing > popAt) {
            s.c.contact = ContactKind::Inside; // popped through
            surfaceForce = {};
        }
    }
    return surfaceForce;
}

Vec3 ForceModel::insideForce(ShapeState& s, const Vec3& tool3, const ToolSample& tool) {
    const TangibleShape& shape = *s.shape;
    Vec3 total{};
    if (double d[3]; effectAt(s, scene::TangibleKind::Density, tool3, tool.moment, d)) {
        const double b = std::clamp(d[0], 0.0, 1.0) * settings_.damping;
        total = field::minus(total, field::scaled(tool.velocity, b));
    }
    if (double f[3]; effectAt(s, scene::TangibleKind::Force, tool3, tool.moment, f)) {
        // Along the shape's axes, turned into the scene's; its size kept.
        const Vec3 local{f[0], f[1], f[2]};
        const Vec3 turned = shape.toScene.vector(local);
        const double len = field::length(turned);
        if (len > 0) total = field::plus(total, field::scaled(turned, field::length(local) / len));
    }
    return total;
}

// One tick: per tangible shape, the contact (the proxy on f = 0 for a
// function, the god-object on triangles for polygons, inside or outside for
// a solid without surface), then the effect felt there: the surface's spring
// with damping, friction and tension; density and force fields inside.
ForceSample ForceModel::tick(const ToolSample& tool) {
    ForceSample out;
    out.proxy = tool.position;
    Vec3 total{};
    bool surfaceFound = false, insideFound = false;
    for (auto& statePtr : states_) {
        ShapeState& s = *statePtr;
        const TangibleShape& shape = *s.shape;
        const Vec3 tool3 = shape.toShape.point(tool.position);
        if (!s.c.hasLastTool) {
            s.c.lastTool = tool3;
            s.c.hasLastTool = true;
        }
        const bool polygons = shape.triangles != nullptr;
        const bool within =
            polygons ? shape.triangles->contains(tool3) : shape.container.contains(tool3);
        const formula::Dual here = s.sampler && !polygons ? solidAt(*s.sampler, tool3)
                                                          : formula::Dual{within ? 1.0 : -1.0};
        if (!std::isfinite(here.v)) {
            report(shape.name + "f", shape.name + ": its function is not a number at " +
                                         pointText(tool.position) +
                                         ": it is not felt where that happens");
            s.c.lastTool = tool3;
            continue;
        }
        if (s.surface) {
            ShapeMaterial material(*this, s, tool.moment);
            s.surface->step(s.c, tool3, here, material);
        } else {
            s.c.contact = here.v >= 0 ? ContactKind::Inside : ContactKind::None;
        }
        const Vec3 spring =
            s.surface && s.c.contact == ContactKind::Surface ? surfaceForce(s, tool) : Vec3{};
        s.c.lastTool = tool3;
        if (s.c.contact == ContactKind::Surface) {
            total = field::plus(total, spring);
            if (!surfaceFound) out.proxy = shape.toScene.point(s.c.proxy);
            surfaceFound = true;
        } else if (s.c.contact == ContactKind::Inside && here.v >= 0) {
            insideFound = true;
            total = field::plus(total, insideForce(s, tool3, tool));
        }
    }
    out.force = total;
    out.contact = surfaceFound  ? ContactKind::Surface
                  : insideFound ? ContactKind::Inside
                                : ContactKind::None;
    return out;
}

} // namespace fl::haptics
