#pragma once
// Deterministic 3D gradient noise (Perlin's improved noise with a fixed
// permutation), the same on every machine and every run. Its value is a
// trilinear blend of eight corner terms g·d with |g·d| <= 2, so |noise| <= 2
// always (in practice it stays near [-1, 1]); each partial derivative is
// bounded by kNoiseLipschitz, which the interval evaluator relies on.
namespace fl::formula {

constexpr double kNoiseBound = 2.0;
constexpr double kNoiseLipschitz = 9.5; // per axis: 1.875 * 4 + 1, rounded up

double noise3(double x, double y, double z);

// Value and gradient together (for the gradient evaluator and haptics).
double noise3Gradient(double x, double y, double z, double grad[3]);

} // namespace fl::formula
