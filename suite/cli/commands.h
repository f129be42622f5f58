#pragma once
// Subcommands of the `functionlab` executable. Each takes the arguments after
// its own name and returns an exit code (see exit_codes.h).
#include <string>
#include <vector>

namespace fl::cli {

using Args = std::vector<std::string>;

int formulaCommand(const Args& args);
int benchCommand(const Args& args);
int checkCommand(const Args& args);
int convertCommand(const Args& args);
int meshCommand(const Args& args);
int renderCommand(const Args& args);
int benchAccuracyCommand(const Args& args); // `bench accuracy`

} // namespace fl::cli
