#pragma once
// The X3D field types and access types, with the facts every reader and writer
// needs about them: how many numbers make one element, whether a field holds
// one value or many, and the names both encodings use.
#include <cstdint>
#include <optional>
#include <string_view>

namespace fl::scene {

enum class FieldType : std::uint8_t {
    SFBool,
    SFInt32,
    SFFloat,
    SFDouble,
    SFTime,
    SFString,
    SFVec2f,
    SFVec2d,
    SFVec3f,
    SFVec3d,
    SFVec4f,
    SFVec4d,
    SFRotation,
    SFColor,
    SFColorRGBA,
    SFImage,
    SFMatrix3f,
    SFMatrix3d,
    SFMatrix4f,
    SFMatrix4d,
    SFNode,
    MFBool,
    MFInt32,
    MFFloat,
    MFDouble,
    MFTime,
    MFString,
    MFVec2f,
    MFVec2d,
    MFVec3f,
    MFVec3d,
    MFVec4f,
    MFVec4d,
    MFRotation,
    MFColor,
    MFColorRGBA,
    MFImage,
    MFMatrix3f,
    MFMatrix3d,
    MFMatrix4f,
    MFMatrix4d,
    MFNode,
    // A field of a node we do not know: its value is kept as the source text
    // so that a round trip does not lose it.
    Unknown,
};

// X3D names; VRML97's field/eventIn/eventOut/exposedField map onto them.
enum class AccessType : std::uint8_t { InitializeOnly, InputOnly, OutputOnly, InputOutput };

std::string_view fieldTypeName(FieldType type);
std::optional<FieldType> parseFieldType(std::string_view name);

std::string_view accessTypeName(AccessType access);               // X3D spelling
std::string_view vrml97AccessTypeName(AccessType access);         // field, eventIn, ...
std::optional<AccessType> parseAccessType(std::string_view name); // either spelling

bool isMultiple(FieldType type);    // MF*
FieldType singleOf(FieldType type); // MFVec3f -> SFVec3f; SF types map to themselves
bool holdsNodes(FieldType type);    // SFNode, MFNode
bool holdsStrings(FieldType type);  // SFString, MFString
bool isIntegral(FieldType type);    // Bool, Int32, Image
// Numbers per element: SFVec3f 3, SFRotation 4, SFMatrix4f 16; 0 for strings,
// nodes, images (variable) and Unknown.
int componentsPerElement(FieldType type);

bool canRead(AccessType access);         // a ROUTE may start here: outputOnly, inputOutput
bool canWrite(AccessType access);        // a ROUTE may end here: inputOnly, inputOutput
bool hasInitialValue(AccessType access); // initializeOnly, inputOutput

} // namespace fl::scene
