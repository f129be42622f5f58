#pragma once
// A PDE model: the patches that stand for one shape, and the box round
// the mesh they were fitted to (its diagonal is the unit of every error).
#include "pde_patch.h"

#include <vector>

namespace fl::pde {

struct Model {
    Vec3 lo{}, hi{};
    std::vector<Patch> patches;

    double diagonal() const;
    std::size_t coefficientCount() const; // vector coefficients, all patches
};

} // namespace fl::pde
