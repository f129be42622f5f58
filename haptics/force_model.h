#pragma once
// The force at one servo tick (DESIGN §6; docs/haptics.md, "How forces are
// made"): the tool point against every tangible shape of the snapshot.
//
// - Surfaces (shapes with FFriction or FTension): a proxy kept on f = 0
//   (Salisbury & Tarr). Contact begins where the segment from the tool's
//   last position to this one first meets the solid (field::marchToSurface:
//   interval-checked, so no tunnelling through shells thinner than a tick's
//   motion); in contact the tool is projected onto the tangent plane at the
//   proxy, the proxy moves towards it as far as the friction cone allows
//   (radius friction × depth), and Newton steps put it back on f = 0. The
//   force is a spring from the tool to the proxy. Where the gradient
//   vanishes (a cone's apex) the last good normal stands in; where there is
//   none, the proxy stays.
// - Polygon contact (standard shapes, collision "polygonal"): a god-object
//   against the triangles the viewer draws (TriangleBvh), sliding on up to
//   three faces, with the same friction cone.
// - FTension: a fraction of the device's maximum force (values above 1 are
//   taken as 1, said once), as OpenHaptics' pop-through is; when the spring
//   (not the damping) pushes back harder than that, the tool pops through;
//   inside, the inside acts and the surface lets the tool out freely. The
//   paper's friction 0.1, tension 1 and density 0.8 are on one scale.
// - FDensity: viscous drag inside, density (clamped to [0, 1]) times the
//   device's damping.
// - FForce: the field (N), evaluated only inside its shape.
// Every effect is read through its own domain box (field::componentView) at
// its own t (the one clock's timing at the tick's moment). A value that is
// not finite makes that effect contribute nothing that tick, and is reported
// once with its location.
#include "device/haptic_device.h"
#include "tangible_scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fl::haptics {

enum class ContactKind : std::uint8_t { None, Surface, Inside };
std::string_view contactName(ContactKind kind); // "none", "surface", "inside"

struct ToolSample {
    field::Vec3 position{}; // scene coordinates
    field::Vec3 velocity{}; // scene units per second
    animation::Instant moment;
};

struct ForceSample {
    field::Vec3 force{}; // N, along the scene's axes: what the device applies to the hand
    field::Vec3 proxy{}; // the surface proxy in contact, else the tool
    ContactKind contact = ContactKind::None;
};

struct ForceSettings {
    double stiffness = 0;      // N per scene unit of spring between tool and proxy
    double damping = 0;        // N·s per scene unit at density 1
    double contactDamping = 0; // N·s per scene unit along a surface's normal
    double maxForce = 0;       // N: the device's most; FTension is a fraction of it
};
// Half the device's stiffness, its full damping inside, and on surfaces
// K·T (twice the least damping that keeps a wall sampled every T = 1/rate
// passive: Colgate & Brown), capped by the device's damping.
ForceSettings settingsFor(const DeviceLimits& limits, double rateHz);

class ForceModel {
  public:
    explicit ForceModel(ForceSettings settings);
    ~ForceModel();
    ForceModel(const ForceModel&) = delete;
    ForceModel& operator=(const ForceModel&) = delete;

    // A new snapshot (on the servo thread, between ticks). Contact with a
    // shape that is still there — the same FShape node — is kept, so a
    // snapshot of a moving surface pushes the proxy out, not through.
    void setScene(std::shared_ptr<const TangibleScene> scene);
    const TangibleScene* scene() const { return scene_.get(); }

    ForceSample tick(const ToolSample& tool);

    // Problems found so far, each said once ("FDensity (f.x3d:12:3) is not
    // a number at (0.1, 0.2, 0.3): it adds nothing there").
    const std::vector<std::string>& reports() const { return reports_; }

  private:
    struct ShapeState;
    template <class Friction>
    void polygonStep(ShapeState& s, const field::Vec3& tool, Friction friction);
    void report(const std::string& key, const std::string& text);
    // One effect's value(s) at a point of the shape; false when the shape
    // has none of that kind or it is not a number there (reported).
    bool effectAt(ShapeState& s, scene::TangibleKind kind, const field::Vec3& p,
                  const animation::Instant& moment, double* values);
    // The implicit proxy: contact found along the tool's way, then kept on
    // f = 0 (sliding as far as the friction cone lets it).
    void implicitProxyStep(ShapeState& s, const field::Vec3& tool, const formula::Dual& here,
                           const animation::Instant& moment);
    // In surface contact: the spring to the proxy with damping along the
    // normal; tension lets the tool pop through.
    field::Vec3 surfaceForce(ShapeState& s, const ToolSample& tool);
    // Inside the solid: density's drag and the force field.
    field::Vec3 insideForce(ShapeState& s, const field::Vec3& toolInShape, const ToolSample& tool);

    ForceSettings settings_;
    std::shared_ptr<const TangibleScene> scene_;
    std::vector<std::unique_ptr<ShapeState>> states_;
    std::vector<std::string> reports_;
    std::set<std::string> reported_;
};

} // namespace fl::haptics
