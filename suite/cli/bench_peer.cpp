#include "bench_peer.h"

#include "platform/exit_codes.h"

#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fl::cli {
std::filesystem::path selfDirectory() {
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return {};
    return std::filesystem::path(std::string(self, std::size_t(n))).parent_path();
}

int runBenchPeer(std::string_view benchmark, const Args& args) {
    const std::filesystem::path peer = selfDirectory() / "functionlab-bench";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(peer, ec) || ::access(peer.c_str(), X_OK) != 0) {
        std::cerr << "functionlab bench " << benchmark << ": the benchmark executable "
                  << peer.string()
                  << " is missing; build it with `cmake --build build --target "
                     "functionlab-bench` (it sits next to functionlab)\n";
        return kExitDiagnostic;
    }
    std::vector<std::string> all{peer.string(), std::string(benchmark)};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    std::cout.flush();
    ::execv(peer.c_str(), argv.data()); // returns only when it could not start
    std::cerr << "functionlab bench " << benchmark << ": cannot run " << peer.string() << "\n";
    return kExitDiagnostic;
}

} // namespace fl::cli
