#include "god_object_contact.h"

#include "triangle_bvh.h"

#include <algorithm>

namespace fl::haptics {

using field::Vec3;

void GodObjectContact::step(ContactState& s, const Vec3& tool, const formula::Dual&,
                            SurfaceMaterial& material) {
    const double eps = 1e-9 * std::max(bvh_.bounds().diagonal(), 1e-300);
    if (s.contact == ContactKind::Inside) {
        if (!bvh_.contains(tool)) s.contact = ContactKind::None; // out again, freely
        return;
    }
    if (s.contact == ContactKind::None) {
        const auto hit = bvh_.firstHit(s.lastTool, tool);
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
        const auto hit = bvh_.firstHit(proxy, goal);
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
    if (const auto hit = bvh_.firstHit(proxy, tool); hit && hit->frontFacing) {
        proxy = field::along(hit->point, hit->normal, eps);
        normal = hit->normal;
    }
    s.lastNormal = normal;
    // The friction cone: within μ · depth of where it was, the proxy stays;
    // beyond, it follows to the cone's edge.
    const double depth = field::dot(field::minus(proxy, tool), normal);
    const Vec3 moved = field::minus(proxy, from);
    const double length = field::length(moved);
    const double radius = material.frictionAt(from) * std::max(depth, 0.0);
    if (length <= radius) return;
    s.proxy = radius > 0 ? field::along(proxy, moved, -radius / length) : proxy;
}

} // namespace fl::haptics
