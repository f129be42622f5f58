// functionlab-bench: the benchmarks that compare with peers the product does
// not link (muParser, and through it OpenMP). `functionlab bench eval` runs
// this executable, found next to functionlab; its options are the ones
// declared in measure/bench_eval_spec.cpp, read by the same table.
//
//   functionlab-bench eval [--json] [--side N] [--seconds S]
#include "measure/bench_eval_spec.h"
#include "platform/exit_codes.h"

#include "eval_table.h"

#include <iostream>

int main(int argc, char** argv) {
    using namespace fl::cli;
    using fl::measure::benchEvalSpec;
    const Args all(argv + 1, argv + argc);
    if (all.empty() || all[0] != "eval") {
        if (!all.empty() && (all[0] == "--help" || all[0] == "-h")) {
            std::cout << helpText(benchEvalSpec());
            return kExitOk;
        }
        std::cerr << "functionlab-bench: give the benchmark to run\n\n"
                  << usageText(benchEvalSpec());
        return kExitUsage;
    }
    int exit = 0;
    const auto a = parseOrExplain(benchEvalSpec(), Args(all.begin() + 1, all.end()), exit,
                                  std::cout, std::cerr);
    if (!a) return exit;
    const auto rows =
        fl::bench::runEvalTable(std::size_t(a->integer("side", 64)), a->number("seconds", 0.2));
    std::cout << (a->flag("json") ? fl::bench::evalTableJson(rows)
                                  : fl::bench::formatEvalTable(rows));
    return kExitOk;
}
