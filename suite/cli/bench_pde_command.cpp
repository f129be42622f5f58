// `functionlab bench pde`: PDE models against Draco and simplification +
// Draco (bench/pde_table), peers the product does not link: it runs in the
// sibling executable functionlab-bench, which reads the same options
// (measure/bench_pde_spec.h).
#include "cli/bench_peer.h"
#include "cli/commands.h"
#include "measure/bench_pde_spec.h"

#include <iostream>

namespace fl::cli {

int benchPdeCommand(const Args& args) {
    int exit = 0;
    if (!parseOrExplain(measure::benchPdeSpec(), args, exit, std::cout, std::cerr)) return exit;
    return runBenchPeer("pde", args);
}

} // namespace fl::cli
