#pragma once
// Two ways to find a patch's coefficients.
//
// fromBoundaryCurves: the paper's method. Four closed curves C0..C3, each
// sampled at M points equally spaced in v (v_j = 2πj/M), lie at
// u = 0, u1, u2, 1; each curve's Fourier coefficients up to N give, mode by
// mode, four equations for the mode's four vector coefficients. The patch
// passes through the curves exactly when they hold no frequency above N
// (the paper's "remainder term" is the rest).
//
// fitToPoints: least squares of the same analytic form to every point of a
// region with known (u, v) — the whole surface, not only four curves.
#include "pde_patch.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::pde {

struct BoundaryCurves {
    std::array<std::vector<Vec3>, 4> curves; // C0..C3, the same count M each
    double u1 = 1.0 / 3, u2 = 2.0 / 3;       // where C1 and C2 lie (0 < u1 < u2 < 1)
};
// Nullopt, with `why`, when the curves do not allow N radii (M < 2N + 1,
// counts differ, u1/u2 out of order, a non-finite point).
std::optional<Patch> fromBoundaryCurves(const BoundaryCurves& c, std::size_t radii, double a,
                                        std::string* why = nullptr);

struct Sample {
    double u = 0, v = 0;
    Vec3 point{};
    double weight = 1;
};
struct FitOptions {
    std::size_t radii = 4;
    double a = 1;
    bool pointAtStart = false; // C0 degenerates to a point (a cap): An(0) = Bn(0) = 0
    bool smoothPole = false;   // with pointAtStart: An'(0) = Bn'(0) = 0 for n >= 2 too
    double ridge = 1e-9;       // Tikhonov weight (of the samples' total weight) for stability
};
// Nullopt when there are fewer samples than coefficients or a sample is not finite.
std::optional<Patch> fitToPoints(const std::vector<Sample>& samples, const FitOptions& options,
                                 std::string* why = nullptr);

} // namespace fl::pde
