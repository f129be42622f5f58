#pragma once
// The boundary curves a PDE model keeps: every region's border loop (mesh
// vertex ids, in the order the patch's v increases), simplified so that
// the model's size follows the shape, not the mesh — each stretch of border
// between two neighbours (a seam) keeps its ends and the vertices
// Douglas–Peucker keeps within `tolerance`. Both sides of a seam keep the
// same vertices (a seam is simplified in one canonical direction), so the
// patches still meet on shared points, without cracks.
#include "mesh/mesh.h"
#include "pde_patch.h"

#include <cstdint>
#include <vector>

namespace fl::pde {

struct BorderCurves {
    std::vector<Vec3> points;                      // shared, numbered from 0
    std::vector<std::vector<std::uint32_t>> loops; // per region: indices into points
};

BorderCurves borderCurves(const mesh::Mesh& mesh,
                          const std::vector<std::vector<std::uint32_t>>& loops, double tolerance);

} // namespace fl::pde
