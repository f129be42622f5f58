#pragma once
// How far a mesh is from the true surface, measured independently of how it
// was made: the first-order distance |f| / |grad f| at every vertex and at
// seven points of every triangle (its centroid, one towards each corner, the
// middle of each edge), as a fraction of the domain box's diagonal. Where
// the box closes the solid, the distance to the box face counts (the face is
// part of that solid's boundary).
#include "field_names.h"
#include "mesh.h"

namespace fl::mesh {

struct SurfaceError {
    double max = 0; // fraction of the box diagonal
    double mean = 0;
    std::size_t samples = 0;
};

SurfaceError measureSurfaceError(const ImplicitField& field, const Mesh& mesh);

} // namespace fl::mesh
