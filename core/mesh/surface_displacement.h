#pragma once
// A displacement texture on parametric geometry: each vertex moves along its
// normal by d, read (as for every component) in the texture's own box mapped
// onto the geometry's, with u, v, w the surface's own parameters. Normals are
// then taken from the displaced triangles. (On implicit and explicit geometry
// the displacement is added to f instead: ImplicitField::displacement.)
#include "field_names.h"
#include "mesh.h"

#include <string>
#include <vector>

namespace fl::mesh {

std::vector<std::string> displaceAlongNormals(Mesh& mesh, const Displacement& displacement,
                                              const Box3& geometryBox, double t);

} // namespace fl::mesh
