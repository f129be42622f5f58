#pragma once
// What an assignment asks for, as the checker understands it: each
// automatic requirement has a kind (a type, never a string the code
// compares), an id the assignment chose (tests outside this repository rely
// on the ids of `implicit-fantasies`), points and parameters; and what the
// checker found — met or not, with evidence and the places in the files.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::grading {

enum class RequirementKind : std::uint8_t {
    ImplicitSurface, // a shown implicit surface f(x,y,z,t) = 0
    ExplicitSolid,   // a shown FRep solid f >= 0
    Parametric,      // a shown parametric curve, surface or solid
    SetOperations,   // at least `minimum` live set operations of `minimumKinds` kinds
    Morphing,        // a shown shape's geometry changes with time
    Animation,       // something shown moves, turns or scales with time
    LevelOfDetail,   // function shapes drawn with continuous level of detail
    FunctionColour,  // a colour defined by a function that varies over the shape or in time
    Tangible,        // a shown shape with `minimum` kinds of tangible effect (FPhysics)
    PdeSurface,      // a shown FPdeSurface whose model reads and draws (docs/pde.md)
};

// The manifest's word for each kind ("implicit-surface", "set-operations" ...).
std::optional<RequirementKind> requirementKindNamed(std::string_view word);
std::string_view requirementKindName(RequirementKind kind);

struct Requirement {
    std::string id;
    RequirementKind kind = RequirementKind::ImplicitSurface;
    std::string description;
    double points = 1;
    int minimum = 1;      // SetOperations: how many live operations; Tangible: effect kinds
    int minimumKinds = 1; // SetOperations: of how many different kinds
    // FunctionColour: a colour that changes only in time does not count
    // (manifest "varies": "over-shape"; "over-shape-or-time" by default).
    bool variesOverShape = false;
};

struct Location {
    std::string file;
    int line = 0;
    int column = 0;
    bool operator==(const Location&) const = default;
};

struct RequirementResult {
    std::string id;
    RequirementKind kind = RequirementKind::ImplicitSurface;
    bool met = false;
    double points = 0, maxPoints = 0;
    // Met: what meets it; not met: why not, in words a student understands.
    std::string evidence;
    std::vector<Location> locations;
};

} // namespace fl::grading
