#pragma once
// Point clouds: an object drawn as points instead of triangles (the paper's
// "dots"), which shows what a surface cannot — the inside of a solid and its
// colouring. Implicit geometry gives points spread evenly over its surface;
// explicit geometry (an FRep solid) points through its inside; parametric
// geometry a grid over its parameter box (a solid's through its volume).
// The result is a Mesh with primitive Points and no triangles.
#include "dual_contouring.h" // MeshResult
#include "parametric.h"

#include <cstddef>
#include <cstdint>

namespace fl::mesh {

struct PointCloudOptions {
    std::size_t count = 20000; // about this many points
    std::uint32_t seed = 1;    // the same seed gives the same points
    int threads = 0;           // for the surface mesh the surface points start from
};

// Points on f = 0, evenly by area: sampled on a mesh of the surface, then
// moved onto the true surface by Newton steps; normals from the gradient.
MeshResult pointsOnSurface(const ImplicitField& field, const PointCloudOptions& options = {});
// Points where f > 0, one jittered sample per cell of a grid sized so that
// about `count` fall inside; normals zero (a solid's inside has none).
MeshResult pointsInSolid(const ImplicitField& field, const PointCloudOptions& options = {});
// A grid over the parameters the definition reads; each point carries its
// (u, v, w). Surfaces get normals, curves and solids zero.
MeshResult pointsOverParameters(const ParametricField& field,
                                const PointCloudOptions& options = {});

} // namespace fl::mesh
