#pragma once
// `functionlab bench haptics`: what one force tick costs and what touch
// accuracy costs in time (issue 16 §5; docs/haptics.md, "Measured").
// - Per tangible example scene: the cost of one force tick along a path
//   through its tangible shapes, as percentiles (p50, p99, p99.9, max).
// - Function contact against polygon contact side by side, on the
//   watermelon's surface: tick cost and contact error (distance of the
//   proxy from the true surface, a fraction of the box diagonal) for the
//   function and for its triangles at several mesh resolutions.
// - The real-time loop at 1 kHz: the period's jitter percentiles, with the
//   machine's load as it is (reported, never asserted).
#include "field/field_sampler.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace fl::haptics {

struct HapticsBenchOptions {
    std::filesystem::path examples; // courseware/examples
    std::vector<double> resolutions{16, 32, 64, 128};
    int passes = 5;         // each path walked this many times per scene
    double loopSeconds = 2; // how long the real-time loop runs
    double rateHz = 1000;
};

struct TickCost {
    std::string name; // "watermelon", "function", "polygons at 64"
    double p50Us = 0, p99Us = 0, p999Us = 0, maxUs = 0;
    std::size_t ticks = 0;
    std::size_t surfaceTicks = 0, insideTicks = 0;
    double resolution = 0;                // polygon rows: the mesh's
    std::size_t triangles = 0;            // polygon rows
    double meanError = -1, maxError = -1; // contact rows: proxy to surface / diagonal
};

struct HapticsBenchResult {
    std::vector<TickCost> scenes;  // per example scene
    std::vector<TickCost> contact; // function, then polygons per resolution
    double loopRateHz = 0;
    double jitterP50Us = 0, jitterP99Us = 0, jitterP999Us = 0, jitterMaxUs = 0;
    std::size_t loopTicks = 0, lateTicks = 0;
    bool realTime = false; // the loop's thread got a real-time priority
    std::vector<std::string> notes;
};

HapticsBenchResult runHapticsBench(const HapticsBenchOptions& options);

// What accuracy costs in time, for touch, on one shape: the tool walks `path`
// (the shape's coordinates) at 1 kHz, felt by the function ("function") and by
// its triangles at each resolution ("polygons at R"); each row's tick cost
// and contact error. `onRow` hears each row as it is measured; `cancel` stops
// between rows. The Accuracy panel's touch curve and `bench haptics` share it.
std::vector<TickCost> touchSweep(const field::ImplicitField& field,
                                 const std::vector<field::Vec3>& path,
                                 const std::vector<double>& resolutions, int passes,
                                 const std::atomic<bool>* cancel = nullptr,
                                 const std::function<void(const TickCost&)>& onRow = {},
                                 std::vector<std::string>* notes = nullptr);
// A path for it on any shape: points just under its surface (a fraction of
// the box diagonal deep), where rays from the box's faces and corners towards
// its middle meet it, after an approach from outside.
std::vector<field::Vec3> pathUnderSurface(const field::ImplicitField& field, double depth = 2e-4);
std::string hapticsBenchText(const HapticsBenchResult& r);
std::string hapticsBenchJson(const HapticsBenchResult& r);

} // namespace fl::haptics
