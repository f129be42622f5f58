#pragma once
// A PDE model as triangles: each patch sampled on a grid in (u, v), v
// closing round on itself; a boundary curve that degenerates to a point (a
// cap's C0) becomes one vertex, so no triangle there has zero area.
// Triangles wind counter-clockwise about Xu × Xv, the normal's direction.
#include "mesh/mesh.h"
#include "pde_model.h"

namespace fl::pde {

struct MeshOptions {
    int stepsU = 16; // rows of quads along u, per patch
    int stepsV = 32; // columns round v, per patch
    // The most grid cells (stepsU x stepsV, all patches together) a model is
    // meshed with: a model from others may hold a million patches.
    double maxCells = 8e6;
};

// The grid meshModel uses: `options`, made coarser (never below 1 x 3) when
// the model's patches would pass maxCells. `fits` false: not even the
// coarsest grid of every patch fits (meshModel then meshes nothing).
struct BoundedGrid {
    MeshOptions options;
    bool reduced = false, fits = true;
};
BoundedGrid boundedGrid(const Model& model, const MeshOptions& options);
// Limits the grid to what can be allocated: steps are clamped to [1, 4096],
// and the whole to boundedGrid's.
mesh::Mesh meshModel(const Model& model, const MeshOptions& options = {});
// Options for a resolution as the scene's meshers read it (cells along the
// longest side): stepsU = N / 2, stepsV = N, at least 4 and 8.
MeshOptions meshOptionsFor(double resolution);

} // namespace fl::pde
