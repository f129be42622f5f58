#include "scene_builder.h"

#include "classic_lexer.h"
#include "components.h"
#include "formula/suggest.h"
#include "utf8.h"

#include <algorithm>
#include <cctype>

namespace fl::scene {

std::string_view encodingName(Encoding encoding) {
    switch (encoding) {
    case Encoding::Vrml97:
        return "VRML97";
    case Encoding::ClassicVrml:
        return "ClassicVRML";
    case Encoding::Xml:
        return "X3D XML";
    }
    return "X3D XML";
}

namespace {

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    std::string best = formula::closestName(name, candidates);
    if (best == name) return {}; // defined, but later or elsewhere: naming it again does not help
    return best.empty() ? std::string() : "did you mean '" + best + "'?";
}

std::vector<std::string> nodeTypeNames() {
    std::vector<std::string> names;
    for (const NodeSpec& s : nodeCatalogue())
        names.emplace_back(s.name);
    return names;
}

// IS may join a node field to an interface field when both move events the
// same way (ISO/IEC 19775-1, table 4.4): an inputOutput node field accepts any.
bool isCompatible(AccessType interface, AccessType nodeField) {
    return nodeField == AccessType::InputOutput || interface == nodeField;
}

} // namespace

SceneBuilder::SceneBuilder(Scene& scene, int file, const ReadLimits& limits,
                           std::vector<SceneDiagnostic>& diagnostics)
    : scene_(scene), file_(file), limits_(limits), diagnostics_(diagnostics) {
    scopes_.emplace_back();
}

void SceneBuilder::error(FilePos pos, std::string message, std::string suggestion) {
    ++errorCount_;
    if (diagnostics_.size() >= limits_.maxDiagnostics) {
        diagnostics_.push_back({Severity::Error,
                                scene_.files[file_].path,
                                pos,
                                "too many errors; stopped reading",
                                {}});
        throw StopReading{};
    }
    diagnostics_.push_back({Severity::Error, scene_.files[file_].path, pos, std::move(message),
                            std::move(suggestion)});
}

void SceneBuilder::warning(FilePos pos, std::string message, std::string suggestion) {
    if (diagnostics_.size() >= limits_.maxDiagnostics)
        return; // warnings never stop a load; extra ones are dropped
    // The same warning for the 100th GeoCoordinate helps nobody: say it three
    // times, then once that it repeats.
    const int seen = ++warningCounts_[message];
    if (seen > 3) {
        if (seen == 4)
            diagnostics_.push_back({Severity::Warning,
                                    scene_.files[file_].path,
                                    pos,
                                    "(the warning above repeats; further repeats are not shown)",
                                    {}});
        return;
    }
    diagnostics_.push_back({Severity::Warning, scene_.files[file_].path, pos, std::move(message),
                            std::move(suggestion)});
}

void SceneBuilder::fail(FilePos pos, std::string message, std::string suggestion) {
    error(pos, std::move(message), std::move(suggestion));
    throw StopReading{};
}

void SceneBuilder::failWithFix(FilePos pos, std::string message, std::string suggestion,
                               DiagnosticFix fix) {
    error(pos, std::move(message), std::move(suggestion));
    diagnostics_.back().fix = std::move(fix);
    throw StopReading{};
}

void SceneBuilder::failOverBudget(FilePos pos, std::string message) {
    error(pos, std::move(message));
    diagnostics_.back().overBudget = true;
    throw StopReading{};
}

bool SceneBuilder::hasErrors() const {
    return errorCount_ > 0;
}

void SceneBuilder::pushScope(ProtoDeclaration* proto) {
    Scope s;
    s.proto = proto;
    scopes_.push_back(std::move(s));
}

// What can only be checked once a scope's last DEF is known.
void SceneBuilder::closeScope(Scope& scope) {
    resolveForwardUses(scope);
    for (const auto& r : scope.routes)
        resolveRoute(scope, r);
    scope.routes.clear();
}

