#pragma once
// The march of a ray to f = 0 through a function shape's domain box: what
// picking asks ("where did the user click"), and what haptic contact and the
// grader ask of a segment ("where does the tool first meet the surface"). One
// implementation, so a click, a touch and a check of one moment agree.
#include "field_sampler.h"

#include <optional>

namespace fl::field {

struct SurfaceHit {
    double s = 0;           // along the ray: origin + s * direction
    Vec3 point{};           // in the field's coordinates
    Vec3 normal{};          // unit; see marchToSurface
    bool onBoxFace = false; // a closed solid entered through its box
};

struct MarchOptions {
    // Steps of at most this fraction of the box's diagonal, so thin features
    // are not skipped over; and at most this many steps along one ray.
    double stepOfDiagonal = 1.0 / 512;
    int maxSteps = 200000;
    // Where both ends of a step have one sign but the step's interval bound
    // says f may take the other between them (a shell thinner than a step),
    // the step is halved up to this many times: no tunnelling through
    // features wider than step / 2^maxDepth.
    int maxDepth = 16;
    // Only hits with s in [0, limit] count (1 for a segment from origin to
    // origin + direction; infinite for a ray).
    double limit = INFINITY;
};

// The first hit of the ray origin + s * direction (s >= 0) with the shape the
// sampler's field shows, inside the field's box:
// - a sign change of f along the ray — between the steps' ends, or inside a
//   step where its interval bound allows one — refined by bisection to the
//   last bit;
//   normal the unit outward direction, -grad f (f >= 0 inside);
// - a field whose box closes the solid (BoxBoundary::Closed): a ray that
//   enters the box where f > 0 hits the box face, with that face's normal;
// - a surface not closed by its box (BoxBoundary::Open, an implicit surface
//   f = 0) has no outside: the normal faces the ray's origin.
// None when the ray misses, the march cannot step (a direction of zero, a
// range lost to rounding) or f is undefined at every step.
std::optional<SurfaceHit> marchToSurface(FieldSampler& sampler, const Vec3& origin,
                                         const Vec3& direction, const MarchOptions& options = {});

} // namespace fl::field
