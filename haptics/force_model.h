#pragma once
// The force at one servo tick (DESIGN §6; docs/haptics.md, "How forces are
// made"): the tool point against every tangible shape of the snapshot.
//
// - Surfaces (shapes with FFriction or FTension): a contact algorithm per
//   shape (contact_algorithm.h) keeps a proxy on the surface — on f = 0 for
//   a function (ImplicitProxyContact), a god-object on the triangles for
//   standard shapes and collision "polygonal" (GodObjectContact) — sliding
//   within the friction cone. The force is a spring from the tool to the
//   proxy, damped along the normal.
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
#include "contact_algorithm.h"
#include "device/haptic_device.h"
#include "tangible_scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fl::haptics {

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
    class ShapeMaterial; // a shape's friction, as its contact algorithm asks for it
    void report(const std::string& key, const std::string& text);
    // One effect's value(s) at a point of the shape; false when the shape
    // has none of that kind or it is not a number there (reported).
    bool effectAt(ShapeState& s, scene::TangibleKind kind, const field::Vec3& p,
                  const animation::Instant& moment, double* values);
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
