#pragma once
// Helpers shared by the mesher's tests: compile a formula into a field, and
// measure how far a mesh is from the true surface.
#include "mesh/dual_contouring.h"
#include "mesh/mesh_topology.h"
#include "mesh/parametric.h"

#include <cstring>
#include <string>

namespace fl::mesh::support {

// A value of type T stored in an export's bytes at `offset` (little-endian
// files read on a little-endian machine).
template <class T>
T bytesAt(const std::string& bytes, std::size_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

ImplicitField field(const std::string& formula, double half = 1.0,
                    BoxBoundary boundary = BoxBoundary::Closed);
ImplicitField field(const std::string& formula, Box3 box,
                    BoxBoundary boundary = BoxBoundary::Closed);

// A parametric definition ("x = ...; y = ...; z = ...;") over u, v, w ranges.
ParametricField parametricField(const std::string& script, std::array<double, 2> u = {0, 1},
                                std::array<double, 2> v = {0, 1}, std::array<double, 2> w = {0, 1});

// The largest first-order distance |f| / |grad f| over the vertices and the
// triangle centroids, as a fraction of the box diagonal.
double maxSurfaceError(const ImplicitField& field, const Mesh& mesh);
// The same over the vertices only.
double maxVertexError(const ImplicitField& field, const Mesh& mesh);

// The signed area of the triangles seen from +z (x-y plane): flat shapes,
// text, trimmed patches; counter-clockwise counts positive.
double areaInXY(const Mesh& mesh);

} // namespace fl::mesh::support
