#pragma once
// The options of `functionlab bench pde`: the contract between functionlab,
// which checks the command line and shows the help, and functionlab-bench
// (bench/), which runs the comparison with peers the product never links
// (Draco, meshoptimizer) and reads the same options.
#include "platform/option_table.h"

namespace fl::measure {

const cli::CommandSpec& benchPdeSpec();

} // namespace fl::measure
