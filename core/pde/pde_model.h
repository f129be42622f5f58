#pragma once
// A PDE model: the patches that stand for one shape, the box round the
// mesh they were fitted to (its diagonal is the unit of every error), and
// the boundary curves the patches share (the paper's curves, as polylines):
// a patch with a border is pulled onto it near u = 1 (pde_mesh.h), so two
// patches that share a curve meet along it exactly — no crack between them.
// A tube (a patch open at both ends, C0 a curve too) may also have a start
// border, which it meets at u = 0 the same way.
#include "pde_patch.h"

#include <cstdint>
#include <vector>

namespace fl::pde {

struct Model {
    Vec3 lo{}, hi{};
    std::vector<Patch> patches;
    std::vector<Vec3> borderPoints; // shared by the patches' borders
    // Per patch (empty, or one list a patch): its border loop, indices into
    // borderPoints in the order v increases; an empty loop: C3 as it is.
    std::vector<std::vector<std::uint32_t>> borders;
    // Per patch (empty, or one list a patch): its loop at u = 0 (C0), in the
    // order v increases; empty for a cap and for a C0 as it is.
    std::vector<std::vector<std::uint32_t>> startBorders;

    double diagonal() const;
    std::size_t coefficientCount() const; // vector coefficients, all patches
    std::size_t maxRadii() const;         // the most radii of any patch (0: none)
};

} // namespace fl::pde
