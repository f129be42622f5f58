// The `functionlab` executable: with no arguments (or a scene file) it opens
// the suite window; with a subcommand it serves scripts, CI and instructors.
// The subcommands and their help come from one table (cli/commands.cpp).
#include "cli/commands.h"
#include "platform/exit_codes.h"
#include "platform/memory_policy.h"
#include "window/gui.h"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    fl::platform::keepFreedMemoryMapped(); // a re-mesh reuses the last one's pages
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) return fl::suite::runWindow(argc, argv, {});
    std::string joinError;
    if (const auto join = fl::suite::parseJoinArguments(args, joinError))
        return fl::suite::runWindow(argc, argv, {}, join);
    if (!joinError.empty()) {
        std::cerr << "functionlab: " << joinError << "\n";
        return fl::cli::kExitUsage;
    }
    if (args.size() == 1 && !fl::cli::isCommandWord(args[0]) &&
        fl::suite::looksLikeSceneFile(args[0]))
        return fl::suite::runWindow(argc, argv, args[0]);
    try {
        return fl::cli::runCommandLine(args, std::cout, std::cerr);
    } catch (const std::exception& e) {
        std::cerr << "functionlab: " << e.what() << "\n";
        return fl::cli::kExitDiagnostic;
    }
}
