#pragma once
// The scene model every part reads: nodes with typed fields, DEF names shared
// by USE, ROUTEs, PROTO declarations and their expanded instances. Encoding-
// neutral: the X3D XML, ClassicVRML and VRML97 readers fill it, the writers
// print it. Plain data; the scene owns every node, references are pointers.
#include "field_type.h"
#include "formula/compiler.h"
#include "formula/tape.h"
#include "node_catalogue.h"
#include "node_kind.h"
#include "scene_diagnostic.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace fl::scene {

struct Node;
struct ProtoDeclaration;
struct Scene;

enum class Encoding { Vrml97, ClassicVrml, Xml };

// How the characters of a string value were written in its file, so that an
// offset into the decoded string can be mapped back to line:column.
enum class StringEscapes : std::uint8_t {
    Classic,            // "..." with \" and \\ escapes
    XmlAttribute,       // attribute text: entities and character references
    XmlAttributeQuoted, // a "..." element of an MFString inside an XML attribute
    XmlText,            // element text or CDATA (Script source)
    None,               // not from a file (defaults, built by code)
};

struct StringOrigin {
    int file = -1;          // index into Scene::files; -1 when not from a file
    std::size_t offset = 0; // byte offset of the first content character
    StringEscapes escapes = StringEscapes::None;
};

// One field value. Numbers of every numeric type live in `numbers` (booleans as
// 0/1, SFImage as its integers); strings in `strings`; nodes in `nodes` (an
// SFNode holds zero or one; NULL is empty). A value of an unknown field keeps
// its source text in `strings[0]`.
struct FieldValue {
    FieldType type = FieldType::Unknown;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    std::vector<Node*> nodes;
    std::vector<StringOrigin> stringOrigins; // parallel to `strings` when read from a file

    std::size_t elementCount() const;
};

// A field given in the file (fields left at their default are not stored).
struct Field {
    std::string name;
    FieldValue value;
    FilePos where;
    int file = -1;
    // Inside a PROTO body: `IS interfaceName` instead of (or, for
    // inputOutput, besides) a value. X3D lets one field be connected to
    // several interface fields (events fan in and out): each is kept.
    std::vector<std::string> isReferences;
};

// A field a Script node or a PROTO interface declares.
struct FieldDeclaration {
    std::string name;
    FieldType type = FieldType::Unknown;
    AccessType access = AccessType::InitializeOnly;
    FieldValue value; // initial value (initializeOnly / inputOutput)
    bool hasValue = false;
    bool valueIsDefault = false;           // not written: the reader filled in the type's default
    std::vector<std::string> isReferences; // Script field inside a PROTO body (as Field's)
    FilePos where;
};

struct Node {
    std::string type;               // "Transform", "FShape", a PROTO name, or unknown
    const NodeSpec* spec = nullptr; // built-in type; nullptr for PROTO instances and unknowns
    const ProtoDeclaration* proto = nullptr; // PROTO instance
    std::string defName;
    std::vector<Field> fields;
    std::vector<FieldDeclaration> declarations; // Script's own fields
    std::string containerField;                 // XML containerField written explicitly in the file
    FilePos where;
    int file = -1;
    // A PROTO instance expanded: its body with IS fields substituted. The
    // first node is what the instance stands for. Empty for EXTERNPROTOs that
    // could not be resolved.
    std::vector<Node*> expansion;
    std::vector<struct Route> expansionRoutes; // the body's ROUTEs, between expanded nodes
    bool inProtoBody = false;                  // part of a PROTO body (a template, not shown)
    // For a node of an expansion: the PROTO instance it was made for (its IS
    // fields connect to that instance's interface). Null elsewhere.
    const Node* instance = nullptr;
    // An Inline whose url was loaded: the scene it shows (owned by the scene
    // that holds this node, in `referenced`). Null when not loaded.
    const Scene* inlined = nullptr;
    // USE of a name not yet DEF'd (X3D allows it): resolved when the file ends.
    std::string forwardUse;

    // What the node is, as a type (NodeKind::Unknown for PROTO instances).
    NodeKind kind() const { return kindOf(spec); }
    const Field* field(std::string_view name) const;
    Field* field(std::string_view name);
    bool isUnknown() const { return spec == nullptr && proto == nullptr; }
    // Whether it may declare fields of its own (Script and shaders; a node of
    // a type FunctionLab does not know, too, so that its interface survives).
    bool declaresFields() const { return spec ? spec->declaresFields : proto == nullptr; }
    // Whether, in X3D XML, its element text is source code (a `url` entry).
    // Text inside an unknown element is not kept: mixed with child elements it
    // has no field to go back to.
    bool sourceInText() const { return spec && spec->sourceInText; }
};

struct Route {
    Node* fromNode = nullptr;
    std::string fromField;
    Node* toNode = nullptr;
    std::string toField;
    FilePos where;
    int file = -1;
};

