#include "force_model.h"

#include "field/domain_mapping.h"
#include "field/ray_march.h"
#include "formula/eval_scalar.h"
#include "triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fl::haptics {

using field::Vec3;

std::string_view contactName(ContactKind kind) {
    switch (kind) {
    case ContactKind::None:
        return "none";
    case ContactKind::Surface:
        return "surface";
    case ContactKind::Inside:
        return "inside";
    }
    return "none";
}

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
    }
    const TangibleShape* shape;
    std::optional<field::FieldSampler> sampler;       // none for a parametric container
    std::vector<formula::ScalarEvaluator> evaluators; // one per effect
    ContactKind contact = ContactKind::None;
    Vec3 proxy{};    // the shape's coordinates
    Vec3 lastTool{}; // the shape's coordinates
    bool hasLastTool = false;
    Vec3 lastNormal{}; // outward, the last one that could be computed
    bool hasNormal = false;
};

namespace {

// The solid as the servo loop feels it: f >= 0, cut by its box where the box
// closes it (min with the distance to the box's faces), with its gradient.
formula::Dual solid(field::FieldSampler& sampler, const Vec3& p) {
    formula::Dual d = sampler.gradient(p);
    const field::ImplicitField& f = sampler.field();
    if (f.boundary != field::BoxBoundary::Closed) return d;
    for (std::size_t a = 0; a < 3; ++a) {
        const double toLow = p[a] - f.box.lo[a], toHigh = f.box.hi[a] - p[a];
        if (toLow < d.v || !std::isfinite(d.v)) {
            d.v = toLow;
            d.d = {0, 0, 0};
            d.d[a] = 1;
        }
        if (toHigh < d.v) {
            d.v = toHigh;
            d.d = {0, 0, 0};
            d.d[a] = -1;
        }
    }
    return d;
}

// Outward unit normal from a gradient (f grows inwards); none where it vanishes.
std::optional<Vec3> outward(const formula::Dual& d) {
    const double len = field::length(d.d);
    if (!(len > 1e-300) || !std::isfinite(len)) return std::nullopt;
    return Vec3{-d.d[0] / len, -d.d[1] / len, -d.d[2] / len};
}

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
                if (old->shape->shape == s.shape) { // the same FShape: its contact goes on
                    state->contact = old->contact;
                    state->proxy = old->proxy;
                    state->lastTool = old->lastTool;
                    state->hasLastTool = old->hasLastTool;
                    state->lastNormal = old->lastNormal;
                    state->hasNormal = old->hasNormal;
                }
            next.push_back(std::move(state));
        }
    states_ = std::move(next); // the old snapshot's states go before it may
    scene_ = std::move(scene);
}

void ForceModel::report(const std::string& key, const std::string& text) {
    if (reported_.insert(key).second) reports_.push_back(text);
}