void SceneBuilder::popScope() {
    closeScope(scopes_.back());
    scopes_.pop_back();
}

// Only the innermost scope: a PROTO interface's default value is its own
// scope, where IS means nothing.
ProtoDeclaration* SceneBuilder::currentProto() const {
    return scopes_.back().proto;
}

// A name must survive every encoding: a ClassicVRML name (X3D's rules, also
// for VRML97 files, which may be written as X3D) that is valid UTF-8 and, for
// node types, PROTOs and fields, an XML name too (letters, digits, '_', '-',
// non-ASCII; not starting with a digit or '-', nor with "xml", which XML
// reserves), since X3D XML writes those as element and attribute names. A
// field may not be called by a word the encodings reserve (DEF, USE, IS ...):
// X3D XML would read it as that word.
bool isPortableName(std::string_view name, bool xmlName) {
    if (!isClassicName(name, true) || !isValidUtf8(name)) return false;
    if (!xmlName) return true;
    const bool xmlChars = std::all_of(name.begin(), name.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u >= 0x80 || std::isalnum(u) || c == '_' || c == '-';
    });
    auto lower = [&](std::size_t i) { return std::tolower(static_cast<unsigned char>(name[i])); };
    const bool reservedByXml =
        name.size() >= 3 && lower(0) == 'x' && lower(1) == 'm' && lower(2) == 'l';
    static constexpr std::string_view kReserved[] = {
        "AS",     "COMPONENT", "DEF",  "EXPORT", "EXTERNPROTO", "FALSE",
        "IMPORT", "IS",        "META", "NULL",   "PROFILE",     "PROTO",
        "ROUTE",  "TO",        "TRUE", "UNIT",   "USE",         "containerField"};
    const bool reservedWord =
        std::find(std::begin(kReserved), std::end(kReserved), name) != std::end(kReserved);
    return xmlChars && !reservedByXml && !reservedWord;
}

static std::string_view nameKindWord(NameKind kind) {
    switch (kind) {
    case NameKind::NodeType:
        return "node type";
    case NameKind::Proto:
        return "PROTO";
    case NameKind::Field:
        return "field";
    case NameKind::Def:
        return "DEF";
    case NameKind::Profile:
        return "profile";
    case NameKind::Component:
        return "component";
    }
    return "";
}

void SceneBuilder::checkName(std::string_view name, NameKind kind, FilePos pos) {
    const bool xmlName =
        kind == NameKind::NodeType || kind == NameKind::Proto || kind == NameKind::Field;
    if (isPortableName(name, xmlName)) return;
    fail(pos,
         "'" + std::string(name) + "' is not a valid " + std::string(nameKindWord(kind)) + " name",
         xmlName ? "use letters, digits, '_' and '-', starting with a letter or '_' but not "
                   "'xml', and no word X3D reserves (DEF, USE, IS, ROUTE ...)"
                 : "X3D names have no spaces, quotes, '#', ',', '.', ':', brackets, braces or "
                   "backslashes, and do not start with a digit, '+' or '-'");
}

