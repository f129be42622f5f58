#include "contact_algorithm.h"

#include "god_object_contact.h"
#include "implicit_proxy_contact.h"
#include "tangible_scene.h"

#include <cmath>

namespace fl::haptics {

std::string_view contactName(ContactKind kind) {
    switch (kind) {
    case ContactKind::None:
        return "none";
    case ContactKind::Surface:
        return "surface";
    case ContactKind::Inside:
        return "inside";
    }
    return "none";
}

std::unique_ptr<SurfaceContact> surfaceContactFor(const TangibleShape& shape,
                                                  field::FieldSampler* sampler) {
    if (!shape.surface) return nullptr;
    if (shape.triangles) return std::make_unique<GodObjectContact>(*shape.triangles);
    if (sampler)
        return std::make_unique<ImplicitProxyContact>(*sampler, shape.container.diagonal());
    return nullptr;
}

formula::Dual solidAt(field::FieldSampler& sampler, const field::Vec3& p) {
    formula::Dual d = sampler.gradient(p);
    const field::ImplicitField& f = sampler.field();
    if (f.boundary != field::BoxBoundary::Closed) return d;
    for (std::size_t a = 0; a < 3; ++a) {
        const double toLow = p[a] - f.box.lo[a], toHigh = f.box.hi[a] - p[a];
        if (toLow < d.v || !std::isfinite(d.v)) {
            d.v = toLow;
            d.d = {0, 0, 0};
            d.d[a] = 1;
        }
        if (toHigh < d.v) {
            d.v = toHigh;
            d.d = {0, 0, 0};
            d.d[a] = -1;
        }
    }
    return d;
}

} // namespace fl::haptics
