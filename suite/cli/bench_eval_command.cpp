// `functionlab bench eval`: the evaluator benchmark table (bench/eval_table).
// It compares with muParser, a peer the product does not link: the table runs
// in the sibling executable functionlab-bench (bench/functionlab_bench.cpp),
// which reads the same options from this file's spec. functionlab checks the
// command line, then hands it on; the output and exit status are the peer's.
#include "cli/commands.h"
#include "cli/exit_codes.h"

#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace fl::cli {

const CommandSpec& benchEvalSpec() {
    static const CommandSpec spec{
        .name = "bench eval",
        .summary = "evaluator speed: FunctionLab vs hand-written C++ vs muParser",
        .synopsis = {"bench eval [--json] [--side N] [--seconds S]"},
        .description =
            "Evaluates the benchmark formulas over an N^3 grid with FunctionLab's batch\n"
            "evaluator, the same formulas hand-written in C++, and muParser, all on one\n"
            "thread; prints nanoseconds per point and the ratios. The engines take turns\n"
            "for at least S seconds and each reports its best turn. The work is done by\n"
            "the executable functionlab-bench next to functionlab.\n",
        .options = {{.name = "json",
                     .help = "print a list of {\"formula\", \"ns_per_point\": {\"functionlab\", "
                             "\"native\", \"muparser\"}} instead of the table"},
                    {.name = "side",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "points along each side of the grid",
                     .defaultValue = "64",
                     .min = 2,
                     .max = 512},
                    {.name = "seconds",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "how long the engines take turns, at least",
                     .defaultValue = "0.2",
                     .min = 0,
                     .max = 60}},
        .exitStatus = "0 measured, 1 functionlab-bench is missing or failed, 2 usage error",
    };
    return spec;
}

namespace {

// The directory of the running executable.
std::filesystem::path selfDirectory() {
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return {};
    return std::filesystem::path(std::string(self, std::size_t(n))).parent_path();
}

} // namespace

int benchEvalCommand(const Args& args) {
    int exit = 0;
    if (!parseOrExplain(benchEvalSpec(), args, exit, std::cout, std::cerr)) return exit;
    const std::filesystem::path peer = selfDirectory() / "functionlab-bench";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(peer, ec) || ::access(peer.c_str(), X_OK) != 0) {
        std::cerr << "functionlab bench eval: the benchmark executable " << peer.string()
                  << " is missing; build it with `cmake --build build --target "
                     "functionlab-bench` (it sits next to functionlab)\n";
        return kExitDiagnostic;
    }
    std::vector<std::string> all{peer.string(), "eval"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    std::cout.flush();
    ::execv(peer.c_str(), argv.data()); // returns only when it could not start
    std::cerr << "functionlab bench eval: cannot run " << peer.string() << "\n";
    return kExitDiagnostic;
}

} // namespace fl::cli