Node* SceneBuilder::openNode(std::string_view type, FilePos pos) {
    if (++depth_ > limits_.maxNestingDepth)
        fail(pos,
             "nodes are nested more than " + std::to_string(limits_.maxNestingDepth) + " deep");
    checkName(type, NameKind::NodeType, pos);
    if (++nodesCreated_ > limits_.maxNodes)
        failOverBudget(pos,
                       "the scene has more than " + std::to_string(limits_.maxNodes) + " nodes");
    Node* node = scene_.newNode();
    node->type = std::string(type);
    node->where = pos;
    node->file = file_;
    node->inProtoBody = scopes_.back().proto != nullptr;
    if (const ProtoDeclaration* proto = findProto(type)) {
        node->proto = proto; // a PROTO may shadow a built-in type
    } else if (const NodeSpec* spec = findNodeSpec(type)) {
        node->spec = spec;
        if (node->kind() == scene::NodeKind::Script && !warnedScript_) {
            warnedScript_ = true;
            warning(pos, "Script nodes are kept but never run");
        }
        checkProfile(*spec, pos);
    } else {
        const std::string suggestion = didYouMean(type, nodeTypeNames());
        if (vrml97()) // VRML97 has a closed set of node types: an unknown name is a mistake
            error(pos, "unknown node type '" + std::string(type) + "'",
                  suggestion.empty()
                      ? std::string("VRML97 knows only its own nodes; declare new ones with PROTO")
                      : suggestion);
        else
            warning(pos,
                    "unknown node type '" + std::string(type) +
                        "'; it is kept and written back on save, but not shown",
                    suggestion);
    }
    scopes_.back().open.push_back(node);
    return node;
}

void SceneBuilder::closeNode() {
    --depth_;
    if (!scopes_.back().open.empty()) scopes_.back().open.pop_back();
}

// X3D 19775-1 §7.2.5: a node outside the declared profile and components
// is the file's mistake; a browser refuses it or says so. FunctionLab says so,
// once per node type, and draws it all the same (many files declare
// Interchange and use more). Function nodes are ours and always known.
void SceneBuilder::checkProfile(const NodeSpec& spec, FilePos pos) {
    if (vrml97() || spec.family == NodeFamily::Function || scene_.profile.empty()) return;
    const std::optional<int> inProfile = profileComponentLevel(scene_.profile, spec.component);
    if (!inProfile || *inProfile >= spec.level) return;
    for (const Component& c : scene_.components)
        if (c.name == spec.component && c.level >= spec.level) return;
    if (!outsideProfile_.insert(std::string(spec.name)).second) return;
    const std::string needed = std::string(spec.component) + ":" + std::to_string(spec.level);
    warning(pos,
            std::string(spec.name) + " (" + needed + ") is not part of profile " + scene_.profile +
                (scene_.components.empty() ? "" : " or the declared components"),
            "declare COMPONENT " + needed + " or a profile that includes it (Immersive, Full)");
}

void SceneBuilder::define(Node* node, std::string_view name, FilePos pos) {
    checkName(name, NameKind::Def, pos);
    Scope& scope = scopes_.back();
    scope.defHistory[std::string(name)].push_back(node);
    auto [it, inserted] = scope.defs.try_emplace(std::string(name), node);
    if (!inserted) {
        warning(pos,
                "DEF " + std::string(name) + " names a second node; USE " + std::string(name) +
                    " now means this one",
                "give each DEF its own name");
        it->second = node;
    }
    node->defName = std::string(name);
    defPositions_[node] = pos;
}

std::string SceneBuilder::defPlace(const Node& node) const {
    const auto it = defPositions_.find(&node);
    const FilePos pos = it == defPositions_.end() ? node.where : it->second;
    return std::to_string(pos.line) + ":" + std::to_string(pos.column);
}

Node* SceneBuilder::use(std::string_view name, FilePos pos) {
    Scope& scope = scopes_.back();
    const Node* holder = scope.open.empty() ? nullptr : scope.open.back();
    if (auto it = scope.defs.find(std::string(name)); it != scope.defs.end()) {
        Node* target = it->second;
        const bool inside =
            std::find(scope.open.begin(), scope.open.end(), target) != scope.open.end();
        useSites_.push_back({holder, target, pos, inside});
        return target;
    }
    Node* placeholder = scene_.newNode();
    placeholder->type = "USE";
    placeholder->forwardUse = std::string(name);
    placeholder->where = pos;
    placeholder->file = file_;
    scope.forwardUses.push_back({placeholder, pos, 0});
    useSites_.push_back({holder, placeholder, pos, false});
    return placeholder;
}

