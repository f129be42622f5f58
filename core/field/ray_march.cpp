#include "ray_march.h"

#include <algorithm>
#include <cmath>

namespace fl::field {
namespace {

bool inside(double f) {
    return f > 0;
}

// The first sign change of f on one step of the march. Equal signs at both
// ends do not prove there is none — a thin shell can lie between — so the
// step's interval bound decides: where f cannot reach the other sign the step
// is empty, else it is halved (down to maxDepth) and each half asked again.
struct Crossing {
    FieldSampler& sampler;
    const Vec3& origin;
    const Vec3& direction;
    int maxDepth;
    long budget = 1'000'000; // halvings for the whole march (a grazing ray)

    std::optional<double> within(double a, double fa, double b, double fb, int depth) {
        if (!(b > a)) return std::nullopt;
        if (std::isfinite(fa) && std::isfinite(fb) && inside(fa) != inside(fb))
            return refine(a, fa, b);
        if (depth >= maxDepth || --budget < 0 || !mayCross(a, fa, b)) return std::nullopt;
        const double m = 0.5 * (a + b), fm = sampler.value(along(origin, direction, m));
        if (auto s = within(a, fa, m, fm, depth + 1)) return s;
        return within(m, fm, b, fb, depth + 1);
    }

    // Can f take the other sign from fa's somewhere on [a, b]?
    bool mayCross(double a, double fa, double b) {
        const Vec3 p = along(origin, direction, a), q = along(origin, direction, b);
        Vec3 lo{}, hi{};
        for (std::size_t k = 0; k < 3; ++k) {
            lo[k] = std::min(p[k], q[k]);
            hi[k] = std::max(p[k], q[k]);
        }
        const formula::Interval r = sampler.interval(lo, hi);
        if (r.empty()) return false; // undefined all along: no surface to meet
        // From an undefined end, a crossing needs values of both signs.
        if (!std::isfinite(fa)) return r.lo <= 0 && r.hi > 0;
        return inside(fa) ? r.lo <= 0 : r.hi > 0;
    }

    // Bisection to the last bit of s.
    double refine(double a, double fa, double b) {
        for (int i = 0; i < 100 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++i) {
            const double m = 0.5 * (a + b), fm = sampler.value(along(origin, direction, m));
            if (!std::isfinite(fm)) break;
            (inside(fm) == inside(fa) ? a : b) = m;
            if (inside(fm) == inside(fa)) fa = fm;
        }
        return 0.5 * (a + b);
    }
};

} // namespace

std::optional<SurfaceHit> marchToSurface(FieldSampler& sampler, const Vec3& origin,
                                         const Vec3& direction, const MarchOptions& options) {
    const ImplicitField& field = sampler.field();
    if (!isFinite(origin) || !isFinite(direction) || !field.box.valid()) return std::nullopt;
    // An origin so far away that its last digit is larger than a thousandth
    // of the box cannot say where on the shape it points: origin + s *
    // direction rounds to that digit, and a hit would be made up.
    const double far = std::max({std::abs(origin[0]), std::abs(origin[1]), std::abs(origin[2])});
    if (far * 2.3e-16 > 1e-3 * field.box.diagonal()) return std::nullopt;
    const auto span = clipRay(origin, direction, field.box);
    if (!span || span->enter > options.limit) return std::nullopt;
    const double s0 = span->enter, s1 = std::min(span->exit, options.limit);
    auto value = [&](double s) { return sampler.value(along(origin, direction, s)); };
    double a = s0, fa = value(a);
    // A solid cut by its box: entering the box inside it is touching the face.
    if (field.boundary == BoxBoundary::Closed && s0 > 0 && inside(fa)) {
        SurfaceHit hit;
        hit.s = s0;
        hit.point = along(origin, direction, s0);
        hit.normal = nearestFaceNormal(field.box, hit.point);
        hit.onBoxFace = true;
        return hit;
    }
    const double step = std::max(field.box.diagonal() * options.stepOfDiagonal /
                                     std::max(length(direction), 1e-300),
                                 (s1 - s0) / 100000);
    if (!std::isfinite(step) || !(step > 0)) return std::nullopt;
    Crossing search{sampler, origin, direction, options.maxDepth};
    int steps = 0;
    for (double b = std::min(s0 + step, s1);; b = std::min(b + step, s1)) {
        // A step lost to rounding (an origin very far away) or a march too
        // long ends the search rather than the caller.
        if (!(b > a) || ++steps > options.maxSteps) return std::nullopt;
        const double fb = value(b);
        if (const auto s = search.within(a, fa, b, fb, 0)) {
            SurfaceHit hit;
            hit.s = *s;
            hit.point = along(origin, direction, hit.s);
            const formula::Dual d = sampler.gradient(hit.point);
            hit.normal =
                unitOr(unitOr({-d.d[0], -d.d[1], -d.d[2]}, scaled(direction, -1)), {0, 0, 1});
            if (field.boundary == BoxBoundary::Open && dot(hit.normal, direction) > 0)
                hit.normal = scaled(hit.normal, -1);
            return hit;
        }
        a = b;
        fa = fb;
        if (b >= s1) return std::nullopt;
    }
}

} // namespace fl::field
