#pragma once
// How close a fitted model is to the mesh it stands for, measured as any
// tool would measure the file: the model encoded, read back, meshed at the
// grid every figure of docs/pde.md uses (16 x 32 per patch), and compared
// with the mesh by exact point-to-triangle distances both ways. `pde fit
// --json`, `bench pde` and the window's Import Mesh as PDE all report it.
#include "mesh/mesh.h"
#include "mesh/surface_distance.h"
#include "pde_file.h"
#include "pde_mesh.h"

#include <optional>
#include <string>

namespace fl::pde {

struct FitMeasure {
    std::string bytes;              // the file as written
    Model model;                    // the file read back: what any reader sees
    mesh::Mesh rebuilt;             // the model meshed
    mesh::SurfaceDistance distance; // rebuilt against the mesh, in the mesh's units
    double diagonal = 1;            // the model's box diagonal (1 for a point)
    double rms() const { return distance.rms / diagonal; }
    double hausdorff() const { return distance.hausdorff / diagonal; }
};

struct MeasureOptions {
    bool text = false; // the text form (else binary with `encode`)
    EncodeOptions encode;
    std::size_t samples = 100000; // each way
    MeshOptions grid{16, 32};
    // The original's tree, when the caller keeps one for many fits of it
    // (built here otherwise); it must be of `original`.
    const mesh::TriangleTree* originalTree = nullptr;
};

// Nullopt, with `why`, only when the encoded model does not read back (a bug).
std::optional<FitMeasure> measureFit(const mesh::Mesh& original, const Model& model,
                                     const MeasureOptions& options, std::string* why = nullptr);

} // namespace fl::pde
