#include "error_driven.h"

#include <algorithm>
#include <cmath>

namespace fl::mesh {

ErrorDrivenResult meshForError(const ImplicitField& field, double targetError,
                               const MeshOptions& options, double maxResolution) {
    ErrorDrivenResult out;
    if (!(targetError > 0) || !std::isfinite(targetError)) {
        out.result.error = "the target error must be a positive fraction of the box diagonal";
        return out;
    }
    // With crossings refined onto the surface, what remains is the chord
    // error of flat triangles, about curvature * cell^2 / 8. Not knowing the
    // curvature, guess features a tenth of the diagonal across and let the
    // measurement correct it.
    const double diagonal = field.box.diagonal(), longest = field.box.longestSide();
    const double cell = diagonal * std::sqrt(0.8 * targetError);
    double resolution = std::clamp(longest / cell, 4.0, maxResolution);
    MeshOptions o = options;
    for (;;) {
        o.resolution = resolution;
        out.result = meshImplicit(field, o);
        if (!out.result.ok()) return out;
        out.error = measureSurfaceError(field, out.result.mesh);
        out.met = out.error.max <= targetError;
        if (out.met || resolution >= maxResolution) return out;
        // Error falls with the square of the cell size where smooth (linearly
        // at worst): step by a little more than the square root of the ratio.
        const double step = std::clamp(1.1 * std::sqrt(out.error.max / targetError), 1.25, 4.0);
        resolution = std::min(maxResolution, resolution * step);
    }
}

} // namespace fl::mesh
