// FunctionLab's function nodes (DESIGN §3, docs/nodes.md): geometry, appearance
// and physics defined by formulas, each in its own domain box, each with its
// own timing. The meaning of every field is documented in docs/nodes.md; keep
// the two in step.
#include "node_catalogue.h"

#include <algorithm>
#include <array>

namespace fl::scene {
namespace {

using enum FieldType;
using enum AccessType;

// Timing every function node carries: `cycleInterval` seconds of the chosen
// clock map onto `timeSpan` of t; `timeBase` picks the clock ("scene": time
// since the scene started, paused and scrubbed by the user; "local": the wall
// clock in the local time zone; "utc": the wall clock in UTC).
#define FL_TIMING_FIELDS                                                                           \
    {"cycleInterval", SFTime, InputOutput, "1"}, {"timeSpan", SFVec2f, InputOutput, "0 1"},        \
        {"loop", SFBool, InputOutput, "FALSE"}, {"startTime", SFTime, InputOutput, "0"},           \
        {"stopTime", SFTime, InputOutput, "0"}, {                                                  \
        "timeBase", SFString, InitializeOnly, "\"scene\""                                          \
    }

// The box a component is defined in; it is mapped onto the geometry's box.
#define FL_DOMAIN_FIELDS                                                                           \
    {"domainMin", SFVec3f, InputOutput, "-1 -1 -1"}, {                                             \
        "domainMax", SFVec3f, InputOutput, "1 1 1"                                                 \
    }

constexpr FieldSpec kFShapeFields[] = {
    {"geometry", SFNode, InputOutput, "NULL"},
    {"appearance", SFNode, InputOutput, "NULL"},
    {"physics", SFNode, InputOutput, "NULL"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kFGeometryFields[] = {
    {"type", SFString, InputOutput, "\"implicit\""},
    {"definition", MFString, InputOutput, ""},
    {"uRange", SFVec2f, InputOutput, "0 1"},
    {"vRange", SFVec2f, InputOutput, "0 1"},
    {"wRange", SFVec2f, InputOutput, "0 1"},
    {"resolution", SFFloat, InputOutput, "32"},
    {"lod", SFBool, InputOutput, "TRUE"},
    {"lodRange", SFVec2f, InputOutput, "8 256"},
    {"points", SFInt32, InputOutput, "0"},
    FL_DOMAIN_FIELDS,
    {"setOperations", SFString, InitializeOnly, "\"minmax\""},
    {"rfunctionM", SFFloat, InitializeOnly, "0"},
    {"rfunctionAlpha", SFFloat, InitializeOnly, "0"},
    {"collision", SFString, InputOutput, "\"function\""},
    FL_TIMING_FIELDS,
};

// A PDE model (`functionlab pde fit`, docs/pde.md) as geometry: its url is
// read like an Inline's (inside the scene's folder only); each patch is
// meshed at resolution/2 steps along u and resolution round v, varied by
// the level of detail within lodRange like an FGeometry.
constexpr FieldSpec kFPdeSurfaceFields[] = {
    {"url", MFString, InputOutput, ""},
    {"resolution", SFFloat, InputOutput, "32"},
    {"lod", SFBool, InputOutput, "TRUE"},
    {"lodRange", SFVec2f, InputOutput, "8 128"},
};

constexpr FieldSpec kFAppearanceFields[] = {
    {"material", SFNode, InputOutput, "NULL"},
    {"texture", SFNode, InputOutput, "NULL"},
    {"textureTransform", SFNode, InputOutput, "NULL"},
};

constexpr FieldSpec kFMaterialFields[] = {
    {"type", SFString, InputOutput, "\"parametric\""},
    {"definition", MFString, InputOutput, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFColor, InputOutput, ""},
    {"diffuseColor", SFColor, InputOutput, "0.8 0.8 0.8"},
    {"ambientIntensity", SFFloat, InputOutput, "0.2"},
    {"emissiveColor", SFColor, InputOutput, "0 0 0"},
    {"specularColor", SFColor, InputOutput, "0 0 0"},
    {"shininess", SFFloat, InputOutput, "0.2"},
    {"transparency", SFFloat, InputOutput, "0"},
    {"transparencyDefinition", MFString, InputOutput, ""},
    FL_DOMAIN_FIELDS,
    FL_TIMING_FIELDS,
};

constexpr FieldSpec kFPhysicsFields[] = {
    {"surface", SFNode, InputOutput, "NULL"},
    {"density", SFNode, InputOutput, "NULL"},
    {"force", SFNode, InputOutput, "NULL"},
};

constexpr FieldSpec kFSurfaceFields[] = {
    {"friction", SFNode, InputOutput, "NULL"},
    {"tension", SFNode, InputOutput, "NULL"},
};

// FTexture3D (a displacement: added to f for FRep geometry, along the normal
// for parametric geometry), FFriction, FTension and FDensity (one explicit
// function of x, y, z, t) and FForce (a script assigning fx, fy, fz): one
// definition in its own domain, with timing. What each definition must
// produce is in function_definitions.cpp.
constexpr FieldSpec kOneDefinitionFields[] = {
    {"definition", MFString, InputOutput, ""},
    FL_DOMAIN_FIELDS,
    FL_TIMING_FIELDS,
};

constexpr FieldSpec kFTransformFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"translation", MFString, InputOutput, ""},
    {"rotationAxis", SFVec3f, InputOutput, "0 0 1"},
    {"rotationAngle", MFString, InputOutput, ""},
    {"scale", MFString, InputOutput, ""},
    {"operation", SFString, InputOutput, "\"group\""},
    {"morphFactor", MFString, InputOutput, ""},
    {"operationDefinition", MFString, InputOutput, ""},
    FL_TIMING_FIELDS,
};

#undef FL_TIMING_FIELDS
#undef FL_DOMAIN_FIELDS

constexpr NodeSpec fn(std::string_view name, std::string_view container,
                      std::span<const FieldSpec> fields) {
    return {name, NodeFamily::Function, "FunctionLab", 1, false, container, fields};
}

// Sorted by name.
constexpr std::array kFunctionNodes = {
    fn("FAppearance", "appearance", kFAppearanceFields),
    fn("FDensity", "density", kOneDefinitionFields),
    fn("FForce", "force", kOneDefinitionFields),
    fn("FFriction", "friction", kOneDefinitionFields),
    fn("FGeometry", "geometry", kFGeometryFields),
    fn("FMaterial", "material", kFMaterialFields),
    fn("FPdeSurface", "geometry", kFPdeSurfaceFields),
    fn("FPhysics", "physics", kFPhysicsFields),
    fn("FShape", "children", kFShapeFields),
    fn("FSurface", "surface", kFSurfaceFields),
    fn("FTension", "tension", kOneDefinitionFields),
    fn("FTexture3D", "texture", kOneDefinitionFields),
    fn("FTransform", "children", kFTransformFields),
};

static_assert(std::is_sorted(kFunctionNodes.begin(), kFunctionNodes.end(),
                             [](const NodeSpec& a, const NodeSpec& b) { return a.name < b.name; }));

} // namespace

std::span<const NodeSpec> functionNodes() {
    return kFunctionNodes;
}

} // namespace fl::scene
