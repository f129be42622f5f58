#include "pde_model.h"

#include <algorithm>
#include <cmath>

namespace fl::pde {

double Model::diagonal() const {
    return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

std::size_t Model::coefficientCount() const {
    std::size_t n = 0;
    for (const Patch& p : patches)
        n += p.coefficientCount();
    return n;
}

std::size_t Model::maxRadii() const {
    std::size_t n = 0;
    for (const Patch& p : patches)
        n = std::max(n, p.radii());
    return n;
}

} // namespace fl::pde
