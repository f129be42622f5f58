#include "cli/bench_field.h"

#include "cli/arguments.h"
#include "formula/compiler.h"
#include "platform/exit_codes.h"

#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"
#include "scene/source_map.h"

#include <iostream>

namespace fl::cli {
namespace {

std::optional<BenchShape> fromScene(std::string_view command, const std::string& file) {
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return std::nullopt;
    std::optional<BenchShape> shape;
    r.scene->forEachNode([&](const scene::Node& n) {
        if (shape || n.inProtoBody || n.kind() != scene::NodeKind::FGeometry ||
            scene::stringField(n, "type") == "parametric")
            return;
        const formula::Tape* tape = r.scene->definition(n, "definition");
        if (!tape) return;
        shape.emplace();
        shape->field.tape = *tape;
        shape->field.box = mesh::domainOf(n);
        if (const scene::Field* definition = n.field("definition"))
            shape->source = scene::formulaText(*definition);
        if (scene::stringField(n, "setOperations") == "rfunction")
            shape->setOperations = {formula::SetOperationMode::Kind::RFunction,
                                    scene::numberField(n, "rfunctionM"),
                                    scene::numberField(n, "rfunctionAlpha")};
        shape->name = file + ":" + std::to_string(n.where.line);
    });
    if (!shape)
        std::cerr << "functionlab " << command << ": " << file
                  << " has no implicit or explicit FGeometry\n";
    return shape;
}

} // namespace

PositionalSpec benchShapePositional() {
    return {.name = "FILE",
            .help = "a scene: its first implicit or explicit FShape (or give --formula and --box)",
            .required = false};
}

std::vector<OptionSpec> benchShapeOptions(std::vector<OptionSpec> others) {
    std::vector<OptionSpec> options{
        {.name = "formula",
         .kind = OptionKind::Text,
         .valueName = "SRC",
         .help = "this formula (f >= 0 inside) instead of a scene's shape"},
        {.name = "box",
         .kind = OptionKind::NumberList,
         .valueName = "X0,Y0,Z0,X1,Y1,Z1",
         .help = "the formula's box, max above min on every axis",
         .count = 6}};
    options.insert(options.end(), others.begin(), others.end());
    return options;
}

std::optional<BenchShape> benchShapeFromArgs(const CommandSpec& spec, const ParsedArgs& a,
                                             int& exitCode) {
    const std::string file = a.positional("FILE"), formula = a.text("formula");
    auto usage = [&](const std::string& problem) {
        exitCode = usageError(spec, problem, std::cerr);
        return std::nullopt;
    };
    if (file.empty() == formula.empty()) return usage("give a scene FILE or --formula, not both");
    exitCode = kExitDiagnostic;
    if (formula.empty()) return fromScene(spec.name, file);
    const auto b = a.numbers("box");
    if (!b) return usage("--formula needs --box X0,Y0,Z0,X1,Y1,Z1");
    BenchShape shape;
    shape.field.box = {{(*b)[0], (*b)[1], (*b)[2]}, {(*b)[3], (*b)[4], (*b)[5]}};
    if (!shape.field.box.valid()) return usage("the box needs max above min on every axis");
    auto tape = compileFormulaArgument(formula, formula::DefinitionKind::Implicit);
    if (!tape) return std::nullopt;
    shape.field.tape = std::move(*tape);
    shape.source = formula;
    shape.name = formula;
    return shape;
}

} // namespace fl::cli
