#pragma once
// A tool path for the simulated device: a polyline walked at constant speed
// from its first point to its last in a given duration (`functionlab
// haptics probe --path X,Y,Z:X,Y,Z --duration S`). Before the start the tool
// waits at the first point, after the end at the last, both at rest.
#include "field/vec3.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::haptics {

struct PathSample {
    field::Vec3 position{};
    field::Vec3 velocity{}; // m/s (scene units per second on a scene path)
};

class PolylinePath {
  public:
    // A path needs at least one point, all finite, and a finite duration
    // > 0; otherwise none, with the reason in *error when given.
    static std::optional<PolylinePath> make(std::vector<field::Vec3> points, double duration,
                                            std::string* error = nullptr);

    // Where the tool is at time t (s from the start) and how it moves.
    // Velocity is the speed along the current segment; at the end and on a
    // path of zero length, zero. t is clamped into [0, duration].
    PathSample at(double t) const;

    double length() const { return cumulative_.back(); }
    double duration() const { return duration_; }
    double speed() const { return length() / duration_; }
    const std::vector<field::Vec3>& points() const { return points_; }

  private:
    PolylinePath(std::vector<field::Vec3> points, double duration);
    std::vector<field::Vec3> points_;
    std::vector<double> cumulative_; // arc length at each point
    double duration_ = 1;
};

// Reads "X,Y,Z:X,Y,Z[:…]" (the --path option): numbers as C++ reads doubles
// ("1e-3", "-0.5"), no spaces. Errors name the point and coordinate, e.g.
// "point 2: coordinate 3 \"abc\" is not a number".
std::optional<std::vector<field::Vec3>> parsePathSpec(std::string_view spec,
                                                      std::string* error = nullptr);

} // namespace fl::haptics
