#pragma once
// The proxy on f = 0 (Salisbury & Tarr): contact begins where the segment
// from the tool's last position to this one first meets the solid
// (field::marchToSurface: interval-checked, so no tunnelling through shells
// thinner than a tick's motion); in contact the tool is projected onto the
// tangent plane at the proxy, the proxy moves towards it as far as the
// friction cone allows (radius μ × depth), and Newton steps put it back on
// f = 0. Where the gradient vanishes (a cone's apex) the last good normal
// stands in; where there is none, the proxy stays.
#include "contact_algorithm.h"

namespace fl::haptics {

class ImplicitProxyContact final : public SurfaceContact {
  public:
    // `diagonal`: of the shape's container, the scale of its tolerances.
    ImplicitProxyContact(field::FieldSampler& sampler, double diagonal)
        : sampler_(sampler), diagonal_(diagonal) {}
    void step(ContactState& state, const field::Vec3& tool, const formula::Dual& here,
              SurfaceMaterial& material) override;

  private:
    // In contact: the proxy slides towards the tool's projection, within the
    // friction cone, and back onto f = 0.
    void slide(ContactState& s, const field::Vec3& tool, SurfaceMaterial& material);

    field::FieldSampler& sampler_;
    double diagonal_;
};

} // namespace fl::haptics