void SceneBuilder::resolveForwardUses(Scope& scope) {
    std::vector<std::string> names;
    for (auto& [placeholder, pos, defsBefore] : scope.forwardUses) {
        auto it = scope.defHistory.find(placeholder->forwardUse);
        if (it != scope.defHistory.end() && defsBefore < it->second.size()) {
            warning(pos,
                    "USE " + placeholder->forwardUse + " comes before DEF " +
                        placeholder->forwardUse + "; it refers to the node defined later",
                    "move the DEF before its first USE");
            resolvedPlaceholders_[placeholder] = it->second[defsBefore]; // the first DEF after it
            continue;
        }
        if (names.empty())
            for (const auto& d : scope.defs)
                names.push_back(d.first);
        error(pos,
              "USE " + placeholder->forwardUse + ": no node is named " + placeholder->forwardUse +
                  " here",
              didYouMean(placeholder->forwardUse, names));
    }
    scope.forwardUses.clear();
}

void SceneBuilder::replacePlaceholders() {
    if (resolvedPlaceholders_.empty()) return;
    auto resolve = [&](Node* n) {
        // A placeholder may name a node that is itself a placeholder only
        // through a cycle of forward USEs; stop after a bounded walk.
        for (int i = 0; i < 64; ++i) {
            auto it = resolvedPlaceholders_.find(n);
            if (it == resolvedPlaceholders_.end()) return n;
            n = it->second;
        }
        return n;
    };
    scene_.forEachNode([&](const Node& constNode) {
        Node& node = const_cast<Node&>(constNode);
        for (Field& f : node.fields)
            for (Node*& child : f.value.nodes)
                child = resolve(child);
        for (FieldDeclaration& d : node.declarations)
            for (Node*& child : d.value.nodes)
                child = resolve(child);
    });
    for (Node*& root : scene_.roots)
        root = resolve(root);
    auto fixProto = [&](auto& self, ProtoDeclaration& p) -> void {
        for (Node*& n : p.body)
            n = resolve(n);
        for (FieldDeclaration& d : p.interface)
            for (Node*& child : d.value.nodes)
                child = resolve(child);
        for (ProtoDeclaration* nested : p.protos)
            self(self, *nested);
    };
    for (ProtoDeclaration* p : scene_.protos)
        fixProto(fixProto, *p);
}

void SceneBuilder::declareImport(std::string_view name, FilePos pos) {
    Node* n = scene_.newNode();
    n->type = "IMPORT";
    n->defName = std::string(name);
    n->where = pos;
    n->file = file_;
    scopes_.back().defs[std::string(name)] = n;
    scopes_.back().defHistory[std::string(name)].push_back(n);
}

void SceneBuilder::declareProto(ProtoDeclaration* proto, FilePos pos) {
    Scope& scope = scopes_.back();
    auto [it, inserted] = scope.protos.try_emplace(proto->name, proto);
    if (!inserted) {
        warning(pos, "PROTO " + proto->name + " is declared twice; the later one is used");
        it->second = proto;
    }
}

const ProtoDeclaration* SceneBuilder::findProto(std::string_view name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (auto p = it->protos.find(std::string(name)); p != it->protos.end()) return p->second;
    return nullptr;
}

void SceneBuilder::setProfile(std::string profile, FilePos pos) {
    checkName(profile, NameKind::Profile, pos);
    if (!isKnownProfile(profile))
        warning(pos, "unknown profile '" + profile + "'",
                "profiles are Core, Interchange, Interactive, Immersive, Full");
    scene_.profile = std::move(profile);
}

void SceneBuilder::addComponent(std::string name, int level, std::string_view levelText,
                                FilePos namePos, FilePos levelPos) {
    checkName(name, NameKind::Component, namePos);
    std::optional<int> max = componentMaxLevel(name);
    if (!max)
        warning(namePos, "unknown component '" + name + "'");
    else if (level < 1 || level > *max)
        error(levelPos, "component " + name + " has levels 1 to " + std::to_string(*max) +
                            ", not " + std::string(levelText));
    scene_.components.push_back({std::move(name), level});
}

