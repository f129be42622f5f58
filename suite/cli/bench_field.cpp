#include "cli/bench_field.h"

#include "cli/arguments.h"
#include "formula/compiler.h"
#include "platform/exit_codes.h"

#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <iostream>

namespace fl::cli {

bool benchFieldFromScene(const std::string& command, const std::string& file,
                         field::ImplicitField& field, std::string& name) {
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return false;
    bool found = false;
    r.scene->forEachNode([&](const scene::Node& n) {
        if (found || n.inProtoBody || n.kind() != scene::NodeKind::FGeometry ||
            scene::stringField(n, "type") == "parametric")
            return;
        const formula::Tape* tape = r.scene->definition(n, "definition");
        if (!tape) return;
        field.tape = *tape;
        field.box = mesh::domainOf(n);
        name = file + ":" + std::to_string(n.where.line);
        found = true;
    });
    if (!found)
        std::cerr << "functionlab " << command << ": " << file
                  << " has no implicit or explicit FGeometry\n";
    return found;
}

std::optional<field::ImplicitField> benchFieldFromArgs(const CommandSpec& spec, const ParsedArgs& a,
                                                       std::string& name, int& exitCode) {
    const std::string file = a.positional("FILE"), formula = a.text("formula");
    auto usage = [&](const std::string& problem) {
        exitCode = usageError(spec, problem, std::cerr);
        return std::nullopt;
    };
    if (file.empty() == formula.empty()) return usage("give a scene FILE or --formula, not both");
    field::ImplicitField field;
    exitCode = kExitDiagnostic;
    if (formula.empty())
        return benchFieldFromScene(std::string(spec.name), file, field, name)
                   ? std::optional(std::move(field))
                   : std::nullopt;
    const auto b = a.numbers("box");
    if (!b) return usage("--formula needs --box X0,Y0,Z0,X1,Y1,Z1");
    field.box = {{(*b)[0], (*b)[1], (*b)[2]}, {(*b)[3], (*b)[4], (*b)[5]}};
    if (!field.box.valid()) return usage("the box needs max above min on every axis");
    auto tape = compileFormulaArgument(formula, formula::DefinitionKind::Implicit);
    if (!tape) return std::nullopt;
    field.tape = std::move(*tape);
    name = formula;
    return field;
}

} // namespace fl::cli
