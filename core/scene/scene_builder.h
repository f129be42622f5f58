#pragma once
// What the X3D XML and Classic readers share once a token or element has been
// understood: node types and field lookup, DEF/USE scopes (with USE before DEF
// resolved at the end), IS and ROUTE checks, limits, diagnostics, and PROTO
// expansion. Encoding rules that differ are parameters, not copies.
#include "node_graph.h"
#include "read_limits.h"
#include "scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace fl::scene {

// Thrown by a reader to stop at an error it cannot recover from; the builder
// has already recorded the diagnostic.
struct StopReading {};

struct FieldInfo {
    FieldType type = FieldType::Unknown;
    AccessType access = AccessType::InputOutput;
    bool known = false;
    bool eventName = false; // set_x / x_changed of an inputOutput field
    std::string_view canonicalName;
};

// What a name names: node types, PROTOs and fields are also written as XML
// element and attribute names; DEF names, profiles and components are not.
enum class NameKind : std::uint8_t { NodeType, Proto, Field, Def, Profile, Component };

// Whether `name` survives every encoding (see SceneBuilder::checkName);
// `xmlName`: it is written as an XML element or attribute name too.
bool isPortableName(std::string_view name, bool xmlName);

class SceneBuilder {
  public:
    SceneBuilder(Scene& scene, int file, const ReadLimits& limits,
                 std::vector<SceneDiagnostic>& diagnostics);

    Scene& scene() { return scene_; }
    int file() const { return file_; }
    const ReadLimits& limits() const { return limits_; }
    bool vrml97() const { return scene_.encoding == Encoding::Vrml97; }

    void error(FilePos pos, std::string message, std::string suggestion = {});
    void warning(FilePos pos, std::string message, std::string suggestion = {});
    [[noreturn]] void fail(FilePos pos, std::string message, std::string suggestion = {});
    // fail() with a fix an editor can offer.
    [[noreturn]] void failWithFix(FilePos pos, std::string message, std::string suggestion,
                                  DiagnosticFix fix);
    // fail() for a bound on size or work (SceneDiagnostic::overBudget).
    [[noreturn]] void failOverBudget(FilePos pos, std::string message);
    bool hasErrors() const;

    // Scopes: the scene, each PROTO body, each PROTO interface default value.
    void pushScope(ProtoDeclaration* proto);
    void popScope(); // resolves forward USEs of the scope
    ProtoDeclaration* currentProto() const;

    // Refuses (with a located error) a name ClassicVRML could not write.
    void checkName(std::string_view name, NameKind kind, FilePos pos);
    // A node starts: type lookup (built-in, PROTO, unknown) by the encoding's
    // rules, the nesting depth, and the node is open (an ancestor of what
    // follows) until closeNode().
    Node* openNode(std::string_view type, FilePos pos);
    void closeNode();
    void define(Node* node, std::string_view name, FilePos pos);
    // The node a USE names; a placeholder when the name comes later in the
    // file. A USE that makes a loop is refused at finish(), where the whole
    // graph is known (a USE inside the node it names is one only in a field
    // that holds children, not in a Script's declared field).
    Node* use(std::string_view name, FilePos pos);

    void declareProto(ProtoDeclaration* proto, FilePos pos);
    // A name an IMPORT brings in: a node of another file, usable in ROUTE and USE.
    void declareImport(std::string_view name, FilePos pos);
    const ProtoDeclaration* findProto(std::string_view name) const;

    // Header statements both encodings share.
    void setProfile(std::string profile, FilePos pos);
    void addComponent(std::string name, int level, std::string_view levelText, FilePos namePos,
                      FilePos levelPos);

    // A new PROTO interface field may not repeat a name, nor an event name
    // (set_x, x_changed) of an inputOutput field, already declared.
    void checkInterfaceField(const ProtoDeclaration& proto, const FieldDeclaration& field,
                             FilePos pos);

