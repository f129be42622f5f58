#pragma once
// How the tool meets one shape's surface (docs/haptics.md, "How forces are
// made"): the contact kept from tick to tick and the algorithm that moves it
// — one algorithm per kind of surface, as HAPI's haptics renderers and
// CHAI3D's force algorithms are. ForceModel picks one per tangible shape and
// adds the effects (spring, friction, tension, density, force fields) on
// top; a new contact method (a Ruspini sphere proxy, say) is one more class
// here, not another branch of the servo tick.
#include "field/field_sampler.h"
#include "field/vec3.h"
#include "formula/eval_gradient.h"

#include <cstdint>
#include <memory>
#include <string_view>

namespace fl::haptics {

struct TangibleShape;

enum class ContactKind : std::uint8_t { None, Surface, Inside };
std::string_view contactName(ContactKind kind); // "none", "surface", "inside"

// One shape's contact, in the shape's coordinates.
struct ContactState {
    ContactKind contact = ContactKind::None;
    field::Vec3 proxy{};    // on the surface while in surface contact
    field::Vec3 lastTool{}; // where the tool was at the last tick
    bool hasLastTool = false;
    field::Vec3 lastNormal{}; // outward, the last one that could be computed
    bool hasNormal = false;
};

// What a contact algorithm asks of the surface's material.
class SurfaceMaterial {
  public:
    virtual ~SurfaceMaterial() = default;
    // The friction coefficient μ at a point of the surface (>= 0).
    virtual double frictionAt(const field::Vec3& p) = 0;
};

class SurfaceContact {
  public:
    virtual ~SurfaceContact() = default;
    // One tick: from the state of the last tick and the tool now (`here`:
    // the solid's value there, >= 0 inside), the new contact and proxy.
    virtual void step(ContactState& state, const field::Vec3& tool, const formula::Dual& here,
                      SurfaceMaterial& material) = 0;
};

// The algorithm for a shape with a surface (FFriction or FTension): the
// god-object on its triangles when it has them, else the proxy on f = 0
// over `sampler`. None for a shape without surface (only its inside acts).
std::unique_ptr<SurfaceContact> surfaceContactFor(const TangibleShape& shape,
                                                  field::FieldSampler* sampler);

// The solid as the servo loop feels it: f >= 0, cut by its box where the
// box closes it (min with the distance to the box's faces), with its gradient.
formula::Dual solidAt(field::FieldSampler& sampler, const field::Vec3& p);

} // namespace fl::haptics
