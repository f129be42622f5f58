// functionlab-bench: the benchmarks that compare with peers the product does
// not link (muParser and through it OpenMP; Draco and meshoptimizer).
// `functionlab bench eval` and `functionlab bench pde` run this executable,
// found next to functionlab; their options are the ones declared in
// measure/bench_eval_spec.cpp and measure/bench_pde_spec.cpp, read by the
// same table.
//
//   functionlab-bench eval [--json] [--side N] [--seconds S]
//   functionlab-bench pde MESH.obj [--patches ...] [--draco ...] [--json]
#include "measure/bench_eval_spec.h"
#include "measure/bench_pde_spec.h"
#include "platform/exit_codes.h"

#include "eval_table.h"
#ifdef FUNCTIONLAB_BENCH_PDE
#include "pde_table.h"
#endif

#include <fstream>
#include <iostream>

namespace {

using namespace fl::cli;

int eval(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(fl::measure::benchEvalSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const auto rows =
        fl::bench::runEvalTable(std::size_t(a->integer("side", 64)), a->number("seconds", 0.2));
    std::cout << (a->flag("json") ? fl::bench::evalTableJson(rows)
                                  : fl::bench::formatEvalTable(rows));
    return kExitOk;
}

int pde(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(fl::measure::benchPdeSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
#ifdef FUNCTIONLAB_BENCH_PDE
    fl::bench::PdeBenchOptions o;
    o.patches = *a->numbers("patches");
    o.radii = std::size_t(a->integer("radii", 8));
    o.dracoBits = *a->numbers("draco");
    o.simplifyErrors = *a->numbers("simplify");
    o.samples = std::size_t(a->integer("samples", 100000));
    const std::string mesh = a->positional("MESH");
    std::string why;
    const auto rows = fl::bench::runPdeBench(mesh, o, why);
    if (rows.empty()) {
        std::cerr << why << "\n";
        return kExitDiagnostic;
    }
    std::cout << (a->flag("json") ? fl::bench::pdeRowsJson(mesh, rows)
                                  : fl::bench::formatPdeTable(mesh, rows));
    if (!why.empty()) std::cerr << "functionlab bench pde: " << why << "\n";
    if (const std::string plot = a->text("plot"); !plot.empty()) {
        std::ofstream out(plot, std::ios::binary | std::ios::trunc);
        if (!(out << fl::bench::pdePlotSvg(mesh, rows))) {
            std::cerr << "functionlab bench pde: " << plot << ": cannot be written\n";
            return kExitDiagnostic;
        }
    }
    return kExitOk;
#else
    std::cerr << "functionlab bench pde: this functionlab-bench was built without Draco and "
                 "meshoptimizer (Debian: libdraco-dev libmeshoptimizer-dev; scripts/run installs "
                 "them)\n";
    return kExitDiagnostic;
#endif
}

} // namespace

int main(int argc, char** argv) {
    const Args all(argv + 1, argv + argc);
    if (!all.empty() && all[0] == "eval") return eval(Args(all.begin() + 1, all.end()));
    if (!all.empty() && all[0] == "pde") return pde(Args(all.begin() + 1, all.end()));
    if (!all.empty() && (all[0] == "--help" || all[0] == "-h")) {
        std::cout << helpText(fl::measure::benchEvalSpec()) << "\n"
                  << helpText(fl::measure::benchPdeSpec());
        return kExitOk;
    }
    std::cerr << "functionlab-bench: give the benchmark to run (eval or pde)\n\n"
              << usageText(fl::measure::benchEvalSpec()) << usageText(fl::measure::benchPdeSpec());
    return kExitUsage;
}
