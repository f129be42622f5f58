// The standard X3D / VRML97 node types FunctionLab knows: every field with its
// type, access type and default value.
//
// Source: the field tables ("Node : X3D...Node { ... }") of each component in
// the X3D 3.3 abstract specification, ISO/IEC 19775-1:2013, and its component
// support tables for the component/level that introduces each node. VRML97
// (ISO/IEC 14772-1:1997) nodes are flagged `inVrml97`; their X3D access types
// are used (field = initializeOnly, eventIn = inputOnly, eventOut = outputOnly,
// exposedField = inputOutput). Where X3D renamed a VRML97 field, the VRML97
// name is kept as an extra field, marked `// VRML97 name`, so VRML97 files read.
//
// Defaults are in ClassicVRML syntax without brackets; "" is an empty MF field
// or, for inputOnly/outputOnly fields, no initial value. The `metadata` field
// every node has is not listed (see kMetadataField). Script lists only its
// standard fields; its user fields are declared in the files.
#include "node_catalogue.h"

#include <algorithm>
#include <array>

namespace fl::scene {
namespace {

using enum FieldType;
using enum AccessType;

// One field per line, as in the specification's tables.
// clang-format off

// ---------------------------------------------------------------------------
// Core
// ---------------------------------------------------------------------------

constexpr FieldSpec kMetadataBooleanFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFBool, InputOutput, ""},
};

constexpr FieldSpec kMetadataDoubleFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFDouble, InputOutput, ""},
};

constexpr FieldSpec kMetadataFloatFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFFloat, InputOutput, ""},
};

constexpr FieldSpec kMetadataIntegerFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFInt32, InputOutput, ""},
};

constexpr FieldSpec kMetadataSetFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFNode, InputOutput, ""},
};

constexpr FieldSpec kMetadataStringFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"reference", SFString, InputOutput, "\"\""},
    {"value", MFString, InputOutput, ""},
};

constexpr FieldSpec kWorldInfoFields[] = {
    {"info", MFString, InitializeOnly, ""},
    {"title", SFString, InitializeOnly, "\"\""},
};

// ---------------------------------------------------------------------------
// Grouping
// ---------------------------------------------------------------------------

