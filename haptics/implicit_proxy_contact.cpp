#include "implicit_proxy_contact.h"

#include "field/ray_march.h"

#include <cmath>
#include <optional>

namespace fl::haptics {

using field::Vec3;

namespace {

// Outward unit normal from a gradient (f grows inwards); none where it vanishes.
std::optional<Vec3> outward(const formula::Dual& d) {
    const double len = field::length(d.d);
    if (!(len > 1e-300) || !std::isfinite(len)) return std::nullopt;
    return Vec3{-d.d[0] / len, -d.d[1] / len, -d.d[2] / len};
}

} // namespace

void ImplicitProxyContact::step(ContactState& s, const Vec3& tool, const formula::Dual& here,
                                SurfaceMaterial& material) {
    if (s.contact == ContactKind::None) {
        field::MarchOptions o;
        o.limit = 1; // the segment from the last tool position to this one
        const auto hit =
            field::marchToSurface(sampler_, s.lastTool, field::minus(tool, s.lastTool), o);
        if (hit) {
            s.contact = ContactKind::Surface;
            s.proxy = hit->point;
            s.lastNormal = hit->normal;
            s.hasNormal = true;
        } else if (here.v >= 0) {
            // Ending exactly on f = 0 is no sign change: entered all the
            // same if the last position was outside; else it started inside.
            const double before = solidAt(sampler_, s.lastTool).v;
            if (before < 0) {
                s.contact = ContactKind::Surface;
                s.proxy = tool;
            } else {
                s.contact = ContactKind::Inside;
            }
        }
    } else if (s.contact == ContactKind::Inside && here.v < 0) {
        s.contact = ContactKind::None; // out again, freely
    }
    if (s.contact == ContactKind::Surface) slide(s, tool, material);
}

void ImplicitProxyContact::slide(ContactState& s, const Vec3& tool, SurfaceMaterial& material) {
    const formula::Dual atProxy = solidAt(sampler_, s.proxy);
    if (auto n = outward(atProxy)) {
        s.lastNormal = *n;
        s.hasNormal = true;
    }
    if (!s.hasNormal) return;
    const Vec3 n = s.lastNormal;
    const double depth = field::dot(field::minus(s.proxy, tool), n);
    if (depth <= 0) {
        // Above the tangent plane: the proxy follows the tool unless the
        // way there meets the solid again (a concave corner).
        const Vec3 start = field::along(s.proxy, n, 1e-9 * diagonal_);
        field::MarchOptions o;
        o.limit = 1;
        const auto hit = field::marchToSurface(sampler_, start, field::minus(tool, start), o);
        if (hit) {
            s.proxy = hit->point;
            s.lastNormal = hit->normal;
        } else {
            s.contact = ContactKind::None;
        }
        return;
    }
    // The tool projected onto the tangent plane; the proxy goes towards it
    // as far as the friction cone lets it.
    const Vec3 onPlane = field::along(tool, n, depth);
    const double mu = material.frictionAt(s.proxy);
    const Vec3 slide = field::minus(onPlane, s.proxy);
    const double slideLength = field::length(slide);
    const double radius = mu * depth;
    Vec3 target = s.proxy;
    if (slideLength > radius) target = field::along(onPlane, slide, -radius / slideLength);
    // Back onto f = 0 by Newton steps along the gradient.
    Vec3 p = target;
    bool ok = false;
    for (int k = 0; k < 8; ++k) {
        const formula::Dual d = solidAt(sampler_, p);
        const double g2 = field::dot(d.d, d.d);
        if (!std::isfinite(d.v) || !(g2 > 1e-300)) break;
        if (std::abs(d.v) <= 1e-12 * diagonal_) {
            ok = true;
            break;
        }
        p = field::minus(p, field::scaled(d.d, d.v / g2));
    }
    if (ok && field::isFinite(p) && field::length(field::minus(p, target)) <= depth + slideLength)
        s.proxy = p; // else the proxy stays: no surface to slide on here
}

} // namespace fl::haptics
