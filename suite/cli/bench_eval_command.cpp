// `functionlab bench eval`: the evaluator benchmark table (bench/eval_table).
#include "arguments.h"
#include "commands.h"
#include "exit_codes.h"

#include "eval_table.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace fl::cli {

namespace {
const char* kBenchHelp = R"(usage: functionlab bench eval [--json] [--side N] [--seconds S]
       functionlab bench accuracy FILE|--formula "SRC" --box X0,Y0,Z0,X1,Y1,Z1
                                  [--json] [--plot OUT.svg] [--resolutions N,N,...]
                                  [--threads N] [--memory MIB]

eval    evaluates the benchmark formulas over an N^3 grid (default 64) with
        FunctionLab's batch evaluator, the same formulas hand-written in C++,
        and muParser, all on one thread; prints nanoseconds per point and the
        ratios. The engines take turns for at least S seconds (default 0.2)
        and each reports its best turn.
        --json prints a list of {"formula", "ns_per_point": {"functionlab",
        "native", "muparser"}}.

accuracy  sweeps the resolution (default 16,32,64,128,256 cells along the
        longest side) for the adaptive mesher and for dense marching cubes in
        the same run, and reports per row: method, resolution, triangles,
        function evaluations, milliseconds, and the max and mean distance from
        mesh to true surface as a fraction of the box diagonal (|f|/|grad f|
        sampled on triangle interiors). FILE: its first implicit or explicit
        FShape. --json prints a list of {"method", "resolution", "triangles",
        "evaluations", "ms", "max_error", "mean_error"}; --plot draws error
        against time (log-log) for both methods as SVG. Resolutions go up to
        2048; dense marching cubes at 2048 takes about a minute and 2-3 GB
        for a sphere. The adaptive mesher keeps to its memory budget (--memory,
        default 2048 MiB) and says when a resolution would exceed it; dense
        marching cubes has none. --threads: both methods' threads (default
        one per core).
)";
}

int benchCommand(const Args& args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << kBenchHelp;
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] == "accuracy") return benchAccuracyCommand(Args(args.begin() + 1, args.end()));
    if (args[0] != "eval") {
        std::cerr << "functionlab bench: unknown benchmark '" << args[0] << "'\n\n" << kBenchHelp;
        return kExitUsage;
    }
    bool json = false;
    double side = 64;
    double seconds = 0.2;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--json") {
            json = true;
        } else if ((args[i] == "--side" || args[i] == "--seconds") && i + 1 < args.size()) {
            // The whole argument must be a number ("12abc" is not 12).
            double& value = args[i] == "--side" ? side : seconds;
            if (!parseNumber(args[i + 1], value)) {
                std::cerr << "functionlab bench eval: " << args[i] << " needs a number, not '"
                          << args[i + 1] << "'\n";
                return kExitUsage;
            }
            ++i;
        } else {
            std::cerr << "functionlab bench eval: unexpected argument '" << args[i] << "'\n\n"
                      << kBenchHelp;
            return kExitUsage;
        }
    }
    if (side < 2 || side > 512 || side != std::floor(side) || !(seconds >= 0.0) || seconds > 60.0) {
        std::cerr << "functionlab bench eval: --side must be a whole number 2..512 and --seconds "
                     "0..60\n";
        return kExitUsage;
    }
    auto rows = bench::runEvalTable(static_cast<std::size_t>(side), seconds);
    std::cout << (json ? bench::evalTableJson(rows) : bench::formatEvalTable(rows));
    return kExitOk;
}

} // namespace fl::cli
