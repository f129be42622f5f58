#pragma once
// The options of `functionlab bench eval`: the contract between functionlab,
// which checks the command line and shows the help, and the benchmark
// executable functionlab-bench (bench/), which runs the table with a peer
// the product never links (muParser) and reads the same options.
#include "platform/option_table.h"

namespace fl::measure {

const cli::CommandSpec& benchEvalSpec();

} // namespace fl::measure
