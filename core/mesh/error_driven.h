#pragma once
// Meshing to an accuracy instead of a resolution: start from a resolution the
// error usually needs, measure the error independently (mesh_error.h), and
// refine until the target is met — so the answer is honest, not a guess.
#include "dual_contouring.h"
#include "mesh_error.h"

namespace fl::mesh {

struct ErrorDrivenResult {
    MeshResult result;
    SurfaceError error; // measured on the mesh returned
    bool met = false;   // the target was reached within the limits
};

// `targetError` as a fraction of the box diagonal (> 0). `options.resolution`
// is ignored; at most `maxResolution` cells along the longest side.
ErrorDrivenResult meshForError(const ImplicitField& field, double targetError,
                               const MeshOptions& options, double maxResolution = 1024);

} // namespace fl::mesh
