#pragma once
// Benchmarks with peers the product never links (muParser, Draco,
// meshoptimizer) run in the sibling executable functionlab-bench (bench/),
// found next to functionlab: functionlab checks the command line, then
// hands it on; the output and exit status are the peer's.
#include "platform/option_table.h"

#include <filesystem>
#include <string_view>

namespace fl::cli {

// The directory of the running executable (its sibling programs live there).
std::filesystem::path selfDirectory();

// Runs `functionlab-bench BENCHMARK ARGS...` in place of this process;
// returns only when it cannot (with the reason said on stderr).
int runBenchPeer(std::string_view benchmark, const Args& args);

} // namespace fl::cli
