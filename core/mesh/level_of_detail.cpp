#include "level_of_detail.h"

#include <algorithm>
#include <cmath>

namespace fl::mesh {

double resolutionForView(const Box3& box, const ViewForLod& view, double minResolution,
                         double maxResolution) {
    const double distance = std::max(view.distance, 1e-9 * box.diagonal());
    // The world size one pixel covers at that distance.
    const double pixel =
        2 * distance * std::tan(view.fieldOfViewY / 2) / std::max(view.viewportHeight, 1.0);
    const double cell = std::max(view.pixelError, 0.1) * pixel;
    const double resolution = box.longestSide() / cell;
    if (!std::isfinite(resolution)) return maxResolution;
    return std::clamp(resolution, minResolution, std::max(minResolution, maxResolution));
}

bool lodChangeWorthIt(double current, double wanted, double band) {
    if (!(current > 0)) return true;
    return wanted > current * (1 + band) || wanted < current / (1 + band);
}

} // namespace fl::mesh
