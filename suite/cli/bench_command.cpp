// `functionlab bench eval`: the evaluator benchmark table (bench/eval_table).
#include "commands.h"
#include "exit_codes.h"

#include "eval_table.h"

#include <cstdlib>
#include <iostream>

namespace fl::cli {

namespace {
const char* kBenchHelp = R"(usage: functionlab bench eval [--json] [--side N] [--seconds S]

eval    evaluates the benchmark formulas over an N^3 grid (default 64) with
        FunctionLab's batch evaluator, the same formulas hand-written in C++,
        and muParser, all on one thread; prints nanoseconds per point and the
        ratios. The engines take turns for at least S seconds (default 0.2)
        and each reports its best turn.
        --json prints a list of {"formula", "ns_per_point": {"functionlab",
        "native", "muparser"}}.
)";
}

int benchCommand(const Args& args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::cout << kBenchHelp;
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] != "eval") {
        std::cerr << "functionlab bench: unknown benchmark '" << args[0] << "'\n\n" << kBenchHelp;
        return kExitUsage;
    }
    bool json = false;
    long side = 64;
    double seconds = 0.2;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--json")
            json = true;
        else if (args[i] == "--side" && i + 1 < args.size())
            side = std::strtol(args[++i].c_str(), nullptr, 10);
        else if (args[i] == "--seconds" && i + 1 < args.size())
            seconds = std::strtod(args[++i].c_str(), nullptr);
        else {
            std::cerr << "functionlab bench eval: unexpected argument '" << args[i] << "'\n\n"
                      << kBenchHelp;
            return kExitUsage;
        }
    }
    if (side < 2 || side > 512 || !(seconds >= 0.0) || seconds > 60.0) {
        std::cerr << "functionlab bench eval: --side must be 2..512 and --seconds 0..60\n";
        return kExitUsage;
    }
    auto rows = bench::runEvalTable(static_cast<std::size_t>(side), seconds);
    std::cout << (json ? bench::evalTableJson(rows) : bench::formatEvalTable(rows));
    return kExitOk;
}

} // namespace fl::cli
