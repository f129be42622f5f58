#include "function_definitions.h"

#include "field_access.h"
#include "source_map.h"

#include <map>
#include <set>
#include <tuple>

namespace fl::scene {
namespace {

using formula::DefinitionKind;

class DefinitionCompiler {
  public:
    DefinitionCompiler(Scene& scene, std::vector<SceneDiagnostic>& out)
        : scene_(scene), out_(out) {}

    void compileNode(const Node& node);

  private:
    void report(const Node& node, const Field* field, Severity severity, FilePos pos,
                std::string message, std::string suggestion = {}) {
        const int file = field && field->file >= 0 ? field->file : node.file;
        const std::string path = file >= 0 ? scene_.files[file].path : std::string();
        // A PROTO body and each of its instances compile the same text: say it once.
        if (!seen_.emplace(path, pos.line, pos.column, message).second) return;
        out_.push_back({severity, path, pos, std::move(message), std::move(suggestion)});
    }
    FilePos fieldPos(const Node& node, std::string_view name) {
        const Field* f = node.field(name);
        return f ? f->where : node.where;
    }
    FilePos locate(const Field& field, const std::vector<std::size_t>& starts, std::size_t offset);
    const LineIndex& lines(int file) {
        auto it = lineIndexes_.find(file);
        if (it == lineIndexes_.end())
            it = lineIndexes_.emplace(file, LineIndex(scene_.files[file].text)).first;
        return it->second;
    }
    formula::CompileOptions optionsFor(const Node& node, DefinitionKind kind);
    void checkGeometry(const Node& node);
    void checkMaterial(const Node& node);
    void checkDomain(const Node& node);

