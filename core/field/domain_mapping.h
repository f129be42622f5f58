#pragma once
// How an appearance or physics component sees a point of its geometry
// (docs/nodes.md, "Domains and how they are mapped"): x, y, z in the
// component's own box, u, v, w the point's place in the geometry's box in
// [0, 1]. The mesher's colours and displacements, the haptic effects and the
// grader all map points this one way.
#include "box3.h"

#include <array>

namespace fl::field {

// (x', y', z', u, v, w) of one point.
std::array<double, 6> componentView(const Vec3& p, const Box3& geometry, const Box3& component);

} // namespace fl::field
