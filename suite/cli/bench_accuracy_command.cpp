// `functionlab bench accuracy`: what accuracy costs in time (bench/accuracy_sweep).
#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

#include "accuracy_sweep.h"
#include "formula/compiler.h"
#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace fl::cli {
namespace {

int usage(const std::string& problem) {
    std::cerr << "functionlab bench accuracy: " << problem << "\n(see functionlab bench --help)\n";
    return kExitUsage;
}

// The first implicit or explicit FShape's geometry of a scene.
bool fieldFromScene(const std::string& file, mesh::ImplicitField& field, std::string& name) {
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return false;
    bool found = false;
    r.scene->forEachNode([&](const scene::Node& n) {
        if (found || n.inProtoBody || n.type != "FGeometry" ||
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
        std::cerr << "functionlab bench accuracy: " << file
                  << " has no implicit or explicit FGeometry\n";
    return found;
}

// A whole number in [lo, hi] written out in full ("8192"), or none.
std::optional<double> wholeNumber(const std::string& text, double lo, double hi) {
    double v = 0;
    if (!parseNumber(text, v) || !(v >= lo && v <= hi) || v != std::floor(v)) return std::nullopt;
    return v;
}

} // namespace

int benchAccuracyCommand(const Args& args) {
    std::string file, formula, box, plot;
    std::vector<double> resolutions{16, 32, 64, 128, 256};
    bool json = false;
    bench::SweepOptions sweep;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "--json")
            json = true;
        else if (a == "--formula" && hasValue)
            formula = args[++i];
        else if (a == "--box" && hasValue)
            box = args[++i];
        else if (a == "--plot" && hasValue)
            plot = args[++i];
        else if (a == "--threads" && hasValue) {
            const std::optional<double> n = wholeNumber(args[++i], 0, 1024);
            if (!n) return usage("--threads needs a whole number 0..1024 (0: one per core)");
            sweep.threads = int(*n);
        } else if (a == "--memory" && hasValue) {
            const std::optional<double> mib = wholeNumber(args[++i], 1, double(1 << 30));
            if (!mib) return usage("--memory needs a budget in MiB, e.g. --memory 8192");
            sweep.memoryBudgetBytes = std::size_t(*mib) * 1024 * 1024;
        } else if (a == "--resolutions" && hasValue) {
            if (!parseNumberList(args[++i], resolutions))
                return usage("--resolutions needs numbers like 16,32,64");
            for (double r : resolutions)
                if (r < 1 || r > 2048) return usage("resolutions must lie in 1..2048");
        } else if (!a.starts_with("-") && file.empty())
            file = a;
        else
            return usage("unexpected argument '" + a + "'");
    }
    if (file.empty() == formula.empty()) return usage("give a scene FILE or --formula, not both");
    mesh::ImplicitField field;
    std::string name;
    if (!formula.empty()) {
        std::vector<double> b;
        if (!parseNumberList(box, b) || b.size() != 6)
            return usage("--formula needs --box X0,Y0,Z0,X1,Y1,Z1");
        field.box = {{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
        if (!field.box.valid()) return usage("the box needs max above min on every axis");
        auto tape = compileFormulaArgument(formula, formula::DefinitionKind::Implicit);
        if (!tape) return kExitDiagnostic;
        field.tape = std::move(*tape);
        name = formula;
    } else if (!fieldFromScene(file, field, name)) {
        return kExitDiagnostic;
    }
    std::vector<std::string> skipped;
    const std::vector<bench::AccuracyRow> rows =
        bench::runAccuracySweep(field, resolutions, sweep, &skipped);
    for (const std::string& s : skipped)
        std::cerr << "note: no row for " << s << "\n";
    std::cout << (json ? bench::accuracyJson(rows) : bench::accuracyTableText(rows));
    if (!plot.empty()) {
        std::ofstream out(plot);
        out << bench::accuracyPlotSvg(rows, "error against time: " + name);
        if (!out) {
            std::cerr << "functionlab bench accuracy: cannot write " << plot << "\n";
            return kExitDiagnostic;
        }
    }
    return kExitOk;
}

} // namespace fl::cli
