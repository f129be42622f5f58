#pragma once
// What FunctionLab knows about node types: for every standard X3D/VRML node and
// every function node, its fields with type, access and default value. Plain
// data; readers, writers, the checker and docs/nodes.md all start here.
#include "field_type.h"

#include <span>
#include <string_view>

namespace fl::scene {

struct FieldSpec {
    std::string_view name;
    FieldType type;
    AccessType access;
    // The default in ClassicVRML syntax without brackets: "0 0 0", "TRUE",
    // "\"EXAMINE\" \"ANY\"", "NULL", "" (empty MF field, or no initial value
    // for inputOnly/outputOnly fields).
    std::string_view defaultValue;
};

enum class NodeFamily : std::uint8_t {
    Standard, // ISO/IEC 19775 (X3D) and ISO/IEC 14772 (VRML97)
    Function, // FunctionLab's function nodes (FShape, FGeometry, ...)
};

struct NodeSpec {
    std::string_view name;
    NodeFamily family;
    std::string_view component;        // X3D component, "FunctionLab" for function nodes
    int level;                         // component level that introduces the node
    bool inVrml97;                     // part of VRML97's closed node set
    std::string_view containerField;   // default containerField in X3D XML
    std::span<const FieldSpec> fields; // without `metadata` (every node has it)
    // Its instances declare fields of their own (`inputOnly SFTime tick`, an
    // XML <field>): Script and the shaders that take uniforms.
    bool declaresFields = false;
    // In X3D XML its element text (CDATA) is source code, one more `url` entry:
    // Script, ShaderPart, ShaderProgram, PackagedShader.
    bool sourceInText = false;
};

// Every node every X3D node has; VRML97 nodes accept it too.
extern const FieldSpec kMetadataField;

// All known node types, standard and function nodes.
std::span<const NodeSpec> nodeCatalogue();
std::span<const NodeSpec> standardNodes();
std::span<const NodeSpec> functionNodes();

// nullptr when the type is not known.
const NodeSpec* findNodeSpec(std::string_view typeName);

// For an event name of an inputOutput field, the field's name: "set_x" and
// "x_changed" give "x"; any other name gives an empty view.
std::string_view eventBaseName(std::string_view name);

// nullptr when the node has no such field. Accepts `metadata` on every node
// and, for inputOutput fields, the event names `set_name` / `name_changed`
// (with `isEventName` set so callers can refuse them where only a field name
// is allowed).
const FieldSpec* findFieldSpec(const NodeSpec& node, std::string_view fieldName,
                               bool* isEventName = nullptr);

} // namespace fl::scene