constexpr FieldSpec kGroupFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kTransformFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"children", MFNode, InputOutput, ""},
    {"rotation", SFRotation, InputOutput, "0 0 1 0"},
    {"scale", SFVec3f, InputOutput, "1 1 1"},
    {"scaleOrientation", SFRotation, InputOutput, "0 0 1 0"},
    {"translation", SFVec3f, InputOutput, "0 0 0"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kSwitchFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"choice", MFNode, InputOutput, ""}, // VRML97 name
    {"whichChoice", SFInt32, InputOutput, "-1"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

// Not an X3DGroupingNode: its children are fixed once initialized.
constexpr FieldSpec kStaticGroupFields[] = {
    {"children", MFNode, InitializeOnly, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

// ---------------------------------------------------------------------------
// Networking
// ---------------------------------------------------------------------------

constexpr FieldSpec kAnchorFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"description", SFString, InputOutput, "\"\""},
    {"parameter", MFString, InputOutput, ""},
    {"url", MFString, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kInlineFields[] = {
    {"load", SFBool, InputOutput, "TRUE"},
    {"url", MFString, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kLoadSensorFields[] = {
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"timeOut", SFTime, InputOutput, "0"},
    {"watchList", MFNode, InputOutput, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"isLoaded", SFBool, OutputOnly, ""},
    {"loadTime", SFTime, OutputOnly, ""},
    {"progress", SFFloat, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// Rendering
// ---------------------------------------------------------------------------

constexpr FieldSpec kColorFields[] = {
    {"color", MFColor, InputOutput, ""},
};

constexpr FieldSpec kColorRGBAFields[] = {
    {"color", MFColorRGBA, InputOutput, ""},
};

constexpr FieldSpec kCoordinateFields[] = {
    {"point", MFVec3f, InputOutput, ""},
};

constexpr FieldSpec kCoordinateDoubleFields[] = {
    {"point", MFVec3d, InputOutput, ""},
};

constexpr FieldSpec kNormalFields[] = {
    {"vector", MFVec3f, InputOutput, ""},
};

constexpr FieldSpec kIndexedLineSetFields[] = {
    {"set_colorIndex", MFInt32, InputOnly, ""},
    {"set_coordIndex", MFInt32, InputOnly, ""},
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"colorIndex", MFInt32, InitializeOnly, ""},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"coordIndex", MFInt32, InitializeOnly, ""},
};

constexpr FieldSpec kLineSetFields[] = {
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"vertexCount", MFInt32, InputOutput, ""},
};

constexpr FieldSpec kPointSetFields[] = {
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
};

// IndexedTriangleSet, IndexedTriangleStripSet, IndexedTriangleFanSet and
// IndexedQuadSet share one field list.
constexpr FieldSpec kIndexedTriangleSetFields[] = {
    {"set_index", MFInt32, InputOnly, ""},
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"index", MFInt32, InitializeOnly, ""},
};

// TriangleSet and QuadSet share one field list.
constexpr FieldSpec kTriangleSetFields[] = {
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kTriangleStripSetFields[] = {
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"stripCount", MFInt32, InputOutput, ""},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kTriangleFanSetFields[] = {
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fanCount", MFInt32, InputOutput, ""},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kClipPlaneFields[] = {
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"plane", SFVec4f, InputOutput, "0 1 0 0"},
};

// ---------------------------------------------------------------------------
// Shape
// ---------------------------------------------------------------------------

constexpr FieldSpec kShapeFields[] = {
    {"appearance", SFNode, InputOutput, "NULL"},
    {"geometry", SFNode, InputOutput, "NULL"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kAppearanceFields[] = {
    {"fillProperties", SFNode, InputOutput, "NULL"},
    {"lineProperties", SFNode, InputOutput, "NULL"},
    {"material", SFNode, InputOutput, "NULL"},
    {"shaders", MFNode, InputOutput, ""},
    {"texture", SFNode, InputOutput, "NULL"},
    {"textureTransform", SFNode, InputOutput, "NULL"},
};

constexpr FieldSpec kMaterialFields[] = {
    {"ambientIntensity", SFFloat, InputOutput, "0.2"},
    {"diffuseColor", SFColor, InputOutput, "0.8 0.8 0.8"},
    {"emissiveColor", SFColor, InputOutput, "0 0 0"},
    {"shininess", SFFloat, InputOutput, "0.2"},
    {"specularColor", SFColor, InputOutput, "0 0 0"},
    {"transparency", SFFloat, InputOutput, "0"},
};

constexpr FieldSpec kTwoSidedMaterialFields[] = {
    {"ambientIntensity", SFFloat, InputOutput, "0.2"},
    {"backAmbientIntensity", SFFloat, InputOutput, "0.2"},
    {"backDiffuseColor", SFColor, InputOutput, "0.8 0.8 0.8"},
    {"backEmissiveColor", SFColor, InputOutput, "0 0 0"},
    {"backShininess", SFFloat, InputOutput, "0.2"},
    {"backSpecularColor", SFColor, InputOutput, "0 0 0"},
    {"backTransparency", SFFloat, InputOutput, "0"},
    {"diffuseColor", SFColor, InputOutput, "0.8 0.8 0.8"},
    {"emissiveColor", SFColor, InputOutput, "0 0 0"},
    {"shininess", SFFloat, InputOutput, "0.2"},
    {"separateBackColor", SFBool, InputOutput, "FALSE"},
    {"specularColor", SFColor, InputOutput, "0 0 0"},
    {"transparency", SFFloat, InputOutput, "0"},
};

constexpr FieldSpec kFillPropertiesFields[] = {
    {"filled", SFBool, InputOutput, "TRUE"},
    {"hatchColor", SFColor, InputOutput, "1 1 1"},
    {"hatched", SFBool, InputOutput, "TRUE"},
    {"hatchStyle", SFInt32, InputOutput, "1"},
};

constexpr FieldSpec kLinePropertiesFields[] = {
    {"applied", SFBool, InputOutput, "TRUE"},
    {"linetype", SFInt32, InputOutput, "1"},
    {"linewidthScaleFactor", SFFloat, InputOutput, "0"},
};

// ---------------------------------------------------------------------------
// Geometry3D
// ---------------------------------------------------------------------------

constexpr FieldSpec kBoxFields[] = {
    {"size", SFVec3f, InitializeOnly, "2 2 2"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kConeFields[] = {
    {"bottom", SFBool, InitializeOnly, "TRUE"},
    {"bottomRadius", SFFloat, InitializeOnly, "1"},
    {"height", SFFloat, InitializeOnly, "2"},
    {"side", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kCylinderFields[] = {
    {"bottom", SFBool, InitializeOnly, "TRUE"},
    {"height", SFFloat, InitializeOnly, "2"},
    {"radius", SFFloat, InitializeOnly, "1"},
    {"side", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"top", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kSphereFields[] = {
    {"radius", SFFloat, InitializeOnly, "1"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
};

constexpr FieldSpec kElevationGridFields[] = {
    {"set_height", MFFloat, InputOnly, ""},
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"creaseAngle", SFFloat, InitializeOnly, "0"},
    {"height", MFFloat, InitializeOnly, ""},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"xDimension", SFInt32, InitializeOnly, "0"},
    {"xSpacing", SFFloat, InitializeOnly, "1.0"},
    {"zDimension", SFInt32, InitializeOnly, "0"},
    {"zSpacing", SFFloat, InitializeOnly, "1.0"},
};

constexpr FieldSpec kExtrusionFields[] = {
    {"set_crossSection", MFVec2f, InputOnly, ""},
    {"set_orientation", MFRotation, InputOnly, ""},
    {"set_scale", MFVec2f, InputOnly, ""},
    {"set_spine", MFVec3f, InputOnly, ""},
    {"beginCap", SFBool, InitializeOnly, "TRUE"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"convex", SFBool, InitializeOnly, "TRUE"},
    {"creaseAngle", SFFloat, InitializeOnly, "0"},
    {"crossSection", MFVec2f, InitializeOnly, "1 1 1 -1 -1 -1 -1 1 1 1"},
    {"endCap", SFBool, InitializeOnly, "TRUE"},
    {"orientation", MFRotation, InitializeOnly, "0 0 1 0"},
    {"scale", MFVec2f, InitializeOnly, "1 1"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"spine", MFVec3f, InitializeOnly, "0 0 0 0 1 0"},
};

constexpr FieldSpec kIndexedFaceSetFields[] = {
    {"set_colorIndex", MFInt32, InputOnly, ""},
    {"set_coordIndex", MFInt32, InputOnly, ""},
    {"set_normalIndex", MFInt32, InputOnly, ""},
    {"set_texCoordIndex", MFInt32, InputOnly, ""},
    {"attrib", MFNode, InputOutput, ""},
    {"color", SFNode, InputOutput, "NULL"},
    {"coord", SFNode, InputOutput, "NULL"},
    {"fogCoord", SFNode, InputOutput, "NULL"},
    {"normal", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"ccw", SFBool, InitializeOnly, "TRUE"},
    {"colorIndex", MFInt32, InitializeOnly, ""},
    {"colorPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"convex", SFBool, InitializeOnly, "TRUE"},
    {"coordIndex", MFInt32, InitializeOnly, ""},
    {"creaseAngle", SFFloat, InitializeOnly, "0"},
    {"normalIndex", MFInt32, InitializeOnly, ""},
    {"normalPerVertex", SFBool, InitializeOnly, "TRUE"},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"texCoordIndex", MFInt32, InitializeOnly, ""},
};

// ---------------------------------------------------------------------------
// Geometry2D
// ---------------------------------------------------------------------------

constexpr FieldSpec kArc2DFields[] = {
    {"endAngle", SFFloat, InitializeOnly, "1.570796"},
    {"radius", SFFloat, InitializeOnly, "1"},
    {"startAngle", SFFloat, InitializeOnly, "0"},
};

constexpr FieldSpec kArcClose2DFields[] = {
    {"closureType", SFString, InitializeOnly, "\"PIE\""},
    {"endAngle", SFFloat, InitializeOnly, "1.570796"},
    {"radius", SFFloat, InitializeOnly, "1"},
    {"solid", SFBool, InitializeOnly, "FALSE"},
    {"startAngle", SFFloat, InitializeOnly, "0"},
};

constexpr FieldSpec kCircle2DFields[] = {
    {"radius", SFFloat, InitializeOnly, "1"},
};

constexpr FieldSpec kDisk2DFields[] = {
    {"innerRadius", SFFloat, InitializeOnly, "0"},
    {"outerRadius", SFFloat, InitializeOnly, "1"},
    {"solid", SFBool, InitializeOnly, "FALSE"},
};

constexpr FieldSpec kPolyline2DFields[] = {
    {"lineSegments", MFVec2f, InitializeOnly, ""},
};

constexpr FieldSpec kPolypoint2DFields[] = {
    {"point", MFVec2f, InputOutput, ""},
};

constexpr FieldSpec kRectangle2DFields[] = {
    {"size", SFVec2f, InitializeOnly, "2 2"},
    {"solid", SFBool, InitializeOnly, "FALSE"},
};

constexpr FieldSpec kTriangleSet2DFields[] = {
    {"vertices", MFVec2f, InputOutput, ""},
    {"solid", SFBool, InitializeOnly, "FALSE"},
};

// ---------------------------------------------------------------------------
// NURBS
// ---------------------------------------------------------------------------

constexpr FieldSpec kContour2DFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
};

constexpr FieldSpec kContourPolyline2DFields[] = {
    {"controlPoint", MFVec2d, InputOutput, ""},
};

constexpr FieldSpec kNurbsCurveFields[] = {
    {"controlPoint", SFNode, InputOutput, "NULL"},
    {"tessellation", SFInt32, InputOutput, "0"},
    {"weight", MFDouble, InputOutput, ""},
    {"closed", SFBool, InitializeOnly, "FALSE"},
    {"knot", MFDouble, InitializeOnly, ""},
    {"order", SFInt32, InitializeOnly, "3"},
};

constexpr FieldSpec kNurbsCurve2DFields[] = {
    {"controlPoint", MFVec2d, InputOutput, ""},
    {"tessellation", SFInt32, InputOutput, "0"},
    {"weight", MFDouble, InputOutput, ""},
    {"closed", SFBool, InitializeOnly, "FALSE"},
    {"knot", MFDouble, InitializeOnly, ""},
    {"order", SFInt32, InitializeOnly, "3"},
};

constexpr FieldSpec kNurbsPatchSurfaceFields[] = {
    {"controlPoint", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"uTessellation", SFInt32, InputOutput, "0"},
    {"vTessellation", SFInt32, InputOutput, "0"},
    {"weight", MFDouble, InputOutput, ""},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"uClosed", SFBool, InitializeOnly, "FALSE"},
    {"uDimension", SFInt32, InitializeOnly, "0"},
    {"uKnot", MFDouble, InitializeOnly, ""},
    {"uOrder", SFInt32, InitializeOnly, "3"},
    {"vClosed", SFBool, InitializeOnly, "FALSE"},
    {"vDimension", SFInt32, InitializeOnly, "0"},
    {"vKnot", MFDouble, InitializeOnly, ""},
    {"vOrder", SFInt32, InitializeOnly, "3"},
};

constexpr FieldSpec kNurbsSetFields[] = {
    {"addGeometry", MFNode, InputOnly, ""},
    {"removeGeometry", MFNode, InputOnly, ""},
    {"geometry", MFNode, InputOutput, ""},
    {"tessellationScale", SFFloat, InputOutput, "1"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kNurbsTextureCoordinateFields[] = {
    {"controlPoint", MFVec2f, InputOutput, ""},
    {"weight", MFFloat, InputOutput, ""},
    {"uDimension", SFInt32, InitializeOnly, "0"},
    {"uKnot", MFDouble, InitializeOnly, ""},
    {"uOrder", SFInt32, InitializeOnly, "3"},
    {"vDimension", SFInt32, InitializeOnly, "0"},
    {"vKnot", MFDouble, InitializeOnly, ""},
    {"vOrder", SFInt32, InitializeOnly, "3"},
};

constexpr FieldSpec kNurbsTrimmedSurfaceFields[] = {
    {"addTrimmingContour", MFNode, InputOnly, ""},
    {"removeTrimmingContour", MFNode, InputOnly, ""},
    {"controlPoint", SFNode, InputOutput, "NULL"},
    {"texCoord", SFNode, InputOutput, "NULL"},
    {"trimmingContour", MFNode, InputOutput, ""},
    {"uTessellation", SFInt32, InputOutput, "0"},
    {"vTessellation", SFInt32, InputOutput, "0"},
    {"weight", MFDouble, InputOutput, ""},
    {"solid", SFBool, InitializeOnly, "TRUE"},
    {"uClosed", SFBool, InitializeOnly, "FALSE"},
    {"uDimension", SFInt32, InitializeOnly, "0"},
    {"uKnot", MFDouble, InitializeOnly, ""},
    {"uOrder", SFInt32, InitializeOnly, "3"},
    {"vClosed", SFBool, InitializeOnly, "FALSE"},
    {"vDimension", SFInt32, InitializeOnly, "0"},
    {"vKnot", MFDouble, InitializeOnly, ""},
    {"vOrder", SFInt32, InitializeOnly, "3"},
};

// ---------------------------------------------------------------------------
// Text
// ---------------------------------------------------------------------------

constexpr FieldSpec kTextFields[] = {
    {"fontStyle", SFNode, InputOutput, "NULL"},
    {"length", MFFloat, InputOutput, ""},
    {"maxExtent", SFFloat, InputOutput, "0.0"},
    {"string", MFString, InputOutput, ""},
    {"lineBounds", MFVec2f, OutputOnly, ""},
    {"origin", SFVec3f, OutputOnly, ""},
    {"textBounds", SFVec2f, OutputOnly, ""},
    {"solid", SFBool, InitializeOnly, "FALSE"},
};

constexpr FieldSpec kFontStyleFields[] = {
    {"family", MFString, InitializeOnly, "\"SERIF\""},
    {"horizontal", SFBool, InitializeOnly, "TRUE"},
    {"justify", MFString, InitializeOnly, "\"BEGIN\""},
    {"language", SFString, InitializeOnly, "\"\""},
    {"leftToRight", SFBool, InitializeOnly, "TRUE"},
    {"size", SFFloat, InitializeOnly, "1.0"},
    {"spacing", SFFloat, InitializeOnly, "1.0"},
    {"style", SFString, InitializeOnly, "\"PLAIN\""},
    {"topToBottom", SFBool, InitializeOnly, "TRUE"},
};

// ---------------------------------------------------------------------------
// Lighting
// ---------------------------------------------------------------------------

constexpr FieldSpec kDirectionalLightFields[] = {
    {"ambientIntensity", SFFloat, InputOutput, "0"},
    {"color", SFColor, InputOutput, "1 1 1"},
    {"direction", SFVec3f, InputOutput, "0 0 -1"},
    {"global", SFBool, InputOutput, "FALSE"},
    {"intensity", SFFloat, InputOutput, "1"},
    {"on", SFBool, InputOutput, "TRUE"},
};

constexpr FieldSpec kPointLightFields[] = {
    {"ambientIntensity", SFFloat, InputOutput, "0"},
    {"attenuation", SFVec3f, InputOutput, "1 0 0"},
    {"color", SFColor, InputOutput, "1 1 1"},
    {"global", SFBool, InputOutput, "TRUE"},
    {"intensity", SFFloat, InputOutput, "1"},
    {"location", SFVec3f, InputOutput, "0 0 0"},
    {"on", SFBool, InputOutput, "TRUE"},
    {"radius", SFFloat, InputOutput, "100"},
};

// X3D's defaults; VRML97 had beamWidth 1.570796 and cutOffAngle 0.785398.
constexpr FieldSpec kSpotLightFields[] = {
    {"ambientIntensity", SFFloat, InputOutput, "0"},
    {"attenuation", SFVec3f, InputOutput, "1 0 0"},
    {"beamWidth", SFFloat, InputOutput, "0.785398"},
    {"color", SFColor, InputOutput, "1 1 1"},
    {"cutOffAngle", SFFloat, InputOutput, "1.570796"},
    {"direction", SFVec3f, InputOutput, "0 0 -1"},
    {"global", SFBool, InputOutput, "TRUE"},
    {"intensity", SFFloat, InputOutput, "1"},
    {"location", SFVec3f, InputOutput, "0 0 0"},
    {"on", SFBool, InputOutput, "TRUE"},
    {"radius", SFFloat, InputOutput, "100"},
};

// ---------------------------------------------------------------------------
// Texturing
// ---------------------------------------------------------------------------

constexpr FieldSpec kImageTextureFields[] = {
    {"url", MFString, InputOutput, ""},
    {"repeatS", SFBool, InitializeOnly, "TRUE"},
    {"repeatT", SFBool, InitializeOnly, "TRUE"},
    {"textureProperties", SFNode, InitializeOnly, "NULL"},
};

constexpr FieldSpec kPixelTextureFields[] = {
    {"image", SFImage, InputOutput, "0 0 0"},
    {"repeatS", SFBool, InitializeOnly, "TRUE"},
    {"repeatT", SFBool, InitializeOnly, "TRUE"},
    {"textureProperties", SFNode, InitializeOnly, "NULL"},
};

constexpr FieldSpec kMovieTextureFields[] = {
    {"description", SFString, InputOutput, "\"\""},
    {"loop", SFBool, InputOutput, "FALSE"},
    {"pauseTime", SFTime, InputOutput, "0"},
    {"pitch", SFFloat, InputOutput, "1.0"},
    {"resumeTime", SFTime, InputOutput, "0"},
    {"speed", SFFloat, InputOutput, "1.0"},
    {"startTime", SFTime, InputOutput, "0"},
    {"stopTime", SFTime, InputOutput, "0"},
    {"url", MFString, InputOutput, ""},
    {"duration_changed", SFTime, OutputOnly, ""},
    {"elapsedTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"isPaused", SFBool, OutputOnly, ""},
    {"repeatS", SFBool, InitializeOnly, "TRUE"},
    {"repeatT", SFBool, InitializeOnly, "TRUE"},
    {"textureProperties", SFNode, InitializeOnly, "NULL"},
};

constexpr FieldSpec kMultiTextureFields[] = {
    {"alpha", SFFloat, InputOutput, "1"},
    {"color", SFColor, InputOutput, "1 1 1"},
    {"function", MFString, InputOutput, ""},
    {"mode", MFString, InputOutput, ""},
    {"source", MFString, InputOutput, ""},
    {"texture", MFNode, InputOutput, ""},
};

constexpr FieldSpec kMultiTextureCoordinateFields[] = {
    {"texCoord", MFNode, InputOutput, ""},
};

constexpr FieldSpec kMultiTextureTransformFields[] = {
    {"textureTransform", MFNode, InputOutput, ""},
};

constexpr FieldSpec kTextureCoordinateFields[] = {
    {"point", MFVec2f, InputOutput, ""},
};

constexpr FieldSpec kTextureCoordinateGeneratorFields[] = {
    {"mode", SFString, InputOutput, "\"SPHERE\""},
    {"parameter", MFFloat, InputOutput, ""},
};

constexpr FieldSpec kTextureTransformFields[] = {
    {"center", SFVec2f, InputOutput, "0 0"},
    {"rotation", SFFloat, InputOutput, "0"},
    {"scale", SFVec2f, InputOutput, "1 1"},
    {"translation", SFVec2f, InputOutput, "0 0"},
};

constexpr FieldSpec kTexturePropertiesFields[] = {
    {"anisotropicDegree", SFFloat, InputOutput, "1"},
    {"borderColor", SFColorRGBA, InputOutput, "0 0 0 0"},
    {"borderWidth", SFInt32, InputOutput, "0"},
    {"boundaryModeR", SFString, InputOutput, "\"REPEAT\""},
    {"boundaryModeS", SFString, InputOutput, "\"REPEAT\""},
    {"boundaryModeT", SFString, InputOutput, "\"REPEAT\""},
    {"magnificationFilter", SFString, InputOutput, "\"FASTEST\""},
    {"minificationFilter", SFString, InputOutput, "\"FASTEST\""},
    {"textureCompression", SFString, InputOutput, "\"FASTEST\""},
    {"texturePriority", SFFloat, InputOutput, "0"},
    {"generateMipMaps", SFBool, InitializeOnly, "FALSE"},
};

// ---------------------------------------------------------------------------
// Interpolation
// ---------------------------------------------------------------------------

constexpr FieldSpec kColorInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFColor, InputOutput, ""},
    {"value_changed", SFColor, OutputOnly, ""},
};

constexpr FieldSpec kCoordinateInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec3f, InputOutput, ""},
    {"value_changed", MFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kCoordinateInterpolator2DFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec2f, InputOutput, ""},
    {"value_changed", MFVec2f, OutputOnly, ""},
};

// Same field list as CoordinateInterpolator; kept apart for clarity.
constexpr FieldSpec kNormalInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec3f, InputOutput, ""},
    {"value_changed", MFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kOrientationInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFRotation, InputOutput, ""},
    {"value_changed", SFRotation, OutputOnly, ""},
};

constexpr FieldSpec kPositionInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec3f, InputOutput, ""},
    {"value_changed", SFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kPositionInterpolator2DFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec2f, InputOutput, ""},
    {"value_changed", SFVec2f, OutputOnly, ""},
};

constexpr FieldSpec kScalarInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFFloat, InputOutput, ""},
    {"value_changed", SFFloat, OutputOnly, ""},
};

