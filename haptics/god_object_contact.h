#pragma once
// The god-object against triangles (Zilles & Salisbury), for standard
// shapes and collision "polygonal": the proxy goes towards the tool until a
// front face stops it, then slides on up to three faces' planes; friction
// holds it within its cone. The triangles are the ones the viewer draws
// (TriangleBvh).
#include "contact_algorithm.h"

namespace fl::haptics {

class TriangleBvh;

class GodObjectContact final : public SurfaceContact {
  public:
    explicit GodObjectContact(const TriangleBvh& triangles) : bvh_(triangles) {}
    void step(ContactState& state, const field::Vec3& tool, const formula::Dual& here,
              SurfaceMaterial& material) override;

  private:
    const TriangleBvh& bvh_;
};

} // namespace fl::haptics