// The god-object against triangles (Zilles & Salisbury): the proxy goes
// towards the tool until a front face stops it, then slides on up to three
// faces' planes; friction holds it within its cone.
template <class Friction>
void ForceModel::polygonStep(ShapeState& s, const Vec3& tool, Friction friction) {
    const TriangleBvh& bvh = *s.shape->triangles;
    const double eps = 1e-9 * std::max(bvh.bounds().diagonal(), 1e-300);
    if (s.contact == ContactKind::Inside) {
        if (!bvh.contains(tool)) s.contact = ContactKind::None; // out again, freely
        return;
    }
    if (s.contact == ContactKind::None) {
        const auto hit = bvh.firstHit(s.lastTool, tool);
        if (!hit || !hit->frontFacing) return;
        s.contact = ContactKind::Surface;
        s.proxy = field::along(hit->point, hit->normal, eps);
        s.lastNormal = hit->normal;
        s.hasNormal = true;
    }
    // Towards the tool until a front face stops the proxy; the rest of the
    // way projected onto that face's plane; up to three faces a tick.
    const Vec3 from = s.proxy;
    Vec3 goal = tool, proxy = s.proxy, normal = s.lastNormal;
    bool free = true;
    for (int constraint = 0; constraint < 3; ++constraint) {
        const auto hit = bvh.firstHit(proxy, goal);
        if (!hit || !hit->frontFacing) {
            proxy = goal;
            break;
        }
        free = false;
        const Vec3 at = field::along(hit->point, hit->normal, eps);
        const Vec3 rest = field::minus(goal, at);
        goal = field::along(goal, hit->normal, -field::dot(rest, hit->normal));
        proxy = at;
        normal = hit->normal;
    }
    if (free) { // nothing between the proxy and the tool: out of contact
        s.contact = ContactKind::None;
        s.proxy = tool;
        return;
    }
    // Sliding on a face's plane past the face's edge (a convex surface) leaves
    // the proxy above the surface: back onto it along the line to the tool.
    if (const auto hit = bvh.firstHit(proxy, tool); hit && hit->frontFacing) {
        proxy = field::along(hit->point, hit->normal, eps);
        normal = hit->normal;
    }
    s.lastNormal = normal;
    // The friction cone: within μ · depth of where it was, the proxy stays;
    // beyond, it follows to the cone's edge.
    const double depth = field::dot(field::minus(proxy, tool), normal);
    const Vec3 moved = field::minus(proxy, from);
    const double length = field::length(moved);
    const double radius = friction(from) * std::max(depth, 0.0);
    if (length <= radius) return;
    s.proxy = radius > 0 ? field::along(proxy, moved, -radius / length) : proxy;
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

void ForceModel::implicitProxyStep(ShapeState& s, const Vec3& tool3, const formula::Dual& here,
                                   const animation::Instant& moment) {
    const double diagonal = s.shape->container.diagonal();
    if (s.contact == ContactKind::None) {
        field::MarchOptions o;
        o.limit = 1; // the segment from the last tool position to this one
        const auto hit =
            field::marchToSurface(*s.sampler, s.lastTool, field::minus(tool3, s.lastTool), o);
        if (hit) {
            s.contact = ContactKind::Surface;
            s.proxy = hit->point;
            s.lastNormal = hit->normal;
            s.hasNormal = true;
        } else if (here.v >= 0) {
            // Ending exactly on f = 0 is no sign change: entered all the
            // same if the last position was outside; else it started inside.
            const double before = solid(*s.sampler, s.lastTool).v;
            if (before < 0) {
                s.contact = ContactKind::Surface;
                s.proxy = tool3;
            } else {
                s.contact = ContactKind::Inside;
            }
        }
    } else if (s.contact == ContactKind::Inside && here.v < 0) {
        s.contact = ContactKind::None; // out again, freely
    }
    if (s.contact == ContactKind::Surface) {
        const formula::Dual atProxy = solid(*s.sampler, s.proxy);
        if (auto n = outward(atProxy)) {
            s.lastNormal = *n;
            s.hasNormal = true;
        }
        if (s.hasNormal) {
            const Vec3 n = s.lastNormal;
            const double depth = field::dot(field::minus(s.proxy, tool3), n);
            if (depth <= 0) {
                // Above the tangent plane: the proxy follows the tool unless the
                // way there meets the solid again (a concave corner).
                const Vec3 start = field::along(s.proxy, n, 1e-9 * diagonal);
                field::MarchOptions o;
                o.limit = 1;
                const auto hit =
                    field::marchToSurface(*s.sampler, start, field::minus(tool3, start), o);
                if (hit) {
                    s.proxy = hit->point;
                    s.lastNormal = hit->normal;
                } else {
                    s.contact = ContactKind::None;
                }
            } else {
                // The tool projected onto the tangent plane; the proxy goes
                // towards it as far as the friction cone lets it.
                const Vec3 onPlane = field::along(tool3, n, depth);
                double mu = 0;
                if (double f[3]; effectAt(s, scene::TangibleKind::Friction, s.proxy, moment, f))
                    mu = std::max(f[0], 0.0);
                const Vec3 slide = field::minus(onPlane, s.proxy);
                const double slideLength = field::length(slide);
                const double radius = mu * depth;
                Vec3 target = s.proxy;
                if (slideLength > radius)
                    target = field::along(onPlane, slide, -radius / slideLength);
                // Back onto f = 0 by Newton steps along the gradient.
                Vec3 p = target;
                bool ok = false;
                for (int k = 0; k < 8; ++k) {
                    const formula::Dual d = solid(*s.sampler, p);
                    const double g2 = field::dot(d.d, d.d);
                    if (!std::isfinite(d.v) || !(g2 > 1e-300)) break;
                    if (std::abs(d.v) <= 1e-12 * diagonal) {
                        ok = true;
                        break;
                    }
                    p = field::minus(p, field::scaled(d.d, d.v / g2));
                }
                if (ok && field::isFinite(p) &&
                    field::length(field::minus(p, target)) <= depth + slideLength)
                    s.proxy = p; // else the proxy stays: no surface to slide on here
            }
        }
    }
}

Vec3 ForceModel::surfaceForce(ShapeState& s, const ToolSample& tool) {
    const TangibleShape& shape = *s.shape;
    Vec3 surfaceForce = field::scaled(field::minus(shape.toScene.point(s.proxy), tool.position),
                                      settings_.stiffness);
    const double pressing = field::length(surfaceForce); // the spring alone
    // Damping along the normal, moving in or out: a sampled spring
    // gives back energy unless b > K·T/2 (Colgate & Brown).
    if (s.hasNormal && settings_.contactDamping > 0) {
        const field::Vec3 n = shape.toScene.vector(s.lastNormal);
        const double nn = field::dot(n, n);
        if (nn > 0)
            surfaceForce =
                field::minus(surfaceForce, field::scaled(n, settings_.contactDamping *
                                                                field::dot(tool.velocity, n) / nn));
    }
    if (double tension[3];
        effectAt(s, scene::TangibleKind::Tension, s.proxy, tool.moment, tension) &&
        tension[0] >= 0) {
        if (tension[0] > 1)
            report(shape.name + "tension>1",
                   "FTension is a fraction of the device's maximum force; " + shape.name +
                       "'s is above 1 and is taken as 1 (the surface then "
                       "holds up to the device's limit)");
        const double popAt = std::min(tension[0], 1.0) * settings_.maxForce;
        if (pressing > popAt) {
            s.contact = ContactKind::Inside; // popped through
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
        if (!s.hasLastTool) {
            s.lastTool = tool3;
            s.hasLastTool = true;
        }
        const bool polygons = shape.triangles != nullptr;
        const bool within =
            polygons ? shape.triangles->contains(tool3) : shape.container.contains(tool3);
        const formula::Dual here =
            s.sampler && !polygons ? solid(*s.sampler, tool3) : formula::Dual{within ? 1.0 : -1.0};
        if (!std::isfinite(here.v)) {
            report(shape.name + "f", shape.name + ": its function is not a number at " +
                                         pointText(tool.position) +
                                         ": it is not felt where that happens");
            s.lastTool = tool3;
            continue;
        }
        if (shape.surface && polygons)
            polygonStep(s, tool3, [&](const Vec3& at) {
                double f[3];
                return effectAt(s, scene::TangibleKind::Friction, at, tool.moment, f)
                           ? std::max(f[0], 0.0)
                           : 0.0;
            });
        else if (shape.surface)
            implicitProxyStep(s, tool3, here, tool.moment);
        else
            s.contact = here.v >= 0 ? ContactKind::Inside : ContactKind::None;
        const Vec3 spring =
            shape.surface && s.contact == ContactKind::Surface ? surfaceForce(s, tool) : Vec3{};
        s.lastTool = tool3;
        if (s.contact == ContactKind::Surface) {
            total = field::plus(total, spring);
            if (!surfaceFound) out.proxy = shape.toScene.point(s.proxy);
            surfaceFound = true;
        } else if (s.contact == ContactKind::Inside && here.v >= 0) {
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