constexpr FieldSpec kEaseInEaseOutFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"easeInEaseOut", MFVec2f, InputOutput, ""},
    {"key", MFFloat, InputOutput, ""},
    {"modifiedFraction_changed", SFFloat, OutputOnly, ""},
};

constexpr FieldSpec kSplinePositionInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"closed", SFBool, InitializeOnly, "FALSE"},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec3f, InputOutput, ""},
    {"keyVelocity", MFVec3f, InputOutput, ""},
    {"normalizeVelocity", SFBool, InputOutput, "FALSE"},
    {"value_changed", SFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kSplinePositionInterpolator2DFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"closed", SFBool, InitializeOnly, "FALSE"},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFVec2f, InputOutput, ""},
    {"keyVelocity", MFVec2f, InputOutput, ""},
    {"normalizeVelocity", SFBool, InputOutput, "FALSE"},
    {"value_changed", SFVec2f, OutputOnly, ""},
};

constexpr FieldSpec kSplineScalarInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"closed", SFBool, InitializeOnly, "FALSE"},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFFloat, InputOutput, ""},
    {"keyVelocity", MFFloat, InputOutput, ""},
    {"normalizeVelocity", SFBool, InputOutput, "FALSE"},
    {"value_changed", SFFloat, OutputOnly, ""},
};