    Scene& scene_;
    std::vector<SceneDiagnostic>& out_;
    std::map<int, LineIndex> lineIndexes_;
    std::set<std::tuple<std::string, int, int, std::string>> seen_;
};

FilePos DefinitionCompiler::locate(const Field& field, const std::vector<std::size_t>& starts,
                                   std::size_t offset) {
    const FieldValue& v = field.value;
    std::size_t i = 0;
    while (i + 1 < starts.size() && starts[i + 1] <= offset)
        ++i;
    if (i >= v.stringOrigins.size() || v.stringOrigins[i].file < 0) return field.where;
    const StringOrigin& origin = v.stringOrigins[i];
    const std::size_t within = std::min(offset - starts[i], v.strings[i].size());
    const std::string& text = scene_.files[origin.file].text;
    return lines(origin.file).position(fileOffsetOf(text, origin, within));
}

formula::CompileOptions DefinitionCompiler::optionsFor(const Node& node, DefinitionKind kind) {
    formula::CompileOptions options;
    options.kind = kind;
    if (node.type == "FGeometry" && stringField(node, "setOperations") == "rfunction") {
        options.setOperations.kind = formula::SetOperationMode::Kind::RFunction;
        options.setOperations.m = numberField(node, "rfunctionM");
        options.setOperations.alpha = numberField(node, "rfunctionAlpha");
    }
    if (node.type == "FTransform") {
        // The user's operation formula reads each child's value as f1, f2, ...
        std::size_t children = nodesField(node, "children").size();
        for (std::size_t i = 1; i <= std::max<std::size_t>(children, 1); ++i)
            options.parameters.push_back({"f" + std::to_string(i), 0.0, false, 0.0, 0.0});
    }
    return options;
}

void DefinitionCompiler::checkGeometry(const Node& node) {
    const std::string type = stringField(node, "type");
    if (type != "implicit" && type != "explicit" && type != "parametric")
        report(node, node.field("type"), Severity::Error, fieldPos(node, "type"),
               "FGeometry type '" + type + "' is not implicit, explicit or parametric");
    const std::string ops = stringField(node, "setOperations");
    if (ops != "minmax" && ops != "rfunction")
        report(node, node.field("setOperations"), Severity::Error, fieldPos(node, "setOperations"),
               "setOperations '" + ops + "' is not minmax or rfunction");
    const std::string collision = stringField(node, "collision");
    if (collision != "function" && collision != "polygonal")
        report(node, node.field("collision"), Severity::Error, fieldPos(node, "collision"),
               "collision '" + collision + "' is not function or polygonal");
    if (stringsField(node, "definition").empty())
        report(node, nullptr, Severity::Error, node.where, "FGeometry has no definition",
               "write definition \"1 - x^2 - y^2 - z^2\" for a unit sphere");
    if (numberField(node, "resolution") <= 0)
        report(node, node.field("resolution"), Severity::Error, fieldPos(node, "resolution"),
               "resolution must be positive");
    for (std::string_view range : {"uRange", "vRange", "wRange"}) {
        const auto r = numbersField(node, range);
        if (r.size() == 2 && !(r[0] <= r[1]))
            report(node, node.field(range), Severity::Error, fieldPos(node, range),
                   std::string(range) + " must go from low to high");
    }
}

void DefinitionCompiler::checkMaterial(const Node& node) {
    const std::string type = stringField(node, "type");
    if (type != "parametric" && type != "explicit") {
        report(node, node.field("type"), Severity::Error, fieldPos(node, "type"),
               "FMaterial type '" + type + "' is not parametric or explicit");
        return;
    }
    const auto keys = numbersField(node, "key");
    const std::size_t colours = numbersField(node, "keyValue").size() / 3;
    if (type == "explicit") {
        if (keys.empty())
            report(node, nullptr, Severity::Error, node.where,
                   "an explicit FMaterial maps its value through key and keyValue, but has no key",
                   "add key [0 1] keyValue [0 0 1, 1 0 0]");
        else if (keys.size() != colours)
            report(node, node.field("keyValue"), Severity::Error, fieldPos(node, "keyValue"),
                   std::to_string(keys.size()) + " keys but " + std::to_string(colours) +
                       " colours in keyValue",
                   "give one colour per key");
        for (std::size_t i = 1; i < keys.size(); ++i)
            if (!(keys[i - 1] <= keys[i])) {
                report(node, node.field("key"), Severity::Error, fieldPos(node, "key"),
                       "keys must not decrease");
                break;
            }
    }
}

void DefinitionCompiler::checkDomain(const Node& node) {
    if (!node.spec || !findFieldSpec(*node.spec, "domainMin")) return;
    const auto lo = numbersField(node, "domainMin"), hi = numbersField(node, "domainMax");
    if (lo.size() == 3 && hi.size() == 3)
        for (int i = 0; i < 3; ++i)
            if (!(lo[i] < hi[i])) {
                report(node, node.field("domainMax"), Severity::Error, fieldPos(node, "domainMax"),
                       "the domain box is empty: domainMax must exceed domainMin in x, y and z");
                return;
            }
    if (numberField(node, "cycleInterval", 0, 1) <= 0)
        report(node, node.field("cycleInterval"), Severity::Error, fieldPos(node, "cycleInterval"),
               "cycleInterval must be positive");
    const std::string base = stringField(node, "timeBase");
    if (base != "scene" && base != "local" && base != "utc")
        report(node, node.field("timeBase"), Severity::Error, fieldPos(node, "timeBase"),
               "timeBase '" + base + "' is not scene, local or utc");
}

void DefinitionCompiler::compileNode(const Node& node) {
    if (node.type == "FGeometry") checkGeometry(node);
    if (node.type == "FMaterial") checkMaterial(node);
    checkDomain(node);
    for (const DefinitionField& df : definitionFields(node)) {
        const Field* field = node.field(df.field);
        if (!field || field->value.strings.empty()) continue;
        std::string source;
        std::vector<std::size_t> starts;
        for (const std::string& line : field->value.strings) {
            if (!starts.empty()) source += '\n';
            starts.push_back(source.size());
            source += line;
        }
        formula::CompileResult result = formula::compile(source, optionsFor(node, df.kind));
        for (const formula::Diagnostic& d : result.diagnostics) {
            const FilePos pos = locate(*field, starts, d.range.begin.offset);
            report(node, field, d.severity, pos,
                   node.type + "." + std::string(df.field) + ": " + d.message, d.suggestion);
        }
        if (result.tape && !node.inProtoBody)
            scene_.definitions.push_back(
                {&node, std::string(df.field), df.kind, std::move(*result.tape)});
    }
}

} // namespace

std::vector<DefinitionField> definitionFields(const Node& node) {
    const std::string& t = node.type;
    if (!node.spec || node.spec->family != NodeFamily::Function) return {};
    if (t == "FGeometry") {
        const std::string type = stringField(node, "type");
        return {{"definition",
                 type == "parametric" ? DefinitionKind::Parametric : DefinitionKind::Implicit}};
    }
    if (t == "FMaterial")
        return {{"definition", DefinitionKind::Colour},
                {"transparencyDefinition", DefinitionKind::Generic}};
    if (t == "FTexture3D") return {{"definition", DefinitionKind::Generic}};
    if (t == "FFriction" || t == "FTension" || t == "FDensity")
        return {{"definition", DefinitionKind::Implicit}};
    if (t == "FForce") return {{"definition", DefinitionKind::Force}};
    if (t == "FTransform")
        return {{"translation", DefinitionKind::Parametric},
                {"rotationAngle", DefinitionKind::Generic},
                {"scale", DefinitionKind::Parametric},
                {"morphFactor", DefinitionKind::Generic},
                {"operationDefinition", DefinitionKind::Generic}};
    return {};
}

void compileFunctionDefinitions(Scene& scene, std::vector<SceneDiagnostic>& diagnostics) {
    DefinitionCompiler compiler(scene, diagnostics);
    std::vector<const Node*> nodes;
    scene.forEachNode([&](const Node& n) {
        if (n.spec && n.spec->family == NodeFamily::Function) nodes.push_back(&n);
    });
    for (const Node* n : nodes)
        compiler.compileNode(*n);
}

} // namespace fl::scene
