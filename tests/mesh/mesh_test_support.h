#pragma once
// Helpers shared by the mesher's tests: compile a formula into a field, and
// measure how far a mesh is from the true surface.
#include "mesh/dual_contouring.h"
#include "mesh/mesh_topology.h"

#include <string>

namespace fl::mesh::support {

ImplicitField field(const std::string& formula, double half = 1.0,
                    BoxBoundary boundary = BoxBoundary::Closed);
ImplicitField field(const std::string& formula, Box3 box,
                    BoxBoundary boundary = BoxBoundary::Closed);

// The largest first-order distance |f| / |grad f| over the vertices and the
// triangle centroids, as a fraction of the box diagonal.
double maxSurfaceError(const ImplicitField& field, const Mesh& mesh);
// The same over the vertices only.
double maxVertexError(const ImplicitField& field, const Mesh& mesh);

} // namespace fl::mesh::support
