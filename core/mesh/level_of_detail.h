#pragma once
// Continuous level of detail: the resolution a shape needs so that one cell,
// seen from the camera, covers about `pixelError` pixels — a real number the
// viewer can move smoothly as the camera approaches (with hysteresis on its
// side, so it does not re-mesh at every frame), clamped to FGeometry.lodRange.
#include "field_names.h"

namespace fl::mesh {

struct ViewForLod {
    double distance = 1;       // from the camera to the nearest point of the shape's box
    double fieldOfViewY = 0.8; // radians
    double viewportHeight = 1080;
    double pixelError = 1.5; // pixels one cell may span
};

double resolutionForView(const Box3& box, const ViewForLod& view, double minResolution = 8,
                         double maxResolution = 256);

// Whether a shape meshed at `current` should be re-meshed for `wanted`:
// only when they differ by more than `band` (25%: a change of LOD is worth it).
bool lodChangeWorthIt(double current, double wanted, double band = 0.25);

} // namespace fl::mesh
