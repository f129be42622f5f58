// `functionlab formula check|eval`: the formula engine from the command line.
#include "arguments.h"
#include "commands.h"
#include "json.h"
#include "platform/exit_codes.h"

#include "formula/compiler.h"
#include "formula/eval_gradient.h"
#include "formula/eval_scalar.h"
#include "formula/nonfinite_report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

namespace fl::cli {

namespace {

using namespace fl::formula;

// --kind, shared by check and eval.
OptionSpec kindOption() {
    return {.name = "kind",
            .kind = OptionKind::Choice,
            .valueName = "KIND",
            .help = "what the formula defines: generic (all of x y z t u v w readable, one "
                    "value), implicit, parametric, colour (or color) or force",
            .defaultValue = "generic",
            .choices = {"generic", "implicit", "parametric", "colour", "color", "force"}};
}

OptionSpec jsonOption(std::string_view help) {
    return {.name = "json", .kind = OptionKind::Flag, .help = help};
}

PositionalSpec sourceArgument() {
    return {.name = "SRC",
            .help = "the formula or script, as one argument; it may start with '-' (\"-x^2\"); "
                    "write -- before one that starts with \"--\""};
}

DefinitionKind kindOf(const std::string& s) {
    if (s == "implicit") return DefinitionKind::Implicit;
    if (s == "parametric") return DefinitionKind::Parametric;
    if (s == "colour" || s == "color") return DefinitionKind::Colour;
    if (s == "force") return DefinitionKind::Force;
    return DefinitionKind::Generic;
}

std::string diagnosticsJson(const std::vector<Diagnostic>& diags) {
    std::string out = "[";
    for (std::size_t i = 0; i < diags.size(); ++i) {
        const Diagnostic& d = diags[i];
        if (i) out += ", ";
        out += "{\"severity\": " + jsonString(severityName(d.severity)) +
               ", \"line\": " + std::to_string(d.range.begin.line) +
               ", \"column\": " + std::to_string(d.range.begin.column) +
               ", \"end_line\": " + std::to_string(d.range.end.line) +
               ", \"end_column\": " + std::to_string(d.range.end.column) +
               ", \"message\": " + jsonString(d.message) +
               ", \"suggestion\": " + jsonString(d.suggestion) + "}";
    }
    return out + "]";
}

void printDiagnostics(const std::vector<Diagnostic>& diags, const std::string& src) {
    for (const Diagnostic& d : diags)
        std::cerr << formatDiagnostic(d, src, "formula");
}

} // namespace

const CommandSpec& formulaCheckSpec() {
    static const CommandSpec spec{
        .name = "formula check",
        .summary = "check a formula or script; diagnostics with carets",
        .synopsis = {"formula check \"SRC\" [--kind KIND] [--tape] [--json]"},
        .description = "Parses and checks SRC and prints each diagnostic as\n"
                       "  formula:LINE:COL: error|warning: message (suggestion)\n"
                       "with the source line and a caret under the range.\n",
        .positionals = {sourceArgument()},
        .options = {kindOption(),
                    {.name = "tape", .help = "also print the compiled tape"},
                    jsonOption("print {\"ok\": bool, \"diagnostics\": [...]} instead")},
        .exitStatus = "0 checked, 1 the formula has errors, 2 usage error",
        .positionalsMayStartWithDash = true,
        .doubleDash = DoubleDash::QuotesNext,
    };
    return spec;
}

int formulaCheckCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(formulaCheckSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::string source = a->positional("SRC");
    CompileOptions co;
    co.kind = kindOf(a->text("kind"));
    CompileResult r = compile(source, co);
    if (a->flag("json")) {
        std::cout << "{\"ok\": " << (r.ok() ? "true" : "false")
                  << ", \"diagnostics\": " << diagnosticsJson(r.diagnostics) << "}\n";
    } else {
        printDiagnostics(r.diagnostics, source);
        if (r.ok()) {
            std::cout << "ok: " << r.tape->code.size() << " operations, " << r.tape->registerCount
                      << " registers, outputs:";
            for (const OutputInfo& out : r.tape->outputs)
                std::cout << " " << out.name;
            std::cout << "\n";
            if (a->flag("tape")) std::cout << r.tape->disassemble();
        }
    }
    return r.ok() ? kExitOk : kExitDiagnostic;
}

const CommandSpec& formulaEvalSpec() {
    static const CommandSpec spec{
        .name = "formula eval",
        .summary = "evaluate a formula at one point: value and gradient",
        .synopsis =
            {"formula eval \"SRC\" --at X,Y,Z [--t T] [--uvw U,V,W] [--param NAME=VALUE ...]\n"
             "[--kind KIND] [--json]"},
        .description =
            "Evaluates SRC at one point and prints each output with its gradient (d/dx,\n"
            "d/dy, d/dz; d/du, d/dv, d/dw for --kind parametric). --json prints exactly\n"
            "one JSON object:\n"
            "  {\"value\": number|null, \"finite\": bool, \"gradient\": [gx, gy, gz],\n"
            "   \"diagnostics\": [...]}  (null where the value is NaN or infinite)\n",
        .positionals = {sourceArgument()},
        .options = {{.name = "at",
                     .kind = OptionKind::NumberList,
                     .valueName = "X,Y,Z",
                     .help = "the point (required unless --kind parametric)",
                     .count = 3},
                    {.name = "t",
                     .kind = OptionKind::Number,
                     .valueName = "T",
                     .help = "the time",
                     .defaultValue = "0"},
                    {.name = "uvw",
                     .kind = OptionKind::NumberList,
                     .valueName = "U,V,W",
                     .help = "the parameters of a parametric definition (required with --kind "
                             "parametric)",
                     .count = 3},
                    {.name = "param",
                     .kind = OptionKind::KeyValue,
                     .valueName = "NAME=VALUE",
                     .help = "set a `param` the formula declares; give it once per parameter",
                     .repeatable = true,
                     .numericValue = true},
                    kindOption(),
                    jsonOption("print one JSON object instead")},
        .exitStatus = "0 evaluated (a NaN or infinite value too, with a warning), 1 the formula "
                      "has errors, 2 usage error",
        .positionalsMayStartWithDash = true,
        .doubleDash = DoubleDash::QuotesNext,
    };
    return spec;
}

int formulaEvalCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(formulaEvalSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::string source = a->positional("SRC");
    const DefinitionKind kind = kindOf(a->text("kind"));
    const bool json = a->flag("json");
    const std::vector<std::pair<std::string, double>> params = a->keyNumbers("param");
    const auto at = a->numbers("at"), uvw = a->numbers("uvw");
    bool parametric = kind == DefinitionKind::Parametric;
    if (!parametric && !at)
        return usageError(formulaEvalSpec(), "eval needs the point: --at X,Y,Z", std::cerr);
    if (parametric && !uvw)
        return usageError(formulaEvalSpec(), "a parametric definition needs --uvw U,V,W",
                          std::cerr);
    CompileOptions co;
    co.kind = kind;
    CompileResult r = compile(source, co);
    std::vector<Diagnostic> diags = r.diagnostics;
    if (r.ok()) {
        for (const auto& [name, value] : params) {
            if (r.tape->paramRegister(name) < 0) {
                diags.push_back({Severity::Error,
                                 {},
                                 "the formula has no parameter '" + name + "'",
                                 "declare it: param " + name + " = 1;"});
            }
        }
    }
    bool ok = r.ok() && !hasErrors(diags);
    if (!ok) {
        if (json) {
            std::cout << "{\"value\": null, \"finite\": false, \"gradient\": [null, null, null], "
                         "\"diagnostics\": "
                      << diagnosticsJson(diags) << "}\n";
        } else {
            printDiagnostics(diags, source);
        }
        return kExitDiagnostic;
    }
    const Tape& tape = *r.tape;
    Point p{};
    if (at) {
        p[0] = (*at)[0];
        p[1] = (*at)[1];
        p[2] = (*at)[2];
    }
    if (uvw) {
        p[4] = (*uvw)[0];
        p[5] = (*uvw)[1];
        p[6] = (*uvw)[2];
    }
    p[3] = a->number("t", 0.0);
    std::array<Input, 3> wrt = parametric ? std::array<Input, 3>{Input::U, Input::V, Input::W}
                                          : std::array<Input, 3>{Input::X, Input::Y, Input::Z};
    GradientEvaluator g(tape, wrt);
    ScalarEvaluator s(tape);
    for (const auto& [name, value] : params) {
        g.parameters().set(name, value);
        s.parameters().set(name, value);
    }
    std::vector<Dual> outs(tape.outputs.size());
    g.evaluateAll(p, outs.data());
    std::vector<double> values(tape.outputs.size());
    s.evaluateAll(p, values.data());
    if (auto warn = explainNonFinite(tape, s.parameters().values(), p)) diags.push_back(*warn);

    const double value = values.empty() ? 0.0 : values[0];
    bool finite = true; // every output, not only the first
    for (double v : values)
        finite = finite && std::isfinite(v);
    Dual d = outs[0];
    if (!std::isfinite(value)) d.d = {NAN, NAN, NAN}; // no gradient of an undefined value
    if (json) {
        std::cout << "{\"value\": " << jsonNumber(value)
                  << ", \"finite\": " << (finite ? "true" : "false") << ", \"gradient\": ["
                  << jsonNumber(d.d[0]) << ", " << jsonNumber(d.d[1]) << ", " << jsonNumber(d.d[2])
                  << "]";
        if (tape.outputs.size() > 1) {
            std::cout << ", \"outputs\": {";
            for (std::size_t i = 0; i < values.size(); ++i)
                std::cout << (i ? ", " : "") << jsonString(tape.outputs[i].name) << ": "
                          << jsonNumber(values[i]);
            std::cout << "}";
        }
        std::cout << ", \"diagnostics\": " << diagnosticsJson(diags) << "}\n";
    } else {
        printDiagnostics(diags, source);
        std::cout.precision(17);
        for (std::size_t i = 0; i < values.size(); ++i) {
            const char* axes = parametric ? "uvw" : "xyz";
            std::cout << tape.outputs[i].name << " = " << values[i] << "\n";
            std::cout << "  gradient = (" << outs[i].d[0] << ", " << outs[i].d[1] << ", "
                      << outs[i].d[2] << ")  [d/d" << axes[0] << ", d/d" << axes[1] << ", d/d"
                      << axes[2] << "]\n";
        }
    }
    return kExitOk;
}

} // namespace fl::cli
