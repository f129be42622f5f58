#pragma once
// X3D interpolators and sequencers (ISO/IEC 19775-1 §19, §30) as pure
// functions: a fraction, the `key` list and the `keyValue` list in, the
// value_changed value out. Plain numbers, as FieldValue stores them.
#include "scene/node_kind.h"
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fl::animation {

enum class InterpolatorKind : std::uint8_t {
    Scalar,       // ScalarInterpolator: 1 number per key
    Position,     // PositionInterpolator: 3
    Position2D,   // PositionInterpolator2D: 2
    Color,        // ColorInterpolator: 3, interpolated in HSV as X3D requires
    Orientation,  // OrientationInterpolator: axis-angle, spherical (shortest arc)
    Normal,       // NormalInterpolator: n unit vectors per key, spherical
    Coordinate,   // CoordinateInterpolator: n points per key
    Coordinate2D, // CoordinateInterpolator2D: n 2D points per key
    Boolean,      // BooleanSequencer: steps, no blending
    Integer,      // IntegerSequencer: steps, no blending
};

std::optional<InterpolatorKind> interpolatorKind(scene::NodeKind node);
// Numbers one key's value holds for the single-valued kinds (Scalar 1,
// Orientation 4 ...); 0 for the kinds with n values per key.
int numbersPerKey(InterpolatorKind kind);

// Why key/keyValue cannot be used (sizes disagree, keys decrease, NaN ...),
// or empty when they can.
std::string checkKeys(InterpolatorKind kind, std::span<const double> key,
                      std::span<const double> keyValue);

// The value at `fraction`; empty when checkKeys would refuse the keys.
// Before the first key: the first value; after the last: the last.
std::vector<double> interpolate(InterpolatorKind kind, std::span<const double> key,
                                std::span<const double> keyValue, double fraction);

// Helpers, exposed for tests.
std::vector<double> rgbToHsv(std::span<const double, 3> rgb);
std::vector<double> hsvToRgb(std::span<const double, 3> hsv);
// Spherical interpolation between two axis-angle rotations (x y z angle).
std::vector<double> slerpRotation(std::span<const double, 4> a, std::span<const double, 4> b,
                                  double s);

} // namespace fl::animation
