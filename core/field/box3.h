#pragma once
// Axis-aligned boxes: the domain of every function node, the cells of the
// mesher, the bounds a ray is clipped to.
#include "vec3.h"

#include <cstddef>
#include <optional>

namespace fl::field {

struct Box3 {
    Vec3 lo{-1, -1, -1};
    Vec3 hi{1, 1, 1};
    double size(int axis) const { return hi[std::size_t(axis)] - lo[std::size_t(axis)]; }
    double longestSide() const;
    double diagonal() const;
    bool valid() const; // finite and hi > lo on every axis
    bool contains(const Vec3& p) const;
};

// Where a ray origin + s * direction (s >= 0) is inside a box: [enter, exit].
struct RaySpan {
    double enter = 0, exit = 0;
};
// None when it misses (slab test; a direction parallel to a face is fine).
std::optional<RaySpan> clipRay(const Vec3& origin, const Vec3& direction, const Box3& box);

// The outward unit normal of the box face nearest to p.
Vec3 nearestFaceNormal(const Box3& box, const Vec3& p);

} // namespace fl::field
