#pragma once
// The effects plan (DESIGN §3): what in a scene varies with time and which
// tangible effects exist, so the viewer and the haptic loop simulate only what
// the scene calls for (a clock whose hands only turn never re-meshes; a scene
// with nothing tangible never starts the haptic loop).
#include "scene.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace fl::scene {

enum TimeVarying : unsigned {
    kStatic = 0,
    kGeometry = 1u << 0,     // re-mesh when t changes
    kDisplacement = 1u << 1, // FTexture3D reads t: re-mesh too
    kColour = 1u << 2,       // recolour vertices only
    kTransform = 1u << 3,    // update matrices only
    kPhysics = 1u << 4,      // haptic fields change with t
};

// What a tangible effect does to the haptic tool (DESIGN §6).
enum class TangibleKind : std::uint8_t { Friction, Tension, Density, Force };
std::string_view tangibleKindName(TangibleKind kind); // "friction", ... as plans print them

struct TangibleEffect {
    TangibleKind kind = TangibleKind::Friction;
    const Node* node = nullptr;
    std::array<double, 3> domainMin{-1, -1, -1};
    std::array<double, 3> domainMax{1, 1, 1};
    bool timeVarying = false;
};

struct PlanEntry {
    const Node* node = nullptr;
    std::string name;     // DEF name, or type and position
    std::string location; // file:line:column
    unsigned timeVarying = kStatic;
    std::string geometry; // "implicit", "parametric", "Box", "none" ...
    bool usesWallClock = false;
    // An FShape without geometry lends its appearance and physics to the
    // standard shapes grouped with it.
    bool appliesToSiblings = false;
    std::vector<TangibleEffect> tangible;
    std::vector<std::string> notes; // e.g. "driven by ROUTE from CLOCK.fraction_changed"
};

struct EffectsPlan {
    std::vector<PlanEntry> entries;
    unsigned timeVarying = kStatic; // union over entries
    bool needsHaptics = false;
    bool usesWallClock = false;
    std::size_t functionShapes = 0;
};

EffectsPlan makeEffectsPlan(const Scene& scene);

// The standard shapes an FShape without geometry lends its appearance and
// physics to (the paper's way of making a Box tangible or coloured by a
// function): every Shape below the group the FShape is a child of, each with
// its lenders in the order found.
std::unordered_map<const Node*, std::vector<const Node*>> lendingShapes(const Scene& scene);

// Those that borrow physics, each with the lender's plan entry. The haptic
// loop feels them; the grader counts them.
std::unordered_map<const Node*, const PlanEntry*> lentPhysics(const Scene& scene,
                                                              const EffectsPlan& plan);

std::vector<std::string_view> timeVaryingNames(unsigned bits); // {"geometry", "colour"}
std::string timeVaryingText(unsigned bits);                    // "geometry, colour" or "static"
std::string planText(const EffectsPlan& plan);

} // namespace fl::scene