void SceneBuilder::checkInterfaceField(const ProtoDeclaration& proto, const FieldDeclaration& d,
                                       FilePos pos) {
    auto eventOf = [](const FieldDeclaration& a, const FieldDeclaration& b) {
        return a.access == AccessType::InputOutput &&
               (b.name == "set_" + a.name || b.name == a.name + "_changed");
    };
    for (const FieldDeclaration& other : proto.interface)
        if (other.name == d.name || eventOf(other, d) || eventOf(d, other))
            error(pos,
                  "interface field '" + d.name + "' of " + proto.name + " clashes with '" +
                      other.name + "'",
                  "an exposedField x already has the events set_x and x_changed");
}

void SceneBuilder::reportUnknownField(const Node& node, std::string_view name, FilePos pos) {
    if (node.isUnknown()) return; // nothing to check against
    const std::string suggestion = suggestField(node, name);
    if (node.proto && vrml97())
        error(pos, "PROTO " + node.type + " has no field '" + std::string(name) + "'", suggestion);
    else
        warning(pos,
                node.type + " has no field '" + std::string(name) + "'; it is kept but ignored",
                suggestion);
}

bool SceneBuilder::reportUnassignable(const Node& node, const FieldInfo& field,
                                      std::string_view name, FilePos pos) {
    if (!field.eventName && hasInitialValue(field.access)) return false;
    error(pos,
          "'" + std::string(name) + "' is an " + std::string(accessTypeName(field.access)) +
              (field.eventName ? " event" : " field") + " of " + node.type +
              "; it cannot be given a value in a file",
          field.eventName ? "write '" + std::string(field.canonicalName) + "' instead"
                          : std::string("send it events with a ROUTE"));
    return true;
}

FieldInfo SceneBuilder::fieldInfo(const Node& node, std::string_view name) const {
    FieldInfo info;
    if (node.spec) {
        bool eventName = false;
        if (const FieldSpec* f = findFieldSpec(*node.spec, name, &eventName)) {
            info = {f->type, f->access, true, eventName, f->name};
            return info;
        }
    }
    for (const FieldDeclaration& d : node.declarations)
        if (d.name == name) return {d.type, d.access, true, false, d.name};
    if (node.proto) {
        const ProtoDeclaration& p = *node.proto;
        if (const FieldDeclaration* d = p.interfaceField(name))
            return {d->type, d->access, true, false, d->name};
        const std::string_view base = eventBaseName(name);
        if (!base.empty())
            if (const FieldDeclaration* d = p.interfaceField(base);
                d && d->access == AccessType::InputOutput)
                return {d->type, d->access, true, true, d->name};
    }
    return info;
}

std::string SceneBuilder::suggestField(const Node& node, std::string_view name) const {
    std::vector<std::string> names;
    if (node.spec)
        for (const FieldSpec& f : node.spec->fields)
            names.emplace_back(f.name);
    if (node.proto)
        for (const FieldDeclaration& d : node.proto->interface)
            names.push_back(d.name);
    for (const FieldDeclaration& d : node.declarations)
        names.push_back(d.name);
    return didYouMean(name, names);
}