    FieldInfo fieldInfo(const Node& node, std::string_view name) const;
    // A field the node's type does not have: a warning (kept, ignored), an
    // error for PROTO instances in VRML97, nothing for unknown node types.
    void reportUnknownField(const Node& node, std::string_view name, FilePos pos);
    // True (with an error reported) when the file may not give this field a
    // value: an event name, or an inputOnly/outputOnly field.
    bool reportUnassignable(const Node& node, const FieldInfo& field, std::string_view name,
                            FilePos pos);
    std::string suggestField(const Node& node, std::string_view name) const;

    // Checks an `IS` between a node's field and the current PROTO's interface.
    void checkIs(const Node& node, const FieldInfo& field, std::string_view fieldName,
                 std::string_view interfaceName, FilePos pos);
    // Validates and stores a ROUTE (in the current PROTO body or the scene).
    void addRoute(std::string_view fromDef, std::string_view fromField, std::string_view toDef,
                  std::string_view toField, FilePos pos);

    // Loads what an EXTERNPROTO names (sets `resolved`); returns why not.
    using ExternProtoResolver = std::function<std::string(ProtoDeclaration&)>;
    void setExternProtoResolver(ExternProtoResolver resolver) {
        resolveExtern_ = std::move(resolver);
    }

    // End of file: forward USEs, EXTERNPROTOs, PROTO expansion.
    void finish();

  private:
    struct Scope {
        ProtoDeclaration* proto = nullptr;
        std::unordered_map<std::string, Node*> defs;
        struct ForwardUse {
            Node* placeholder;
            FilePos pos;
            std::size_t defsBefore; // how many DEFs of the name preceded the USE
        };
        std::vector<ForwardUse> forwardUses;
        std::unordered_map<std::string, std::vector<Node*>> defHistory;
        std::unordered_map<std::string, ProtoDeclaration*> protos;
        struct PendingRoute {
            std::string fromDef, fromField, toDef, toField;
            FilePos pos;
        };
        std::vector<PendingRoute> routes; // checked when the scope ends (DEFs may follow)
        std::vector<Node*> open;          // the nodes being read, outermost first
    };
    // Where a USE was written, to say where a loop is closed: `holder` is the
    // node whose field holds it (null at the top of a scope), `target` the
    // node or forward placeholder it returned.
    struct UseSite {
        const Node* holder;
        const Node* target;
        FilePos pos;
        bool insideTarget; // written inside the node it names
    };
    const Node* resolvedTarget(const Node* n) const;
    const UseSite* useSiteOf(const Node& holder, const Node& target) const;
    // Refuses a loop in the graph (one error, located at a USE that closes it
    // where one can be found) and returns whether there was one.
    bool refuseLoops(Edges edges);
    void resolveRoute(Scope& scope, const Scope::PendingRoute& r);
    Node* cloneForInstance(Node& original, const Node& instance, std::size_t depth,
                           std::unordered_map<const Node*, Node*>& clones);
    void closeScope(Scope& scope);
    void resolveForwardUses(Scope& scope);
    void resolveExternProtos();
    void expandInstances();
    void expand(Node& instance, std::size_t depth);
    void replacePlaceholders();

    Scene& scene_;
    int file_;
    const ReadLimits& limits_;
    std::vector<SceneDiagnostic>& diagnostics_;
    std::vector<Scope> scopes_;
    std::unordered_map<Node*, Node*> resolvedPlaceholders_;
    std::vector<UseSite> useSites_;
    std::unordered_map<const Node*, FilePos> defPositions_;     // where each DEF name is written
    std::string defPlace(const Node& node) const;               // "line:column" of its DEF
    std::unordered_map<const Node*, const Node*> cloneOrigins_; // expanded node -> body node
    std::size_t depth_ = 0;
    ExternProtoResolver resolveExtern_;
    std::size_t nodesCreated_ = 0;
    std::size_t expandedNodes_ = 0;
    std::size_t errorCount_ = 0;
    std::unordered_map<std::string, int> warningCounts_;
    bool warnedScript_ = false;
    std::set<std::string> outsideProfile_; // node types already warned about
    void checkProfile(const NodeSpec& spec, FilePos pos);
};

std::string_view encodingName(Encoding encoding);

} // namespace fl::scene
