#pragma once
// What the servo loop touches: an immutable snapshot of the scene's tangible
// shapes at one moment (DESIGN §6) — each shape's field exactly as the viewer
// meshes it (ShapeMesh::field), its placement in the scene, and its effects
// (friction, tension, density, force) as compiled tapes with their domain
// boxes and timing from the one clock. Made off the servo thread (meshing may
// take milliseconds), swapped in whole; the servo thread only reads it.
//
// Only what the effects plan calls for is here: a scene with nothing tangible
// gives an empty snapshot and the loop never starts.
#include "animation/animator.h"
#include "field/affine.h"
#include "field/field_sampler.h"
#include "formula/tape.h"
#include "scene/effects_plan.h"
#include "scene/scene.h"
#include "triangle_bvh.h"

#include <memory>
#include <string>
#include <vector>

namespace fl::haptics {

struct EffectField {
    scene::TangibleKind kind = scene::TangibleKind::Friction;
    formula::Tape tape;       // one value (friction, tension, density) or three (fx, fy, fz)
    field::Box3 componentBox; // its own domain box
    animation::FunctionTiming timing; // its t at any moment
    bool readsTime = false;           // the tape reads t: evaluated with the tick's t
    std::string location;             // file:line:column of its definition
};

struct TangibleShape {
    std::string name; // "FShape WATERMELON (file:line:col)"
    const scene::Node* shape = nullptr;
    // The solid f >= 0 as meshed, in the shape's own coordinates. Null for a
    // parametric solid: then only its inside acts, taken as its domain box.
    std::shared_ptr<const field::ImplicitField> field;
    field::Box3 container; // the shape's coordinates: where its inside is looked for
    // Polygon contact: the triangles the viewer draws (standard geometry, or
    // collision "polygonal"), in the shape's coordinates. Null: function contact.
    std::shared_ptr<const TriangleBvh> triangles;
    // Where the effects look: the box their domain boxes are mapped from, in
    // the coordinates `effectFrame` takes the shape's to — the shape's own box
    // (identity) for a function shape; the lending FShape's bbox, in its own
    // coordinates (its group's), for standard shapes that borrow its physics.
    field::Box3 geometryBox;
    field::Affine effectFrame;
    field::Affine toScene; // the shape's coordinates to the scene's
    field::Affine toShape; // and back
    // Touchable as a surface (it has FFriction or FTension); otherwise only
    // its inside acts (density, a force field's container).
    bool surface = false;
    std::vector<EffectField> effects;
    const EffectField* effect(scene::TangibleKind kind) const;
};

struct TangibleScene {
    std::vector<TangibleShape> shapes;
    // Tangible shapes left out, and why ("standard geometry: polygon contact
    // is not rendered yet").
    std::vector<std::string> notes;
    // A shape's geometry moves with t: the snapshot must be made again as time
    // passes (effects that read t do not need that: they take the tick's t).
    bool geometryVaries = false;
    animation::Instant moment; // the moment it shows
    bool empty() const { return shapes.empty(); }
};

// The snapshot at the moment `clock` was last ticked to (`moment`), for the
// shapes the plan lists as tangible.
TangibleScene makeTangibleScene(const scene::Scene& scene, const scene::EffectsPlan& plan,
                                const animation::Animator& clock, const animation::Instant& moment);

// The same, running the scene's animation to `sceneSeconds` itself (as
// `render --time` does): for the command line and tests.
TangibleScene makeTangibleScene(const scene::Scene& scene, double sceneSeconds);

} // namespace fl::haptics