void SceneBuilder::checkIs(const Node& node, const FieldInfo& field, std::string_view fieldName,
                           std::string_view interfaceName, FilePos pos) {
    const ProtoDeclaration* proto = currentProto();
    if (!proto) {
        error(pos, "IS " + std::string(interfaceName) + " outside a PROTO body",
              "IS connects a field to the interface of the PROTO it is written in");
        return;
    }
    const FieldDeclaration* decl = proto->interfaceField(interfaceName);
    if (!decl) {
        std::vector<std::string> names;
        for (const auto& d : proto->interface)
            names.push_back(d.name);
        error(pos,
              "PROTO " + proto->name + " has no interface field '" + std::string(interfaceName) +
                  "'",
              didYouMean(interfaceName, names));
        return;
    }
    if (!field.known) return; // field of an unknown node: nothing to check against
    if (decl->type != field.type) {
        error(pos,
              "field '" + std::string(fieldName) + "' of " + node.type + " is " +
                  std::string(fieldTypeName(field.type)) + " but interface field '" + decl->name +
                  "' is " + std::string(fieldTypeName(decl->type)),
              "IS joins fields of the same type");
        return;
    }
    if (!isCompatible(decl->access, field.access))
        error(pos,
              "interface field '" + decl->name + "' is " +
                  std::string(accessTypeName(decl->access)) + " but '" + std::string(fieldName) +
                  "' of " + node.type + " is " + std::string(accessTypeName(field.access)),
              "IS joins fields whose events flow the same way");
}

void SceneBuilder::addRoute(std::string_view fromDef, std::string_view fromField,
                            std::string_view toDef, std::string_view toField, FilePos pos) {
    scopes_.back().routes.push_back({std::string(fromDef), std::string(fromField),
                                     std::string(toDef), std::string(toField), pos});
}

void SceneBuilder::resolveRoute(Scope& scope, const Scope::PendingRoute& r) {
    auto lookup = [&](const std::string& name) -> Node* {
        auto it = scope.defs.find(name);
        if (it != scope.defs.end()) return it->second;
        std::vector<std::string> names;
        for (const auto& d : scope.defs)
            names.push_back(d.first);
        error(r.pos, "ROUTE names '" + name + "' but no node is DEF'd with that name here",
              didYouMean(name, names));
        return nullptr;
    };
    Node* from = lookup(r.fromDef);
    Node* to = lookup(r.toDef);
    if (!from || !to) return;
    FieldInfo out = fieldInfo(*from, r.fromField);
    if (!out.known && !from->isUnknown()) out = fieldInfo(*from, r.fromField + "_changed");
    FieldInfo in = fieldInfo(*to, r.toField);
    if (!in.known && !to->isUnknown()) in = fieldInfo(*to, "set_" + r.toField);
    bool ok = true;
    if (!from->isUnknown() && !out.known) {
        error(r.pos, r.fromDef + " (" + from->type + ") has no field '" + r.fromField + "'",
              suggestField(*from, r.fromField));
        ok = false;
    } else if (out.known && !canRead(out.access)) {
        error(r.pos,
              "ROUTE starts at " + r.fromDef + "." + r.fromField + ", an " +
                  std::string(accessTypeName(out.access)) + " field that sends no events",
              "a ROUTE starts at an outputOnly or inputOutput field");
        ok = false;
    }
    if (!to->isUnknown() && !in.known) {
        error(r.pos, r.toDef + " (" + to->type + ") has no field '" + r.toField + "'",
              suggestField(*to, r.toField));
        ok = false;
    } else if (in.known && !canWrite(in.access)) {
        error(r.pos,
              "ROUTE ends at " + r.toDef + "." + r.toField + ", an " +
                  std::string(accessTypeName(in.access)) + " field that receives no events",
              "a ROUTE ends at an inputOnly or inputOutput field");
        ok = false;
    }
    if (ok && out.known && in.known && out.type != in.type) {
        error(r.pos,
              "ROUTE connects " + std::string(fieldTypeName(out.type)) + " " + r.fromDef + "." +
                  r.fromField + " to " + std::string(fieldTypeName(in.type)) + " " + r.toDef + "." +
                  r.toField,
              "both ends of a ROUTE must have the same type");
        ok = false;
    }
    if (!ok) return;
    Route route{from, r.fromField, to, r.toField, r.pos, file_};
    if (scope.proto)
        scope.proto->routes.push_back(std::move(route));
    else
        scene_.routes.push_back(std::move(route));
}

