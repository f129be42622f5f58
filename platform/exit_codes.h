#pragma once

namespace fl::cli {

// Exit codes shared by every subcommand.
enum ExitCode : int {
    kExitOk = 0,         // did what was asked (warnings allowed)
    kExitDiagnostic = 1, // the input has errors; diagnostics were printed
    kExitUsage = 2,      // the command line itself is wrong
};

} // namespace fl::cli
