#include "function_definitions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "field_access.h"
#include "function_kinds.h"
#include "source_map.h"

#include <map>
#include <set>
#include <tuple>

namespace fl::scene {
namespace {

// Numbers in a cache key: every bit counts (0.1 and 0.1000000001 differ).
std::string formatNumberKey(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

using formula::DefinitionKind;

class DefinitionCompiler {
  public:
    DefinitionCompiler(Scene& scene, std::vector<SceneDiagnostic>& out, const ReadLimits& limits)
        : scene_(scene), out_(out), limits_(limits) {}

    // False once the scene's formulas cost more than the limits allow.
    bool compileNode(const Node& node);

  private:
    void report(const Node& node, const Field* field, Severity severity, FilePos pos,
                std::string message, std::string suggestion = {}) {
        const int file = field && field->file >= 0 ? field->file : node.file;
        const std::string& path = scene_.pathOf(file);
        // A PROTO body and each of its instances compile the same text: say it once.
        if (!seen_.emplace(path, pos.line, pos.column, message).second) return;
        // "type '\"explicit\"' is not ...": the quotes of ClassicVRML carried
        // into an XML attribute, where SFString values stand bare.
        if (suggestion.empty() && message.find("'\"") != std::string::npos &&
            message.find("\"'") != std::string::npos)
            suggestion = "drop the double quotes: in X3D XML a single string is written bare, as "
                         "in type='explicit'";
        out_.push_back({severity, path, pos, std::move(message), std::move(suggestion)});
    }
    FilePos fieldPos(const Node& node, std::string_view name) {
        const Field* f = node.field(name);
        return f ? f->where : node.where;
    }
    const LineIndex& lines(int file) { return lineIndexes_.of(file); }
    formula::CompileOptions optionsFor(const Node& node, DefinitionKind kind);
    void checkGeometry(const Node& node);
    void warnDroppedBackslashes(const Node& node, const Field& field);
    void checkTransform(const Node& node);
    void checkMaterialOutputs(const Node& node, const formula::Tape& tape, const Field& field);
    void checkMaterial(const Node& node);
    void checkDomain(const Node& node);

    // One compilation per distinct text and options: a PROTO's instances
    // share it (and its tape).
    struct Compiled {
        std::shared_ptr<const formula::Tape> tape;
        std::vector<formula::Diagnostic> diagnostics;
    };
    const Compiled& compiled(const std::string& source, const formula::CompileOptions& options);
    bool overBudget(const Node& node, const Field& field);

    Scene& scene_;
    std::vector<SceneDiagnostic>& out_;
    const ReadLimits& limits_;
    std::map<std::string, Compiled> cache_;
    long compileSteps_ = 0;
    std::size_t tapeInstructions_ = 0;
    LineIndexes lineIndexes_{scene_};
    std::set<std::tuple<std::string, int, int, std::string>> seen_;
};

formula::CompileOptions DefinitionCompiler::optionsFor(const Node& node, DefinitionKind kind) {
    formula::CompileOptions options;
    options.kind = kind;
    if (node.kind() == scene::NodeKind::FGeometry &&
        stringField(node, "setOperations") == "rfunction") {
        options.setOperations.kind = formula::SetOperationMode::Kind::RFunction;
        options.setOperations.m = numberField(node, "rfunctionM");
        options.setOperations.alpha = numberField(node, "rfunctionAlpha");
    }
    if (node.kind() == scene::NodeKind::FTransform) {
        // The user's operation formula reads each child's value as f1, f2, ...
        std::size_t children = nodesField(node, "children").size();
        for (std::size_t i = 1; i <= std::max<std::size_t>(children, 1); ++i)
            options.parameters.push_back({"f" + std::to_string(i), 0.0, false, 0.0, 0.0});
    }
    return options;
}

void DefinitionCompiler::checkGeometry(const Node& node) {
    const std::string word = stringField(node, "type");
    const std::optional<GeometryType> type = geometryTypeNamed(word);
    if (!type)
        report(node, node.field("type"), Severity::Error, fieldPos(node, "type"),
               "FGeometry type '" + word + "' is not implicit, explicit or parametric");
    const std::string ops = stringField(node, "setOperations");
    if (ops != "minmax" && ops != "rfunction")
        report(node, node.field("setOperations"), Severity::Error, fieldPos(node, "setOperations"),
               "setOperations '" + ops + "' is not minmax or rfunction");
    const std::string collision = stringField(node, "collision");
    if (collision != "function" && collision != "polygonal")
        report(node, node.field("collision"), Severity::Error, fieldPos(node, "collision"),
               "collision '" + collision + "' is not function or polygonal");
    const Field* definition = node.field("definition");
    const bool givenByInstance = definition && !definition->isReferences.empty();
    if (stringsField(node, "definition").empty() && !givenByInstance)
        report(node, nullptr, Severity::Error, node.where, "FGeometry has no definition",
               "write definition \"1 - x^2 - y^2 - z^2\" for a unit sphere");
    if (numberField(node, "points") < 0 || numberField(node, "points") > 10'000'000)
        report(node, node.field("points"), Severity::Error, fieldPos(node, "points"),
               "points gives the size of a point cloud: 0 (draw a mesh) up to 10000000",
               "write points 20000 to draw the object as about 20000 points");
    if (numberField(node, "resolution") <= 0)
        report(node, node.field("resolution"), Severity::Error, fieldPos(node, "resolution"),
               "resolution must be positive");
    if (ops == "rfunction" &&
        !(numberField(node, "rfunctionAlpha") > -1 && numberField(node, "rfunctionAlpha") <= 1))
        report(node, node.field("rfunctionAlpha"), Severity::Error,
               fieldPos(node, "rfunctionAlpha"),
               "rfunctionAlpha must lie in (-1, 1]: at -1 and below the R-functions stop being "
               "set operations",
               "0 gives the R0 family (a smooth, exact-sign union and intersection)");
    if (ops == "rfunction" && numberField(node, "rfunctionM") < 0)
        report(node, node.field("rfunctionM"), Severity::Error, fieldPos(node, "rfunctionM"),
               "rfunctionM (the continuity of the R-functions) must not be negative");
    const auto lodRange = numbersField(node, "lodRange");
    if (lodRange.size() == 2 && !(0 < lodRange[0] && lodRange[0] <= lodRange[1]))
        report(node, node.field("lodRange"), Severity::Error, fieldPos(node, "lodRange"),
               "lodRange gives the coarsest and the finest resolution: two positive numbers, the "
               "first not above the second");
    // The default "function" quietly means polygons for parametric geometry;
    // only asking for it in the file is worth a word.
    if (type == GeometryType::Parametric && collision == "function" && node.field("collision"))
        report(node, node.field("collision"), Severity::Warning, fieldPos(node, "collision"),
               "collision 'function' needs a formula that says inside or outside; parametric "
               "geometry has none, so it is touched through its polygons",
               "write collision \"polygonal\"");
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

// In a ClassicVRML string `\x` stands for x, so the difference operator `\`
// written once vanishes ("a \ b" reads "a  b") and the formula fails with a
// puzzling message, or worse, means something else. Say so where it happens.
void DefinitionCompiler::warnDroppedBackslashes(const Node& node, const Field& field) {
    for (const StringOrigin& origin : field.value.stringOrigins) {
        if (origin.escapes != StringEscapes::Classic || origin.file < 0) continue;
        const std::string& text = scene_.files[std::size_t(origin.file)].text;
        for (std::size_t i = origin.offset; i < text.size() && text[i] != '"'; ++i) {
            if (text[i] != '\\') continue;
            if (i + 1 < text.size() && (text[i + 1] == '"' || text[i + 1] == '\\')) {
                ++i;
                continue;
            }
            report(node, &field, Severity::Warning, lines(origin.file).position(i),
                   "a single \\ in a ClassicVRML string is dropped (it escapes the next "
                   "character), so the difference operator disappears here",
                   "write \\\\ for the difference operator");
            break;
        }
    }
}

void DefinitionCompiler::checkTransform(const Node& node) {
    const std::string word = stringField(node, "operation");
    const std::optional<SetOperation> op = setOperationNamed(word);
    if (!op) {
        report(node, node.field("operation"), Severity::Error, fieldPos(node, "operation"),
               "FTransform operation '" + word +
                   "' is not group, union, intersection, difference, morph or formula");
        return;
    }
    if (op == SetOperation::Formula && stringsField(node, "operationDefinition").empty())
        report(node, node.field("operation"), Severity::Error, fieldPos(node, "operation"),
               "operation 'formula' combines the children by operationDefinition, which is empty",
               "write operationDefinition \"max(f1, f2)\" (the union of the first two children)");
    if (op == SetOperation::Morph && stringsField(node, "morphFactor").empty())
        report(node, node.field("operation"), Severity::Warning, fieldPos(node, "operation"),
               "operation 'morph' without a morphFactor shows the first child only",
               "write morphFactor \"0.5 - 0.5*cos(2*pi*t)\" to morph back and forth");
}

// Only `key`/`keyValue` decide a colour map; a parametric FMaterial assigns
// r, g, b. A formula that gives the other shape is a mistake either way.
void DefinitionCompiler::checkMaterialOutputs(const Node& node, const formula::Tape& tape,
                                              const Field& field) {
    const std::string type = stringField(node, "type");
    const bool threeOutputs = tape.outputs.size() == 3;
    if (type == "explicit" && threeOutputs)
        report(node, &field, Severity::Error, fieldPos(node, "definition"),
               "an explicit FMaterial maps one value through key and keyValue, but the definition "
               "assigns r, g and b",
               "write type \"parametric\" to give the colour directly");
    else if (type == "parametric" && !threeOutputs)
        report(node, &field, Severity::Error, fieldPos(node, "definition"),
               "a parametric FMaterial assigns r = ...; g = ...; b = ...; but the definition gives "
               "one value",
               "write type \"explicit\" with key and keyValue to map one value to colours");
}

void DefinitionCompiler::checkDomain(const Node& node) {
    if (!node.spec || !findFieldSpec(*node.spec, "timeBase")) return;
    const auto lo = numbersField(node, "domainMin"), hi = numbersField(node, "domainMax");
    if (lo.size() == 3 && hi.size() == 3)
        for (int i = 0; i < 3; ++i)
            if (!(lo[i] < hi[i])) {
                report(node, node.field("domainMax"), Severity::Error, fieldPos(node, "domainMax"),
                       "the domain box is empty: domainMax must exceed domainMin in x, y and z");
                break;
            }
    const auto span = numbersField(node, "timeSpan");
    if (span.size() == 2 && !(std::isfinite(span[0]) && std::isfinite(span[1])))
        report(node, node.field("timeSpan"), Severity::Error, fieldPos(node, "timeSpan"),
               "timeSpan must be two finite numbers");
    if (numberField(node, "cycleInterval", 0, 1) <= 0)
        report(node, node.field("cycleInterval"), Severity::Error, fieldPos(node, "cycleInterval"),
               "cycleInterval must be positive");
    const std::string base = stringField(node, "timeBase");
    if (base != "scene" && base != "local" && base != "utc")
        report(node, node.field("timeBase"), Severity::Error, fieldPos(node, "timeBase"),
               "timeBase '" + base + "' is not scene, local or utc");
}

const DefinitionCompiler::Compiled&
DefinitionCompiler::compiled(const std::string& source, const formula::CompileOptions& options) {
    std::string key = std::to_string(int(options.kind)) + ' ' +
                      std::to_string(int(options.setOperations.kind)) + ' ' +
                      formatNumberKey(options.setOperations.m) + ' ' +
                      formatNumberKey(options.setOperations.alpha) + ' ' +
                      std::to_string(options.parameters.size()) + '\n' + source;
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    formula::CompileResult result = formula::compile(source, options);
    compileSteps_ += result.expansionSteps;
    Compiled c;
    if (result.tape) c.tape = std::make_shared<const formula::Tape>(std::move(*result.tape));
    c.diagnostics = std::move(result.diagnostics);
    return cache_.emplace(std::move(key), std::move(c)).first->second;
}

bool DefinitionCompiler::overBudget(const Node& node, const Field& field) {
    std::string what;
    if (compileSteps_ > limits_.maxCompileSteps)
        what = "take more than " + std::to_string(limits_.maxCompileSteps) +
               " steps to compile (after inlining functions and unrolling loops)";
    else if (tapeInstructions_ > limits_.maxTapeInstructions)
        what = "come to more than " + std::to_string(limits_.maxTapeInstructions) + " instructions";
    if (what.empty()) return false;
    // Where the node is written: a PROTO instance, not the body it copies.
    const Node* at = &node;
    while (at->instance)
        at = at->instance;
    const std::size_t before = out_.size();
    report(*at, at == &node ? &field : nullptr, Severity::Error,
           at == &node ? field.where : at->where,
           "the scene's formulas, every PROTO instance counted, " + what +
               ": this one is past the limit",
           "use fewer instances of costly formulas, fewer loop iterations, or split the scene");
    if (out_.size() > before) out_.back().overBudget = true;
    return true;
}

bool DefinitionCompiler::compileNode(const Node& node) {
    if (node.kind() == scene::NodeKind::FGeometry) checkGeometry(node);
    if (node.kind() == scene::NodeKind::FMaterial) checkMaterial(node);
    if (node.kind() == scene::NodeKind::FTransform) checkTransform(node);
    checkDomain(node);
    for (const DefinitionField& df : definitionFields(node)) {
        const Field* field = node.field(df.field);
        if (!field || field->value.strings.empty()) continue;
        const std::string source = formulaText(*field);
        warnDroppedBackslashes(node, *field);
        const Compiled& result = compiled(source, optionsFor(node, df.kind));
        for (const formula::Diagnostic& d : result.diagnostics) {
            const FilePos pos = formulaTextPosition(*field, d.range.begin.offset, lineIndexes_);
            report(node, field, d.severity, pos,
                   node.type + "." + std::string(df.field) + ": " + d.message, d.suggestion);
        }
        if (result.tape && node.kind() == scene::NodeKind::FMaterial && df.field == "definition")
            checkMaterialOutputs(node, *result.tape, *field);
        if (result.tape && !node.inProtoBody) {
            tapeInstructions_ += result.tape->code.size();
            scene_.definitions.push_back({&node, std::string(df.field), df.kind, result.tape});
        }
        if (overBudget(node, *field)) return false;
    }
    return true;
}

} // namespace

std::vector<DefinitionField> definitionFields(const Node& node) {
    const std::string& t = node.type;
    if (!node.spec || node.spec->family != NodeFamily::Function) return {};
    if (t == "FGeometry") {
        const bool parametric =
            geometryTypeNamed(stringField(node, "type")) == GeometryType::Parametric;
        return {{"definition", parametric ? DefinitionKind::Parametric : DefinitionKind::Implicit}};
    }
    if (t == "FMaterial")
        return {{"definition", DefinitionKind::Colour},
                {"transparencyDefinition", DefinitionKind::Generic}};
    if (t == "FTexture3D") return {{"definition", DefinitionKind::Generic}};
    // Physical properties read the point both ways: x, y, z in the domain
    // box and u, v, w mapped to [0, 1]^3 (docs/nodes.md, Domains).
    if (t == "FFriction" || t == "FTension" || t == "FDensity")
        return {{"definition", DefinitionKind::Generic}};
    if (t == "FForce") return {{"definition", DefinitionKind::Force}};
    if (t == "FTransform")
        return {{"translation", DefinitionKind::Parametric},
                {"rotationAngle", DefinitionKind::Generic},
                {"scale", DefinitionKind::Parametric},
                {"morphFactor", DefinitionKind::Generic},
                {"operationDefinition", DefinitionKind::Generic}};
    return {};
}

void compileFunctionDefinitions(Scene& scene, std::vector<SceneDiagnostic>& diagnostics,
                                const ReadLimits& limits) {
    DefinitionCompiler compiler(scene, diagnostics, limits);
    std::vector<const Node*> nodes;
    scene.forEachNode([&](const Node& n) {
        if (n.spec && n.spec->family == NodeFamily::Function) nodes.push_back(&n);
    });
    for (const Node* n : nodes)
        if (!compiler.compileNode(*n)) return;
}

} // namespace fl::scene
