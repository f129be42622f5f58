// `functionlab bench eval`: the evaluator benchmark table (bench/eval_table).
// It compares with muParser, a peer the product does not link: the table runs
// in the sibling executable functionlab-bench (bench/functionlab_bench.cpp),
// which reads the same options (measure/bench_eval_spec.h).
#include "cli/bench_peer.h"
#include "cli/commands.h"
#include "measure/bench_eval_spec.h"

#include <iostream>

namespace fl::cli {

int benchEvalCommand(const Args& args) {
    int exit = 0;
    if (!parseOrExplain(benchEvalSpec(), args, exit, std::cout, std::cerr)) return exit;
    return runBenchPeer("eval", args);
}

} // namespace fl::cli
