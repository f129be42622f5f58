#pragma once
// What accuracy costs in time (issue 4 §6): the adaptive mesher and dense
// marching cubes swept over resolutions in the same run, each row measured
// the same way — triangles, function evaluations, milliseconds, and the error
// measured independently of either mesher (core/mesh/mesh_error.h).
#include "field/field_sampler.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::measure {

// Who produced a row: the meshers of `bench accuracy` and the Accuracy
// panel's meshing curve, or the contacts of its touch curve.
enum class Method : unsigned char {
    Adaptive, // the adaptive mesher (dual contouring)
    Dense,    // dense marching cubes
    Function, // touch: contact with the function itself
    Polygons, // touch: contact with its triangles
    PdeMesh,  // a PDE model meshed at a resolution (the Accuracy panel's drawing curve)
    PdeFit,   // a PDE model fitted with a number of patches (Import Mesh as PDE)
    Vtk,      // bench mesh --peer vtk: sampled into a grid, vtkFlyingEdges3D (a peer)
    Libfive,  // bench mesh --peer libfive: libfive's dual contouring (a peer)
};
const char*
methodName(Method method); // "adaptive", "dense", "function", "polygons", "vtk", "libfive" ...

struct AccuracyRow {
    Method method = Method::Adaptive;
    double resolution = 0;
    std::size_t triangles = 0;
    std::size_t evaluations = 0; // points + gradients (intervals apart)
    std::size_t intervals = 0;
    double milliseconds = 0; // a mesh's time, or a touch row's median tick
    double maxError = 0;     // fraction of the box diagonal
    double meanError = 0;
};

struct SweepOptions {
    int threads = 0;                            // both methods; 0: one per core
    std::size_t memoryBudgetBytes = 2ull << 30; // the adaptive mesher's (mesh::MeshOptions)
};

// `skipped` (when given) gets one line per run that did not produce a row,
// e.g. a resolution over the memory budget.
std::vector<AccuracyRow> runAccuracySweep(const field::ImplicitField& field,
                                          const std::vector<double>& resolutions,
                                          const SweepOptions& options = {},
                                          std::vector<std::string>* skipped = nullptr);

std::string accuracyTableText(const std::vector<AccuracyRow>& rows);
std::string accuracyJson(const std::vector<AccuracyRow>& rows);
// Error against time, log-log, one polyline per method.
std::string accuracyPlotSvg(const std::vector<AccuracyRow>& rows, const std::string& title);
// "at 256: adaptive 12.3x faster, 15.1x fewer evaluations; finest error both reach ..."
std::string accuracySummary(const std::vector<AccuracyRow>& rows);
// A method's time at a given max error, read off the log-log line between
// its two rows whose errors bracket it; none when no row reaches the error.
std::optional<double> timeAtError(const std::vector<AccuracyRow>& rows, Method method,
                                  double error);
// The same for its evaluations (points + gradients).
std::optional<double> evaluationsAtError(const std::vector<AccuracyRow>& rows, Method method,
                                         double error);

} // namespace fl::measure
