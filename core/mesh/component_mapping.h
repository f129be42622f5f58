#pragma once
// How an appearance component sees the vertices of its geometry's mesh
// (field/domain_mapping.h for one point) — on parametric geometry u, v, w
// are the surface's own parameters.
#include "field/domain_mapping.h"
#include "field_names.h"
#include "mesh.h"

#include <array>
#include <vector>

namespace fl::mesh {

using field::componentView; // (x', y', z', u, v, w) of one point

// The same for every vertex of a mesh, as six arrays ready for a batch
// evaluation; u, v, w from mesh.parameters when the mesh has them.
std::array<std::vector<double>, 6> componentViews(const Mesh& mesh, const Box3& geometry,
                                                  const Box3& component);

} // namespace fl::mesh