// Statements we keep but do not act on (IMPORT, EXPORT), as text.
struct KeptStatement {
    std::string text;
    FilePos where;
};

struct ProtoDeclaration {
    std::string name;
    bool external = false;
    std::vector<FieldDeclaration> interface;
    std::vector<std::string> urls; // EXTERNPROTO
    // PROTO body (empty for an EXTERNPROTO); for a resolved EXTERNPROTO,
    // `resolved` points at the PROTO it names.
    std::vector<Node*> body;
    std::vector<Route> routes;
    std::vector<ProtoDeclaration*> protos; // nested declarations
    std::vector<KeptStatement> imports;    // IMPORT statements in the body
    const ProtoDeclaration* resolved = nullptr;
    FilePos where;
    int file = -1;

    const FieldDeclaration* interfaceField(std::string_view name) const;
    const ProtoDeclaration& definition() const { return resolved ? *resolved : *this; }
};

struct SourceFile {
    std::string path;
    std::string text; // decoded (gunzipped) text the positions refer to
};

struct Component {
    std::string name;
    int level = 1;
};

// A function node's definition compiled at load time (DESIGN §3). The
// instances of a PROTO share the tape their common text compiles to.
struct CompiledDefinition {
    const Node* node = nullptr;
    std::string field; // "definition", "translation", ...
    formula::DefinitionKind kind = formula::DefinitionKind::Generic;
    std::shared_ptr<const formula::Tape> tape;
};

// A number no other Scene object of this process has had: caches keyed by
// node addresses add it, so an address reused by a later scene never finds
// an earlier scene's entry. A moved-from scene takes a fresh one.
class SceneSerial {
  public:
    SceneSerial() : value_(next()) {}
    SceneSerial(const SceneSerial&) = delete;
    SceneSerial& operator=(const SceneSerial&) = delete;
    SceneSerial(SceneSerial&& o) noexcept : value_(o.value_) { o.value_ = next(); }
    SceneSerial& operator=(SceneSerial&& o) noexcept {
        value_ = o.value_;
        o.value_ = next();
        return *this;
    }
    std::uint64_t value() const { return value_; }

  private:
    static std::uint64_t next();
    std::uint64_t value_;
};

struct Scene {
    SceneSerial serial;
    Encoding encoding = Encoding::Xml;
    std::string version; // "2.0" for VRML97, "3.3" ...
    std::string profile; // X3D profile; empty for VRML97
    std::vector<Component> components;
    std::vector<std::pair<std::string, std::string>> meta; // X3D head meta / META
    std::vector<std::string> units;                        // UNIT statements, kept as text

    std::vector<Node*> roots;
    std::vector<Route> routes;
    std::vector<ProtoDeclaration*> protos;
    std::vector<KeptStatement> imports;
    std::vector<KeptStatement> exports;

    // files[0] is the scene file itself; files of Inline and EXTERNPROTO
    // references follow, so every node's `file` indexes this one table.
    std::vector<SourceFile> files;
    // Scenes loaded for Inline nodes and EXTERNPROTO declarations, owned here.
    std::vector<std::unique_ptr<Scene>> referenced;
    // Every definition of every function node outside PROTO bodies.
    // `definition()` also finds those of the scenes Inlines show.
    std::vector<CompiledDefinition> definitions;
    const formula::Tape* definition(const Node& node, std::string_view field) const;

    Scene() = default;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    Scene(Scene&&) = default;
    Scene& operator=(Scene&&) = default;

    // The path of files[file]; empty for -1 (nodes built by code) or a bad index.
    const std::string& pathOf(int file) const;
    // "path:line:column" of a node ("<scene>:..." when it is not from a file).
    std::string locationOf(const Node& node) const;

    Node* newNode();
    // Every node the scene owns, including PROTO bodies and expansions.
    template <class F>
    void forEachNode(F&& f) const {
        for (const auto& n : nodes_)
            f(*n);
    }
    template <class F>
    void forEachNode(F&& f) {
        for (auto& n : nodes_)
            f(*n);
    }
    ProtoDeclaration* newProto();
    std::size_t nodeCount() const { return nodes_.size(); }
    // Adds `offset` to every file index this scene and the scenes it
    // references hold: what moving its files into another scene's table takes.
    void shiftFileIndices(int offset);

  private:
    std::deque<std::unique_ptr<Node>> nodes_;
    std::deque<std::unique_ptr<ProtoDeclaration>> protos_;
};

// What a node stands for: a PROTO instance's first expanded node (through
// nested instances), any other node itself; null for an instance whose
// EXTERNPROTO was not loaded.
const Node* effectiveNode(const Node* node);

// The scene and every scene its Inlines show, each once, the scene first.
std::vector<const Scene*> scenesShownBy(const Scene& scene);

} // namespace fl::scene
