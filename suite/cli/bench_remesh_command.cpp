// `functionlab bench remesh`: what a student waits for after an edit — the
// formula compiled again and its shape meshed again — over many edits
// (issue 31 §3: p50 and p95 at resolution 128).
#include "cli/arguments.h"
#include "cli/bench_field.h"
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "formula/compiler.h"
#include "measure/percentiles.h"
#include "mesh/dual_contouring.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace fl::cli {
namespace {

using Clock = std::chrono::steady_clock;

// The most memory the process has held (resident), in MiB.
double peakMiB() {
    rusage usage{};
    return ::getrusage(RUSAGE_SELF, &usage) == 0 ? double(usage.ru_maxrss) / 1024.0 : 0.0;
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

} // namespace

const CommandSpec& benchRemeshSpec() {
    static const CommandSpec spec{
        .name = "bench remesh",
        .summary = "what an edit costs: the formula compiled and its shape meshed again",
        .synopsis = {"bench remesh FILE [--resolution N] [--edits N] [--threads N] [--whole-tape] "
                     "[--json]",
                     "bench remesh --formula \"SRC\" --box X0,Y0,Z0,X1,Y1,Z1 [options]"},
        .description =
            "Edits the formula of one shape — the first implicit or explicit FShape of the\n"
            "scene FILE, or --formula over --box — N times, each edit a new constant added\n"
            "to it (so every edit is new to the compiler and to the machine-code cache, as\n"
            "a student's is), and after each compiles it and meshes it with the adaptive\n"
            "mesher at the resolution: the time from an edit to its mesh. Prints the first\n"
            "(cold) edit and the p50 and p95 of the others, for compiling, meshing and both,\n"
            "and the most memory the process held (its peak resident size).\n"
            "A scene's formula is compiled as --formula would be: its set-operation mode\n"
            "and slider values are not applied (the watermelon has neither). A formula that\n"
            "is a script (with ';') is edited by compiling it again unchanged.\n",
        .positionals = {benchShapePositional()},
        .options = benchShapeOptions(
            {{.name = "resolution",
              .kind = OptionKind::Number,
              .valueName = "N",
              .help = "cells along the box's longest side",
              .defaultValue = "128",
              .min = 1,
              .max = 1024},
             {.name = "edits",
              .kind = OptionKind::Integer,
              .valueName = "N",
              .help = "how many edits",
              .defaultValue = "50",
              .min = 2,
              .max = 100000},
             {.name = "threads",
              .kind = OptionKind::Integer,
              .valueName = "N",
              .help = "meshing threads (0: one per core)",
              .defaultValue = "0",
              .min = 0,
              .max = 256},
             {.name = "whole-tape",
              .help = "mesh without simplifying the formula per block (the min, max and "
                      "select each block's interval decides are kept): the baseline of "
                      "that step, same mesh"},
             {.name = "json",
              .help = "print {\"edits\", \"resolution\", \"cold_ms\", \"compile_ms\": "
                      "{\"p50\", \"p95\"}, \"mesh_ms\": {...}, \"total_ms\": {...}, "
                      "\"peak_mib\"}"}}),
        .exitStatus = "0 measured, 1 the input has errors, 2 usage error",
    };
    return spec;
}

int benchRemeshCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchRemeshSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const auto shape = benchShapeFromArgs(benchRemeshSpec(), *a, exit);
    if (!shape) return exit;
    const std::string& text = shape->source;
    const field::Box3& box = shape->field.box;
    const bool script = text.find(';') != std::string::npos;
    const std::size_t edits = std::size_t(a->integer("edits", 50));
    mesh::MeshOptions options;
    options.resolution = a->number("resolution", 128);
    options.threads = int(a->integer("threads", 0));
    options.simplifyPerBlock = !a->flag("whole-tape");
    std::vector<double> compileMs, meshMs, totalMs;
    double coldMs = 0;
    for (std::size_t k = 0; k < edits; ++k) {
        char constant[64];
        std::snprintf(constant, sizeof constant, "%.3g", 1e-9 * double(k + 1));
        const std::string edited = script ? text : "(" + text + ") + " + constant;
        const auto started = Clock::now();
        formula::CompileOptions co;
        co.kind = formula::DefinitionKind::Implicit;
        co.setOperations = shape->setOperations;
        formula::CompileResult compiled = formula::compile(edited, co);
        const double compiling = msSince(started);
        if (!compiled.tape) {
            for (const formula::Diagnostic& d : compiled.diagnostics)
                std::cerr << formula::formatDiagnostic(d, edited, "formula");
            return kExitDiagnostic;
        }
        field::ImplicitField field;
        field.tape = std::move(*compiled.tape);
        field.box = box;
        const auto meshing = Clock::now();
        const mesh::MeshResult m = mesh::meshImplicit(field, options);
        const double meshed = msSince(meshing);
        if (!m.error.empty()) {
            std::cerr << "functionlab bench remesh: " << m.error << "\n";
            return kExitDiagnostic;
        }
        if (k == 0) {
            coldMs = compiling + meshed;
            continue;
        }
        compileMs.push_back(compiling);
        meshMs.push_back(meshed);
        totalMs.push_back(compiling + meshed);
    }
    const measure::Spread c = measure::spreadOf(compileMs), m = measure::spreadOf(meshMs),
                          t = measure::spreadOf(totalMs);
    if (a->flag("json")) {
        std::printf("{\"edits\": %zu, \"resolution\": %g, \"cold_ms\": %.3f, "
                    "\"compile_ms\": {\"p50\": %.3f, \"p95\": %.3f}, "
                    "\"mesh_ms\": {\"p50\": %.3f, \"p95\": %.3f}, "
                    "\"total_ms\": {\"p50\": %.3f, \"p95\": %.3f}, \"peak_mib\": %.1f}\n",
                    edits, options.resolution, coldMs, c.p50, c.p95, m.p50, m.p95, t.p50, t.p95,
                    peakMiB());
        return kExitOk;
    }
    std::printf("%zu edits at resolution %g%s: the first %.1f ms; the others p50 %.1f ms, p95 "
                "%.1f ms (compiling p50 %.2f ms, p95 %.2f ms; meshing p50 %.1f ms, p95 %.1f ms)\n",
                edits, options.resolution, script ? " (a script: compiled unchanged)" : "", coldMs,
                t.p50, t.p95, c.p50, c.p95, m.p50, m.p95);
    std::printf("peak memory of the process: %.0f MiB\n", peakMiB());
    return kExitOk;
}

} // namespace fl::cli
