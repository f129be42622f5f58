#pragma once
// Adaptive polygonization of implicit and explicit (FRep) geometry: an octree
// over the domain box pruned with the interval evaluator (space that cannot
// hold the surface is never sampled), then dual contouring (Ju et al. 2002) on
// the surviving blocks: surface crossings refined onto f = 0 with normals from
// the analytic gradient, one vertex per cell placed by a quadratic error
// function so the sharp edges and corners of min/max set operations stay
// sharp. Blocks run on every core; the output is the same whatever the number
// of threads. docs/meshing.md describes the behaviour on hard cases.
#include "field_names.h"
#include "mesh.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fl::mesh {

struct MeshOptions {
    // Cells along the box's longest side: a continuous parameter (12.5 is a
    // valid resolution). Cells are as near to cubes as the box allows.
    double resolution = 64;
    // Regula falsi steps that move each edge crossing onto f = 0 after the
    // linear guess (0: linear interpolation only, as marching cubes does).
    int refineSteps = 1;
    int threads = 0; // 0: one per core
    // Each block samples the formula simplified for it (the min, max and
    // select its interval decides dropped: formula/tape_simplify.h); the mesh
    // is the same bit for bit either way (off: for tests and benchmarks).
    bool simplifyPerBlock = true;
    std::size_t memoryBudgetBytes = 2ull << 30; // refuse (with a message) what would need more
    const std::atomic<bool>* cancel = nullptr;  // set it to stop early
    // Fraction done in [0, 1]; called from worker threads, one call at a time.
    std::function<void(double)> progress;
};

struct MeshStats {
    std::array<int, 3> cells{}; // grid cells per axis
    std::array<double, 3> cellSize{};
    std::size_t blocks = 0;       // blocks of the grid
    std::size_t activeBlocks = 0; // blocks the intervals could not rule out
    std::size_t surfaceCells = 0; // cells with a vertex
    EvaluationCounts evaluations;
    double milliseconds = 0;
    // Parametric geometry: the largest distance measured between the object
    // and its sampled chords (0 when not measured: uniform sampling).
    double chordError = 0;
};

struct MeshResult {
    Mesh mesh;
    MeshStats stats;
    std::vector<std::string> warnings; // NaN regions, no sign change, ...
    std::string error;                 // set when nothing was meshed (budget, bad box)
    bool cancelled = false;
    // False for an implicit surface (BoxBoundary::Open) that leaves its box or
    // does not close: it has two sides to show. Set by those who orient it.
    bool closedSurface = true;
    bool ok() const { return error.empty() && !cancelled; }
};

MeshResult meshImplicit(const ImplicitField& field, const MeshOptions& options = {});

} // namespace fl::mesh
