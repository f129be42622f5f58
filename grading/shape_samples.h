#pragma once
// Where the checker looks at a shape's inside: points of its solid f >= 0,
// found on a grid of its box, so that a small shape (a ball of radius 0.2 in
// a box of 2, too small for the checker's coarse mesh) is looked at where it
// is, not where the box is empty. The colour and tangible checks sample there.
#include "solid_difference.h"

#include "field/field_sampler.h"
#include "mesh/mesh.h"

#include <vector>

namespace fl::grading {

// At most `most` of `points`, spread evenly over them (all when fewer).
std::vector<mesh::Vec3f> evenlyPicked(const std::vector<mesh::Vec3f>& points, std::size_t most);

// At most `most` points inside the solid (spread evenly over those found),
// in the field's coordinates; fewer when the budget runs out (it is marked
// exceeded), none when the solid is empty.
std::vector<mesh::Vec3f> pointsInside(const field::ImplicitField& f, Budget& budget,
                                      std::size_t most = 64);

} // namespace fl::grading