void SceneBuilder::finish() {
    while (scopes_.size() > 1)
        popScope(); // a reader stopped inside a PROTO body
    closeScope(scopes_.back());
    replacePlaceholders();
    if (hasErrors() || refuseLoops(Edges::AsWritten)) return;
    resolveExternProtos();
    expandInstances();
    // A loop only an expansion makes (a PROTO whose interface default holds
    // an instance of itself): the nodes as written have none.
    refuseLoops(Edges::WithExpansions);
}

const Node* SceneBuilder::resolvedTarget(const Node* n) const {
    for (int i = 0; i < 64; ++i) { // the same bound replacePlaceholders() walks
        auto it = resolvedPlaceholders_.find(const_cast<Node*>(n));
        if (it == resolvedPlaceholders_.end()) break;
        n = it->second;
    }
    return n;
}

const SceneBuilder::UseSite* SceneBuilder::useSiteOf(const Node& holder, const Node& target) const {
    auto origin = [&](const Node* n) {
        auto it = cloneOrigins_.find(n);
        return it == cloneOrigins_.end() ? n : it->second;
    };
    const Node* h = origin(&holder);
    const Node* t = origin(&target);
    for (const UseSite& site : useSites_)
        if (site.holder == h && resolvedTarget(site.target) == t) return &site;
    return nullptr;
}

bool SceneBuilder::refuseLoops(Edges edges) {
    std::vector<const Node*> roots(scene_.roots.begin(), scene_.roots.end());
    const NodeGraphShape shape = examineNodeGraph(
        roots, protoNodes(scene_), edges, limits_.maxUnfoldedNodes, limits_.maxUnfoldedDepth);
    if (!shape.loop) return false;
    const NodeLoop& loop = *shape.loop;
    // The edge that closed the loop may be the one that nests a node where it
    // is written (the node was first reached by a forward USE): any USE on
    // the loop is a place to cut it.
    const UseSite* site = nullptr;
    const std::size_t n = loop.path.size();
    for (std::size_t i = 0; i < n && !site; ++i)
        site = useSiteOf(*loop.path[(i + n - 1) % n], *loop.path[i]);
    auto name = [](const Node& node) {
        return node.defName.empty() ? node.type : node.type + " " + node.defName;
    };
    std::string through;
    for (const Node* p : loop.path)
        through += (through.empty() ? "" : " > ") + name(*p);
    through += " > " + name(*loop.ancestor);
    if (site && site->insideTarget) {
        // X3D 19775-1 §4.4.3: a node may not be its own ancestor.
        const std::string& def = site->target->defName;
        error(site->pos,
              "USE " + def + " is inside the node it names (DEF " + def + " at " +
                  defPlace(*site->target) + "): a node cannot contain itself",
              "a scene is a tree: USE " + def + " outside DEF " + def +
                  ", or DEF a separate node to use here");
    } else if (site) {
        const Node& target = *resolvedTarget(site->target);
        error(site->pos,
              "USE " + target.defName + " makes a loop: DEF " + target.defName + " (at " +
                  defPlace(target) + ") would contain itself (" + through + ")",
              "a scene is a tree with shared leaves: USE a node only outside itself");
    } else {
        // Not written as a USE in this file: an expansion joined the loop.
        const Node& instance = loop.ancestor->instance ? *loop.ancestor->instance : *loop.ancestor;
        error(instance.where,
              name(instance) + " would contain itself once its PROTO is expanded (" + through + ")",
              "a PROTO's default field values may not hold an instance of that PROTO");
    }
    return true;
}

void SceneBuilder::resolveExternProtos() {
    std::vector<ProtoDeclaration*> stack(scene_.protos.begin(), scene_.protos.end());
    while (!stack.empty()) {
        ProtoDeclaration* p = stack.back();
        stack.pop_back();
        stack.insert(stack.end(), p->protos.begin(), p->protos.end());
        if (!p->external || p->resolved) continue;
        const std::string why = resolveExtern_ ? resolveExtern_(*p) : "no file to look in";
        if (!why.empty())
            warning(p->where, "EXTERNPROTO " + p->name + " not loaded: " + why +
                                  "; its instances show nothing");
    }
}

