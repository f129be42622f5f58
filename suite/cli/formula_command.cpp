// `functionlab formula check|eval`: the formula engine from the command line.
#include "arguments.h"
#include "commands.h"
#include "exit_codes.h"
#include "json.h"

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

const char* kFormulaHelp = R"(usage: functionlab formula check "SRC" [--kind KIND] [--tape] [--json]
       functionlab formula eval "SRC" --at X,Y,Z [--t T] [--uvw U,V,W]
                                [--param NAME=VALUE ...] [--kind KIND] [--json]

check   parse and check SRC; print diagnostics with a caret under the column.
        --tape also prints the compiled tape; --json prints
        {"ok": bool, "diagnostics": [...]}.
eval    evaluate SRC at one point; print the value and the gradient (d/dx, d/dy,
        d/dz; d/du, d/dv, d/dw for --kind parametric).
        --json prints exactly one JSON object:
        {"value": number|null, "finite": bool, "gradient": [gx, gy, gz],
         "diagnostics": [...]}  (null where the value is NaN or infinite)

KIND is generic (default), implicit, parametric, colour or force.
A formula may start with '-' ("-x^2"); write -- before a formula that starts
with "--".
Exit status: 0 evaluated/checked, 1 the formula has errors, 2 usage error.
)";

bool parseKind(const std::string& s, DefinitionKind& kind) {
    if (s == "generic")
        kind = DefinitionKind::Generic;
    else if (s == "implicit")
        kind = DefinitionKind::Implicit;
    else if (s == "parametric")
        kind = DefinitionKind::Parametric;
    else if (s == "colour" || s == "color")
        kind = DefinitionKind::Colour;
    else if (s == "force")
        kind = DefinitionKind::Force;
    else
        return false;
    return true;
}

bool parseTriple(const std::string& s, double out[3]) {
    std::vector<double> v;
    if (!parseNumberList(s, v) || v.size() != 3) return false;
    std::copy(v.begin(), v.end(), out);
    return true;
}

int usage(const std::string& message) {
    std::cerr << "functionlab formula: " << message << "\n\n" << kFormulaHelp;
    return kExitUsage;
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

struct Options {
    std::string source;
    bool haveSource = false;
    DefinitionKind kind = DefinitionKind::Generic;
    bool json = false;
    bool tape = false;
    std::optional<std::array<double, 3>> at;
    std::optional<std::array<double, 3>> uvw;
    double t = 0.0;
    std::vector<std::pair<std::string, double>> params;
};

// Returns an error message, or empty when the arguments were understood.
std::string parseOptions(const Args& args, std::size_t first, Options& o) {
    for (std::size_t i = first; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::optional<std::string> {
            if (i + 1 >= args.size()) return std::nullopt;
            return args[++i];
        };
        if (a == "--json")
            o.json = true;
        else if (a == "--tape")
            o.tape = true;
        else if (a == "--kind") {
            auto v = value();
            if (!v || !parseKind(*v, o.kind))
                return "--kind needs one of generic, implicit, parametric, colour, force";
        } else if (a == "--at") {
            auto v = value();
            double p[3];
            if (!v || !parseTriple(*v, p)) return "--at needs three finite numbers: --at X,Y,Z";
            o.at = std::array<double, 3>{p[0], p[1], p[2]};
        } else if (a == "--uvw") {
            auto v = value();
            double p[3];
            if (!v || !parseTriple(*v, p)) return "--uvw needs three finite numbers: --uvw U,V,W";
            o.uvw = std::array<double, 3>{p[0], p[1], p[2]};
        } else if (a == "--t") {
            auto v = value();
            if (!v || !parseNumber(*v, o.t)) return "--t needs a finite number";
        } else if (a == "--param") {
            auto v = value();
            std::size_t eq = v ? v->find('=') : std::string::npos;
            double num;
            if (!v || eq == std::string::npos || eq == 0 || !parseNumber(v->substr(eq + 1), num))
                return "--param needs NAME=VALUE";
            o.params.emplace_back(v->substr(0, eq), num);
        } else if (a == "--" && !o.haveSource && i + 1 < args.size()) {
            o.source = args[++i]; // everything after -- is the formula, even "--x"
            o.haveSource = true;
        } else if (a.rfind("--", 0) == 0) {
            // options start with "--"; a single '-' starts a formula such as "-x^2"
            return "unknown option '" + a + "'";
        } else if (!o.haveSource) {
            o.source = a;
            o.haveSource = true;
        } else {
            return "unexpected argument '" + a + "' (quote the formula as one argument)";
        }
    }
    if (!o.haveSource) return "missing the formula: functionlab formula " + args[0] + " \"SRC\"";
    return {};
}

int check(const Args& args) {
    Options o;
    if (std::string err = parseOptions(args, 1, o); !err.empty()) return usage(err);
    CompileOptions co;
    co.kind = o.kind;
    CompileResult r = compile(o.source, co);
    if (o.json) {
        std::cout << "{\"ok\": " << (r.ok() ? "true" : "false")
                  << ", \"diagnostics\": " << diagnosticsJson(r.diagnostics) << "}\n";
    } else {
        printDiagnostics(r.diagnostics, o.source);
        if (r.ok()) {
            std::cout << "ok: " << r.tape->code.size() << " operations, " << r.tape->registerCount
                      << " registers, outputs:";
            for (const OutputInfo& out : r.tape->outputs)
                std::cout << " " << out.name;
            std::cout << "\n";
            if (o.tape) std::cout << r.tape->disassemble();
        }
    }
    return r.ok() ? kExitOk : kExitDiagnostic;
}

int eval(const Args& args) {
    Options o;
    if (std::string err = parseOptions(args, 1, o); !err.empty()) return usage(err);
    bool parametric = o.kind == DefinitionKind::Parametric;
    if (!parametric && !o.at) return usage("eval needs the point: --at X,Y,Z");
    if (parametric && !o.uvw) return usage("a parametric definition needs --uvw U,V,W");
    CompileOptions co;
    co.kind = o.kind;
    CompileResult r = compile(o.source, co);
    std::vector<Diagnostic> diags = r.diagnostics;
    if (r.ok()) {
        for (const auto& [name, value] : o.params) {
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
        if (o.json) {
            std::cout << "{\"value\": null, \"finite\": false, \"gradient\": [null, null, null], "
                         "\"diagnostics\": "
                      << diagnosticsJson(diags) << "}\n";
        } else {
            printDiagnostics(diags, o.source);
        }
        return kExitDiagnostic;
    }
    const Tape& tape = *r.tape;
    Point p{};
    if (o.at) {
        p[0] = (*o.at)[0];
        p[1] = (*o.at)[1];
        p[2] = (*o.at)[2];
    }
    if (o.uvw) {
        p[4] = (*o.uvw)[0];
        p[5] = (*o.uvw)[1];
        p[6] = (*o.uvw)[2];
    }
    p[3] = o.t;
    std::array<Input, 3> wrt = parametric ? std::array<Input, 3>{Input::U, Input::V, Input::W}
                                          : std::array<Input, 3>{Input::X, Input::Y, Input::Z};
    GradientEvaluator g(tape, wrt);
    ScalarEvaluator s(tape);
    for (const auto& [name, value] : o.params) {
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
    if (o.json) {
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
        printDiagnostics(diags, o.source);
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

} // namespace

int formulaCommand(const Args& args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << kFormulaHelp;
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] == "check") return check(args);
    if (args[0] == "eval") return eval(args);
    return usage("unknown formula command '" + args[0] + "'");
}

} // namespace fl::cli
