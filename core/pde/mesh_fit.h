#pragma once
// `pde fit`: a polygon mesh as PDE patches. The mesh is cut into disk
// regions (mesh_regions.h), each laid on the unit disk (disk_map.h) and
// fitted by least squares as a cap — a patch whose C0 is a point at the
// disk's pole and whose C3 is the region's border — to its vertices and
// face centres, weighted by area (the border's vertices more, so that
// neighbours' borders meet). The region whose points the fit misses most
// is split and both halves fitted again, until the patch count or the
// error asked for is reached.
#include "mesh/mesh.h"
#include "pde_model.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fl::pde {

enum class FitMethod : std::uint8_t {
    Points,         // least squares to every point of the region, with parameter correction
    BoundaryCurves, // the paper's: four curves read off the region, the patch through them
};

struct MeshFitOptions {
    FitMethod method = FitMethod::Points;
    std::size_t patches = 0; // this many (0: as few as reach `error`)
    double error = 0.003;    // RMS of the fit's misses, a fraction of the box diagonal
    std::size_t radii = 12;  // the most per patch (small regions take fewer; see fitMesh)
    // The PDE's a (the paper's a >= 1); docs/pde.md has 1, 0.5 and 0.25 measured.
    double a = 1;
    std::size_t maxPatches = 2000;
    double borderWeight = 4; // how much more a border vertex counts
    int corrections = 3;     // rounds of parameter correction after the first fit
    std::function<void(std::size_t patches, double rms)> progress;
    // Set it to stop early (the window's import dialog, when the user moves
    // on): fitMesh then returns nothing and says "cancelled".
    const std::atomic<bool>* cancel = nullptr;
};

struct MeshFit {
    Model model;
    double rms = 0;       // the fit's RMS miss (|X(u,v) - p|), fraction of the diagonal
    bool reached = false; // the error asked for (or the count) was reached
    std::vector<std::vector<std::uint32_t>> regions; // the faces each patch stands for
};

// Nullopt, with `why`, for a mesh no patch can stand for (no faces, a
// non-manifold edge, faces wound both ways); `triangleLines` locate it.
std::optional<MeshFit> fitMesh(const mesh::Mesh& mesh, const MeshFitOptions& options,
                               std::string* why,
                               const std::vector<std::uint32_t>* triangleLines = nullptr);

} // namespace fl::pde