void SceneBuilder::expandInstances() {
    std::vector<Node*> stack(scene_.roots.rbegin(), scene_.roots.rend());
    std::unordered_map<const Node*, bool> seen;
    while (!stack.empty()) {
        Node* n = stack.back();
        stack.pop_back();
        if (!n || !seen.emplace(n, true).second) continue;
        if (n->proto && n->expansion.empty()) expand(*n, 0);
        for (const Field& f : n->fields)
            for (Node* child : f.value.nodes)
                stack.push_back(child);
        for (const FieldDeclaration& d : n->declarations)
            for (Node* child : d.value.nodes)
                stack.push_back(child);
    }
}

void SceneBuilder::expand(Node& instance, std::size_t depth) {
    const ProtoDeclaration& proto = instance.proto->definition();
    if (proto.external) return; // unresolved EXTERNPROTO: warned at its declaration
    if (depth >= limits_.maxProtoDepth)
        fail(instance.where, "PROTO instances nest more than " +
                                 std::to_string(limits_.maxProtoDepth) + " deep (does PROTO " +
                                 proto.name + " contain itself?)");
    std::unordered_map<const Node*, Node*> clones;
    for (Node* bodyNode : proto.body)
        instance.expansion.push_back(cloneForInstance(*bodyNode, instance, depth, clones));
    for (const Route& r : proto.routes) {
        auto from = clones.find(r.fromNode);
        auto to = clones.find(r.toNode);
        if (from != clones.end() && to != clones.end())
            instance.expansionRoutes.push_back(
                {from->second, r.fromField, to->second, r.toField, r.where, r.file});
    }
}

Node* SceneBuilder::cloneForInstance(Node& original, const Node& instance, std::size_t depth,
                                     std::unordered_map<const Node*, Node*>& clones) {
    if (auto it = clones.find(&original); it != clones.end())
        return it->second; // DEF/USE inside the body stays shared
    if (++expandedNodes_ > limits_.maxExpandedNodes)
        failOverBudget(instance.where, "PROTO expansion creates more than " +
                                           std::to_string(limits_.maxExpandedNodes) + " nodes");
    Node* copy = scene_.newNode();
    clones.emplace(&original, copy);
    cloneOrigins_.emplace(copy, &original);
    copy->type = original.type;
    copy->spec = original.spec;
    copy->proto = original.proto;
    copy->defName = original.defName;
    copy->containerField = original.containerField;
    copy->where = original.where;
    copy->file = original.file;
    copy->inProtoBody = false;
    copy->instance = &instance;
    copy->declarations = original.declarations;
    copy->fields = original.fields;
    const ProtoDeclaration& proto = instance.proto->definition();
    // A field connected to several interface fields takes its value from the first.
    auto substitute = [&](FieldValue& value, const std::vector<std::string>& references) {
        if (references.empty()) return false;
        const std::string& isName = references.front();
        if (const Field* given = instance.field(isName)) {
            value = given->value;
        } else if (const FieldDeclaration* decl = proto.interfaceField(isName)) {
            value = decl->value;
        }
        return true;
    };
    for (Field& f : copy->fields) {
        if (substitute(f.value, f.isReferences)) continue; // instance nodes are shared, not cloned
        for (Node*& child : f.value.nodes)
            if (child) child = cloneForInstance(*child, instance, depth, clones);
    }
    for (FieldDeclaration& d : copy->declarations) {
        if (substitute(d.value, d.isReferences)) continue;
        for (Node*& child : d.value.nodes)
            if (child) child = cloneForInstance(*child, instance, depth, clones);
    }
    if (copy->proto) expand(*copy, depth + 1);
    return copy;
}

} // namespace fl::scene
