#pragma once
// How an appearance or physics component sees a point of its geometry
// (docs/nodes.md, "Domains and how they are mapped"): x, y, z in the
// component's own box, u, v, w the point's place in the geometry's box in
// [0, 1] — or, on parametric geometry, the surface's own parameters.
#include "implicit_field.h" // Box3
#include "mesh.h"

#include <array>
#include <vector>

namespace fl::mesh {

// (x', y', z', u, v, w) of one point.
std::array<double, 6> componentView(const std::array<double, 3>& p, const Box3& geometry,
                                    const Box3& component);

// The same for every vertex of a mesh, as six arrays ready for a batch
// evaluation; u, v, w from mesh.parameters when the mesh has them.
std::array<std::vector<double>, 6> componentViews(const Mesh& mesh, const Box3& geometry,
                                                  const Box3& component);

} // namespace fl::mesh