constexpr FieldSpec kSquadOrientationInterpolatorFields[] = {
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFRotation, InputOutput, ""},
    {"normalizeVelocity", SFBool, InputOutput, "FALSE"},
    {"value_changed", SFRotation, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// PointingDeviceSensor
// ---------------------------------------------------------------------------

constexpr FieldSpec kTouchSensorFields[] = {
    {"description", SFString, InputOutput, "\"\""},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"hitNormal_changed", SFVec3f, OutputOnly, ""},
    {"hitPoint_changed", SFVec3f, OutputOnly, ""},
    {"hitTexCoord_changed", SFVec2f, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"isOver", SFBool, OutputOnly, ""},
    {"touchTime", SFTime, OutputOnly, ""},
};

constexpr FieldSpec kPlaneSensorFields[] = {
    {"autoOffset", SFBool, InputOutput, "TRUE"},
    {"axisRotation", SFRotation, InputOutput, "0 0 1 0"},
    {"description", SFString, InputOutput, "\"\""},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"maxPosition", SFVec2f, InputOutput, "-1 -1"},
    {"minPosition", SFVec2f, InputOutput, "0 0"},
    {"offset", SFVec3f, InputOutput, "0 0 0"},
    {"isActive", SFBool, OutputOnly, ""},
    {"isOver", SFBool, OutputOnly, ""},
    {"trackPoint_changed", SFVec3f, OutputOnly, ""},
    {"translation_changed", SFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kCylinderSensorFields[] = {
    {"autoOffset", SFBool, InputOutput, "TRUE"},
    {"axisRotation", SFRotation, InputOutput, "0 0 1 0"},
    {"description", SFString, InputOutput, "\"\""},
    {"diskAngle", SFFloat, InputOutput, "0.26179167"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"maxAngle", SFFloat, InputOutput, "-1"},
    {"minAngle", SFFloat, InputOutput, "0"},
    {"offset", SFFloat, InputOutput, "0"},
    {"isActive", SFBool, OutputOnly, ""},
    {"isOver", SFBool, OutputOnly, ""},
    {"rotation_changed", SFRotation, OutputOnly, ""},
    {"trackPoint_changed", SFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kSphereSensorFields[] = {
    {"autoOffset", SFBool, InputOutput, "TRUE"},
    {"description", SFString, InputOutput, "\"\""},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"offset", SFRotation, InputOutput, "0 1 0 0"},
    {"isActive", SFBool, OutputOnly, ""},
    {"isOver", SFBool, OutputOnly, ""},
    {"rotation_changed", SFRotation, OutputOnly, ""},
    {"trackPoint_changed", SFVec3f, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// KeyDeviceSensor
// ---------------------------------------------------------------------------

constexpr FieldSpec kKeySensorFields[] = {
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"actionKeyPress", SFInt32, OutputOnly, ""},
    {"actionKeyRelease", SFInt32, OutputOnly, ""},
    {"altKey", SFBool, OutputOnly, ""},
    {"controlKey", SFBool, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"keyPress", SFString, OutputOnly, ""},
    {"keyRelease", SFString, OutputOnly, ""},
    {"shiftKey", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kStringSensorFields[] = {
    {"deletionAllowed", SFBool, InputOutput, "TRUE"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"enteredText", SFString, OutputOnly, ""},
    {"finalText", SFString, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// EnvironmentalSensor
// ---------------------------------------------------------------------------

constexpr FieldSpec kProximitySensorFields[] = {
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"size", SFVec3f, InputOutput, "0 0 0"},
    {"centerOfRotation_changed", SFVec3f, OutputOnly, ""},
    {"enterTime", SFTime, OutputOnly, ""},
    {"exitTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"orientation_changed", SFRotation, OutputOnly, ""},
    {"position_changed", SFVec3f, OutputOnly, ""},
};

constexpr FieldSpec kVisibilitySensorFields[] = {
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"size", SFVec3f, InputOutput, "0 0 0"},
    {"enterTime", SFTime, OutputOnly, ""},
    {"exitTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kTransformSensorFields[] = {
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"size", SFVec3f, InputOutput, "0 0 0"},
    {"targetObject", SFNode, InputOutput, "NULL"},
    {"enterTime", SFTime, OutputOnly, ""},
    {"exitTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"orientation_changed", SFRotation, OutputOnly, ""},
    {"position_changed", SFVec3f, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// Navigation
// ---------------------------------------------------------------------------

constexpr FieldSpec kViewpointFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"centerOfRotation", SFVec3f, InputOutput, "0 0 0"},
    {"description", SFString, InputOutput, "\"\""},
    {"fieldOfView", SFFloat, InputOutput, "0.7854"},
    {"jump", SFBool, InputOutput, "TRUE"},
    {"orientation", SFRotation, InputOutput, "0 0 1 0"},
    {"position", SFVec3f, InputOutput, "0 0 10"},
    {"retainUserOffsets", SFBool, InputOutput, "FALSE"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kOrthoViewpointFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"centerOfRotation", SFVec3f, InputOutput, "0 0 0"},
    {"description", SFString, InputOutput, "\"\""},
    {"fieldOfView", MFFloat, InputOutput, "-1 -1 1 1"},
    {"jump", SFBool, InputOutput, "TRUE"},
    {"orientation", SFRotation, InputOutput, "0 0 1 0"},
    {"position", SFVec3f, InputOutput, "0 0 10"},
    {"retainUserOffsets", SFBool, InputOutput, "FALSE"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kViewpointGroupFields[] = {
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"children", MFNode, InputOutput, ""},
    {"description", SFString, InputOutput, "\"\""},
    {"displayed", SFBool, InputOutput, "TRUE"},
    {"retainUserOffsets", SFBool, InputOutput, "FALSE"},
    {"size", SFVec3f, InputOutput, "0 0 0"},
};

constexpr FieldSpec kNavigationInfoFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"avatarSize", MFFloat, InputOutput, "0.25 1.6 0.75"},
    {"headlight", SFBool, InputOutput, "TRUE"},
    {"speed", SFFloat, InputOutput, "1.0"},
    {"transitionTime", SFTime, InputOutput, "1.0"},
    {"transitionType", MFString, InputOutput, "\"LINEAR\""},
    {"type", MFString, InputOutput, "\"EXAMINE\" \"ANY\""},
    {"visibilityLimit", SFFloat, InputOutput, "0"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
    {"transitionComplete", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kBillboardFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"axisOfRotation", SFVec3f, InputOutput, "0 1 0"},
    {"children", MFNode, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kCollisionFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"collide", SFBool, InputOutput, "TRUE"}, // VRML97 name
    {"collideTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
    {"proxy", SFNode, InitializeOnly, "NULL"},
};

constexpr FieldSpec kLODFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"level", MFNode, InputOutput, ""}, // VRML97 name
    {"level_changed", SFInt32, OutputOnly, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
    {"center", SFVec3f, InitializeOnly, "0 0 0"},
    {"forceTransitions", SFBool, InitializeOnly, "FALSE"},
    {"range", MFFloat, InitializeOnly, ""},
};

// ---------------------------------------------------------------------------
// EnvironmentalEffects
// ---------------------------------------------------------------------------

constexpr FieldSpec kBackgroundFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"groundAngle", MFFloat, InputOutput, ""},
    {"groundColor", MFColor, InputOutput, ""},
    {"backUrl", MFString, InputOutput, ""},
    {"bottomUrl", MFString, InputOutput, ""},
    {"frontUrl", MFString, InputOutput, ""},
    {"leftUrl", MFString, InputOutput, ""},
    {"rightUrl", MFString, InputOutput, ""},
    {"topUrl", MFString, InputOutput, ""},
    {"skyAngle", MFFloat, InputOutput, ""},
    {"skyColor", MFColor, InputOutput, "0 0 0"},
    {"transparency", SFFloat, InputOutput, "0"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kTextureBackgroundFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"groundAngle", MFFloat, InputOutput, ""},
    {"groundColor", MFColor, InputOutput, ""},
    {"backTexture", SFNode, InputOutput, "NULL"},
    {"bottomTexture", SFNode, InputOutput, "NULL"},
    {"frontTexture", SFNode, InputOutput, "NULL"},
    {"leftTexture", SFNode, InputOutput, "NULL"},
    {"rightTexture", SFNode, InputOutput, "NULL"},
    {"topTexture", SFNode, InputOutput, "NULL"},
    {"skyAngle", MFFloat, InputOutput, ""},
    {"skyColor", MFColor, InputOutput, "0 0 0"},
    {"transparency", SFFloat, InputOutput, "0"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kFogFields[] = {
    {"set_bind", SFBool, InputOnly, ""},
    {"color", SFColor, InputOutput, "1 1 1"},
    {"fogType", SFString, InputOutput, "\"LINEAR\""},
    {"visibilityRange", SFFloat, InputOutput, "0"},
    {"bindTime", SFTime, OutputOnly, ""},
    {"isBound", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kLocalFogFields[] = {
    {"color", SFColor, InputOutput, "1 1 1"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"fogType", SFString, InputOutput, "\"LINEAR\""},
    {"visibilityRange", SFFloat, InputOutput, "0"},
};

constexpr FieldSpec kFogCoordinateFields[] = {
    {"depth", MFFloat, InputOutput, ""},
};

// ---------------------------------------------------------------------------
// Sound
// ---------------------------------------------------------------------------

constexpr FieldSpec kAudioClipFields[] = {
    {"description", SFString, InputOutput, "\"\""},
    {"loop", SFBool, InputOutput, "FALSE"},
    {"pauseTime", SFTime, InputOutput, "0"},
    {"pitch", SFFloat, InputOutput, "1.0"},
    {"resumeTime", SFTime, InputOutput, "0"},
    {"startTime", SFTime, InputOutput, "0"},
    {"stopTime", SFTime, InputOutput, "0"},
    {"url", MFString, InputOutput, ""},
    {"duration_changed", SFTime, OutputOnly, ""},
    {"elapsedTime", SFTime, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"isPaused", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kSoundFields[] = {
    {"direction", SFVec3f, InputOutput, "0 0 1"},
    {"intensity", SFFloat, InputOutput, "1"},
    {"location", SFVec3f, InputOutput, "0 0 0"},
    {"maxBack", SFFloat, InputOutput, "10"},
    {"maxFront", SFFloat, InputOutput, "10"},
    {"minBack", SFFloat, InputOutput, "1"},
    {"minFront", SFFloat, InputOutput, "1"},
    {"priority", SFFloat, InputOutput, "0"},
    {"source", SFNode, InputOutput, "NULL"},
    {"spatialize", SFBool, InitializeOnly, "TRUE"},
};

// ---------------------------------------------------------------------------
// Time
// ---------------------------------------------------------------------------

constexpr FieldSpec kTimeSensorFields[] = {
    {"cycleInterval", SFTime, InputOutput, "1"},
    {"enabled", SFBool, InputOutput, "TRUE"},
    {"loop", SFBool, InputOutput, "FALSE"},
    {"pauseTime", SFTime, InputOutput, "0"},
    {"resumeTime", SFTime, InputOutput, "0"},
    {"startTime", SFTime, InputOutput, "0"},
    {"stopTime", SFTime, InputOutput, "0"},
    {"cycleTime", SFTime, OutputOnly, ""},
    {"elapsedTime", SFTime, OutputOnly, ""},
    {"fraction_changed", SFFloat, OutputOnly, ""},
    {"isActive", SFBool, OutputOnly, ""},
    {"isPaused", SFBool, OutputOnly, ""},
    {"time", SFTime, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// EventUtilities
// ---------------------------------------------------------------------------

constexpr FieldSpec kBooleanFilterFields[] = {
    {"set_boolean", SFBool, InputOnly, ""},
    {"inputFalse", SFBool, OutputOnly, ""},
    {"inputNegate", SFBool, OutputOnly, ""},
    {"inputTrue", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kBooleanSequencerFields[] = {
    {"next", SFBool, InputOnly, ""},
    {"previous", SFBool, InputOnly, ""},
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFBool, InputOutput, ""},
    {"value_changed", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kBooleanToggleFields[] = {
    {"set_boolean", SFBool, InputOnly, ""},
    {"toggle", SFBool, InputOutput, "FALSE"},
};

constexpr FieldSpec kBooleanTriggerFields[] = {
    {"set_triggerTime", SFTime, InputOnly, ""},
    {"triggerTrue", SFBool, OutputOnly, ""},
};

constexpr FieldSpec kIntegerSequencerFields[] = {
    {"next", SFBool, InputOnly, ""},
    {"previous", SFBool, InputOnly, ""},
    {"set_fraction", SFFloat, InputOnly, ""},
    {"key", MFFloat, InputOutput, ""},
    {"keyValue", MFInt32, InputOutput, ""},
    {"value_changed", SFInt32, OutputOnly, ""},
};

constexpr FieldSpec kIntegerTriggerFields[] = {
    {"set_boolean", SFBool, InputOnly, ""},
    {"integerKey", SFInt32, InputOutput, "-1"},
    {"triggerValue", SFInt32, OutputOnly, ""},
};

constexpr FieldSpec kTimeTriggerFields[] = {
    {"set_boolean", SFBool, InputOnly, ""},
    {"triggerTime", SFTime, OutputOnly, ""},
};

// ---------------------------------------------------------------------------
// Scripting
// ---------------------------------------------------------------------------

// Standard fields only; a Script's own fields are declared in the file.
constexpr FieldSpec kScriptFields[] = {
    {"url", MFString, InputOutput, ""},
    {"directOutput", SFBool, InitializeOnly, "FALSE"},
    {"mustEvaluate", SFBool, InitializeOnly, "FALSE"},
};

// ---------------------------------------------------------------------------
// Shaders (X3D 19775-1 §31): programs are kept and written back, never run;
// ComposedShader, PackagedShader and ShaderProgram declare their uniforms as
// fields of their own.
// ---------------------------------------------------------------------------

constexpr FieldSpec kComposedShaderFields[] = {
    {"activate", SFBool, InputOnly, ""},
    {"parts", MFNode, InputOutput, ""},
    {"isSelected", SFBool, OutputOnly, ""},
    {"isValid", SFBool, OutputOnly, ""},
    {"language", SFString, InitializeOnly, "\"\""},
};

constexpr FieldSpec kPackagedShaderFields[] = {
    {"activate", SFBool, InputOnly, ""},
    {"url", MFString, InputOutput, ""},
    {"isSelected", SFBool, OutputOnly, ""},
    {"isValid", SFBool, OutputOnly, ""},
    {"language", SFString, InitializeOnly, "\"\""},
};

constexpr FieldSpec kProgramShaderFields[] = {
    {"activate", SFBool, InputOnly, ""},
    {"programs", MFNode, InputOutput, ""},
    {"isSelected", SFBool, OutputOnly, ""},
    {"isValid", SFBool, OutputOnly, ""},
    {"language", SFString, InitializeOnly, "\"\""},
};

constexpr FieldSpec kShaderPartFields[] = {
    {"url", MFString, InputOutput, ""},
    {"type", SFString, InitializeOnly, "\"VERTEX\""},
};

constexpr FieldSpec kShaderProgramFields[] = {
    {"url", MFString, InputOutput, ""},
    {"type", SFString, InitializeOnly, "\"VERTEX\""},
};

constexpr FieldSpec kFloatVertexAttributeFields[] = {
    {"value", MFFloat, InputOutput, ""},
    {"name", SFString, InitializeOnly, "\"\""},
    {"numComponents", SFInt32, InitializeOnly, "4"},
};

constexpr FieldSpec kMatrix3VertexAttributeFields[] = {
    {"value", MFMatrix3f, InputOutput, ""},
    {"name", SFString, InitializeOnly, "\"\""},
};

constexpr FieldSpec kMatrix4VertexAttributeFields[] = {
    {"value", MFMatrix4f, InputOutput, ""},
    {"name", SFString, InitializeOnly, "\"\""},
};

// ---------------------------------------------------------------------------
// CADGeometry (QuadSet and IndexedQuadSet reuse kTriangleSetFields and
// kIndexedTriangleSetFields)
// ---------------------------------------------------------------------------

constexpr FieldSpec kCADAssemblyFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"name", SFString, InputOutput, "\"\""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kCADFaceFields[] = {
    {"name", SFString, InputOutput, "\"\""},
    {"shape", SFNode, InputOutput, "NULL"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kCADLayerFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"children", MFNode, InputOutput, ""},
    {"name", SFString, InputOutput, "\"\""},
    {"visible", MFBool, InputOutput, ""},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

constexpr FieldSpec kCADPartFields[] = {
    {"addChildren", MFNode, InputOnly, ""},
    {"removeChildren", MFNode, InputOnly, ""},
    {"center", SFVec3f, InputOutput, "0 0 0"},
    {"children", MFNode, InputOutput, ""},
    {"name", SFString, InputOutput, "\"\""},
    {"rotation", SFRotation, InputOutput, "0 0 1 0"},
    {"scale", SFVec3f, InputOutput, "1 1 1"},
    {"scaleOrientation", SFRotation, InputOutput, "0 0 1 0"},
    {"translation", SFVec3f, InputOutput, "0 0 0"},
    {"bboxCenter", SFVec3f, InitializeOnly, "0 0 0"},
    {"bboxSize", SFVec3f, InitializeOnly, "-1 -1 -1"},
};

// clang-format on

// ---------------------------------------------------------------------------
// The table
// ---------------------------------------------------------------------------

constexpr NodeSpec x3d(std::string_view name, std::string_view component, int level,
                       std::string_view container, std::span<const FieldSpec> fields) {
    return {name, NodeFamily::Standard, component, level, false, container, fields};
}

// A node of VRML97's closed set (and of X3D).
constexpr NodeSpec vrml(std::string_view name, std::string_view component, int level,
                        std::string_view container, std::span<const FieldSpec> fields) {
    return {name, NodeFamily::Standard, component, level, true, container, fields};
}

// A node whose instances declare their own fields and/or hold source code
// as XML element text.
constexpr NodeSpec withInterface(NodeSpec n, bool declaresFields, bool sourceInText) {
    n.declaresFields = declaresFields;
    n.sourceInText = sourceInText;
    return n;
}

// Sorted by name (ASCII), for binary search.
constexpr std::array kStandardNodes = {
    vrml("Anchor", "Networking", 2, "children", kAnchorFields),
    vrml("Appearance", "Shape", 1, "appearance", kAppearanceFields),
    x3d("Arc2D", "Geometry2D", 2, "geometry", kArc2DFields),
    x3d("ArcClose2D", "Geometry2D", 2, "geometry", kArcClose2DFields),
    vrml("AudioClip", "Sound", 1, "source", kAudioClipFields),
    vrml("Background", "EnvironmentalEffects", 1, "children", kBackgroundFields),
    vrml("Billboard", "Navigation", 2, "children", kBillboardFields),
    x3d("BooleanFilter", "EventUtilities", 1, "children", kBooleanFilterFields),
    x3d("BooleanSequencer", "EventUtilities", 1, "children", kBooleanSequencerFields),
    x3d("BooleanToggle", "EventUtilities", 1, "children", kBooleanToggleFields),
    x3d("BooleanTrigger", "EventUtilities", 1, "children", kBooleanTriggerFields),
    vrml("Box", "Geometry3D", 1, "geometry", kBoxFields),
    x3d("CADAssembly", "CADGeometry", 2, "children", kCADAssemblyFields),
    x3d("CADFace", "CADGeometry", 2, "children", kCADFaceFields),
    x3d("CADLayer", "CADGeometry", 2, "children", kCADLayerFields),
    x3d("CADPart", "CADGeometry", 2, "children", kCADPartFields),
    x3d("Circle2D", "Geometry2D", 2, "geometry", kCircle2DFields),
    x3d("ClipPlane", "Rendering", 5, "children", kClipPlaneFields),
    vrml("Collision", "Navigation", 2, "children", kCollisionFields),
    vrml("Color", "Rendering", 1, "color", kColorFields),
    vrml("ColorInterpolator", "Interpolation", 1, "children", kColorInterpolatorFields),
    x3d("ColorRGBA", "Rendering", 1, "color", kColorRGBAFields),
    withInterface(x3d("ComposedShader", "Shaders", 1, "shaders", kComposedShaderFields), true,
                  false),
    vrml("Cone", "Geometry3D", 1, "geometry", kConeFields),
    x3d("Contour2D", "NURBS", 4, "trimmingContour", kContour2DFields),
    x3d("ContourPolyline2D", "NURBS", 3, "children", kContourPolyline2DFields),
    vrml("Coordinate", "Rendering", 1, "coord", kCoordinateFields),
    x3d("CoordinateDouble", "NURBS", 1, "coord", kCoordinateDoubleFields),
    vrml("CoordinateInterpolator", "Interpolation", 1, "children", kCoordinateInterpolatorFields),
    x3d("CoordinateInterpolator2D", "Interpolation", 3, "children",
        kCoordinateInterpolator2DFields),
    vrml("Cylinder", "Geometry3D", 1, "geometry", kCylinderFields),
    vrml("CylinderSensor", "PointingDeviceSensor", 1, "children", kCylinderSensorFields),
    vrml("DirectionalLight", "Lighting", 1, "children", kDirectionalLightFields),
    x3d("Disk2D", "Geometry2D", 2, "geometry", kDisk2DFields),
    x3d("EaseInEaseOut", "Interpolation", 4, "children", kEaseInEaseOutFields),
    vrml("ElevationGrid", "Geometry3D", 3, "geometry", kElevationGridFields),
    vrml("Extrusion", "Geometry3D", 4, "geometry", kExtrusionFields),
    x3d("FillProperties", "Shape", 3, "fillProperties", kFillPropertiesFields),
    x3d("FloatVertexAttribute", "Shaders", 1, "attrib", kFloatVertexAttributeFields),
    vrml("Fog", "EnvironmentalEffects", 2, "children", kFogFields),
    x3d("FogCoordinate", "EnvironmentalEffects", 4, "fogCoord", kFogCoordinateFields),
    vrml("FontStyle", "Text", 1, "fontStyle", kFontStyleFields),
    vrml("Group", "Grouping", 1, "children", kGroupFields),
    vrml("ImageTexture", "Texturing", 1, "texture", kImageTextureFields),
    vrml("IndexedFaceSet", "Geometry3D", 2, "geometry", kIndexedFaceSetFields),
    vrml("IndexedLineSet", "Rendering", 1, "geometry", kIndexedLineSetFields),
    x3d("IndexedQuadSet", "CADGeometry", 1, "geometry", kIndexedTriangleSetFields),
    x3d("IndexedTriangleFanSet", "Rendering", 3, "geometry", kIndexedTriangleSetFields),
    x3d("IndexedTriangleSet", "Rendering", 3, "geometry", kIndexedTriangleSetFields),
    x3d("IndexedTriangleStripSet", "Rendering", 3, "geometry", kIndexedTriangleSetFields),
    vrml("Inline", "Networking", 2, "children", kInlineFields),
    x3d("IntegerSequencer", "EventUtilities", 1, "children", kIntegerSequencerFields),
    x3d("IntegerTrigger", "EventUtilities", 1, "children", kIntegerTriggerFields),
    x3d("KeySensor", "KeyDeviceSensor", 1, "children", kKeySensorFields),
    vrml("LOD", "Navigation", 2, "children", kLODFields),
    x3d("LineProperties", "Shape", 2, "lineProperties", kLinePropertiesFields),
    x3d("LineSet", "Rendering", 1, "geometry", kLineSetFields),
    x3d("LoadSensor", "Networking", 3, "children", kLoadSensorFields),
    x3d("LocalFog", "EnvironmentalEffects", 4, "children", kLocalFogFields),
    vrml("Material", "Shape", 1, "material", kMaterialFields),
    x3d("Matrix3VertexAttribute", "Shaders", 1, "attrib", kMatrix3VertexAttributeFields),
    x3d("Matrix4VertexAttribute", "Shaders", 1, "attrib", kMatrix4VertexAttributeFields),
    x3d("MetadataBoolean", "Core", 1, "metadata", kMetadataBooleanFields),
    x3d("MetadataDouble", "Core", 1, "metadata", kMetadataDoubleFields),
    x3d("MetadataFloat", "Core", 1, "metadata", kMetadataFloatFields),
    x3d("MetadataInteger", "Core", 1, "metadata", kMetadataIntegerFields),
    x3d("MetadataSet", "Core", 1, "metadata", kMetadataSetFields),
    x3d("MetadataString", "Core", 1, "metadata", kMetadataStringFields),
    vrml("MovieTexture", "Texturing", 3, "texture", kMovieTextureFields),
    x3d("MultiTexture", "Texturing", 2, "texture", kMultiTextureFields),
    x3d("MultiTextureCoordinate", "Texturing", 2, "texCoord", kMultiTextureCoordinateFields),
    x3d("MultiTextureTransform", "Texturing", 2, "textureTransform", kMultiTextureTransformFields),
    vrml("NavigationInfo", "Navigation", 1, "children", kNavigationInfoFields),
    vrml("Normal", "Rendering", 1, "normal", kNormalFields),
    vrml("NormalInterpolator", "Interpolation", 2, "children", kNormalInterpolatorFields),
    x3d("NurbsCurve", "NURBS", 1, "geometry", kNurbsCurveFields),
    x3d("NurbsCurve2D", "NURBS", 3, "children", kNurbsCurve2DFields),
    x3d("NurbsPatchSurface", "NURBS", 1, "geometry", kNurbsPatchSurfaceFields),
    x3d("NurbsSet", "NURBS", 2, "children", kNurbsSetFields),
    x3d("NurbsTextureCoordinate", "NURBS", 1, "texCoord", kNurbsTextureCoordinateFields),
    x3d("NurbsTrimmedSurface", "NURBS", 4, "geometry", kNurbsTrimmedSurfaceFields),
    vrml("OrientationInterpolator", "Interpolation", 1, "children", kOrientationInterpolatorFields),
    x3d("OrthoViewpoint", "Navigation", 3, "children", kOrthoViewpointFields),
    withInterface(x3d("PackagedShader", "Shaders", 1, "shaders", kPackagedShaderFields), true,
                  true),
    vrml("PixelTexture", "Texturing", 1, "texture", kPixelTextureFields),
    vrml("PlaneSensor", "PointingDeviceSensor", 1, "children", kPlaneSensorFields),
    vrml("PointLight", "Lighting", 2, "children", kPointLightFields),
    vrml("PointSet", "Rendering", 1, "geometry", kPointSetFields),
    x3d("Polyline2D", "Geometry2D", 1, "geometry", kPolyline2DFields),
    x3d("Polypoint2D", "Geometry2D", 1, "geometry", kPolypoint2DFields),
    vrml("PositionInterpolator", "Interpolation", 1, "children", kPositionInterpolatorFields),
    x3d("PositionInterpolator2D", "Interpolation", 3, "children", kPositionInterpolator2DFields),
    x3d("ProgramShader", "Shaders", 1, "shaders", kProgramShaderFields),
    vrml("ProximitySensor", "EnvironmentalSensor", 1, "children", kProximitySensorFields),
    x3d("QuadSet", "CADGeometry", 1, "geometry", kTriangleSetFields),
    x3d("Rectangle2D", "Geometry2D", 1, "geometry", kRectangle2DFields),
    vrml("ScalarInterpolator", "Interpolation", 1, "children", kScalarInterpolatorFields),
    withInterface(vrml("Script", "Scripting", 1, "children", kScriptFields), true, true),
    withInterface(x3d("ShaderPart", "Shaders", 1, "parts", kShaderPartFields), false, true),
    withInterface(x3d("ShaderProgram", "Shaders", 1, "programs", kShaderProgramFields), true, true),
    vrml("Shape", "Shape", 1, "children", kShapeFields),
    vrml("Sound", "Sound", 1, "children", kSoundFields),
    vrml("Sphere", "Geometry3D", 1, "geometry", kSphereFields),
    vrml("SphereSensor", "PointingDeviceSensor", 1, "children", kSphereSensorFields),
    x3d("SplinePositionInterpolator", "Interpolation", 4, "children",
        kSplinePositionInterpolatorFields),
    x3d("SplinePositionInterpolator2D", "Interpolation", 4, "children",
        kSplinePositionInterpolator2DFields),
    x3d("SplineScalarInterpolator", "Interpolation", 4, "children",
        kSplineScalarInterpolatorFields),
    vrml("SpotLight", "Lighting", 2, "children", kSpotLightFields),
    x3d("SquadOrientationInterpolator", "Interpolation", 5, "children",
        kSquadOrientationInterpolatorFields),
    x3d("StaticGroup", "Grouping", 3, "children", kStaticGroupFields),
    x3d("StringSensor", "KeyDeviceSensor", 2, "children", kStringSensorFields),
    vrml("Switch", "Grouping", 2, "children", kSwitchFields),
    vrml("Text", "Text", 1, "geometry", kTextFields),
    x3d("TextureBackground", "EnvironmentalEffects", 3, "children", kTextureBackgroundFields),
    vrml("TextureCoordinate", "Texturing", 1, "texCoord", kTextureCoordinateFields),
    x3d("TextureCoordinateGenerator", "Texturing", 2, "texCoord",
        kTextureCoordinateGeneratorFields),
    x3d("TextureProperties", "Texturing", 2, "textureProperties", kTexturePropertiesFields),
    vrml("TextureTransform", "Texturing", 1, "textureTransform", kTextureTransformFields),
    vrml("TimeSensor", "Time", 1, "children", kTimeSensorFields),
    x3d("TimeTrigger", "EventUtilities", 1, "children", kTimeTriggerFields),
    vrml("TouchSensor", "PointingDeviceSensor", 1, "children", kTouchSensorFields),
    vrml("Transform", "Grouping", 1, "children", kTransformFields),
    x3d("TransformSensor", "EnvironmentalSensor", 3, "children", kTransformSensorFields),
    x3d("TriangleFanSet", "Rendering", 3, "geometry", kTriangleFanSetFields),
    x3d("TriangleSet", "Rendering", 3, "geometry", kTriangleSetFields),
    x3d("TriangleSet2D", "Geometry2D", 1, "geometry", kTriangleSet2DFields),
    x3d("TriangleStripSet", "Rendering", 3, "geometry", kTriangleStripSetFields),
    x3d("TwoSidedMaterial", "Shape", 4, "material", kTwoSidedMaterialFields),
    vrml("Viewpoint", "Navigation", 1, "children", kViewpointFields),
    x3d("ViewpointGroup", "Navigation", 3, "children", kViewpointGroupFields),
    vrml("VisibilitySensor", "EnvironmentalSensor", 2, "children", kVisibilitySensorFields),
    vrml("WorldInfo", "Core", 1, "children", kWorldInfoFields),
};

constexpr bool byName(const NodeSpec& a, const NodeSpec& b) {
    return a.name < b.name;
}

static_assert(std::is_sorted(kStandardNodes.begin(), kStandardNodes.end(), byName));
static_assert(std::adjacent_find(kStandardNodes.begin(), kStandardNodes.end(),
                                 [](const NodeSpec& a, const NodeSpec& b) {
                                     return a.name == b.name;
                                 }) == kStandardNodes.end());
static_assert(std::count_if(kStandardNodes.begin(), kStandardNodes.end(),
                            [](const NodeSpec& n) { return n.inVrml97; }) == 54);

} // namespace

std::span<const NodeSpec> standardNodes() {
    return kStandardNodes;
}

} // namespace fl::scene
