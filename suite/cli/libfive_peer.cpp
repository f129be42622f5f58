#include "cli/libfive_peer.h"

#include "cli/bench_peer.h"

#include <algorithm>
#include <cstdio>
#include <thread>
#include <unistd.h>

namespace fl::cli {

namespace fs = std::filesystem;

namespace {

fs::path peerProgram() {
    return selfDirectory() / "functionlab-libfive-peer";
}

} // namespace

bool libfivePeerBuilt(std::string& why) {
    const fs::path program = peerProgram();
    if (::access(program.c_str(), X_OK) == 0) return true;
    why = "the libfive peer " + program.string() +
          " is not built: clone https://github.com/libfive/libfive, install Debian's "
          "libboost-dev and libpng-dev, configure with -DFUNCTIONLAB_LIBFIVE_SOURCE=<the "
          "clone> and build the target functionlab-libfive-peer";
    return false;
}

std::optional<MeshPeerRow> runLibfivePeer(const field::ImplicitField& field,
                                          const std::string& formula,
                                          const formula::SetOperationMode& setOperations,
                                          double resolution, int threads, std::string& why) {
    if (threads <= 0) threads = std::max(1, int(std::thread::hardware_concurrency()));
    threads = std::min(threads, 1024); // the peer's own limit
    if (!libfivePeerBuilt(why)) return std::nullopt;
    std::error_code ec;
    const fs::path dir = peerScratchDirectory("libfive");
    const fs::path stlPath = dir / "mesh.stl";
    char numbers[512];
    std::snprintf(numbers, sizeof numbers, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %d 3",
                  field.box.lo[0], field.box.lo[1], field.box.lo[2], field.box.hi[0],
                  field.box.hi[1], field.box.hi[2], resolution, threads);
    char rfunctions[96] = "";
    if (setOperations.kind == formula::SetOperationMode::Kind::RFunction)
        std::snprintf(rfunctions, sizeof rfunctions, " %.17g %.17g", setOperations.m,
                      setOperations.alpha);
    const std::string output =
        runCapturing(shellQuoted(peerProgram().string()) + " " + shellQuoted(formula) + " " +
                     numbers + " " + shellQuoted(stlPath.string()) + rfunctions);
    const auto ms = jsonNumber(output, "ms");
    const auto used = jsonNumber(output, "resolution");
    std::string problem;
    const auto read = ms ? readBinaryStl(stlPath, problem) : std::nullopt;
    fs::remove_all(dir, ec);
    if (!ms || !used) {
        why = "the libfive peer failed: " + outputTail(output);
        return std::nullopt;
    }
    if (!read) {
        why = "the libfive peer's triangles cannot be read back: " + problem;
        return std::nullopt;
    }
    MeshPeerRow r;
    r.contourMs = *ms;
    r.row = measuredPeerRow(measure::Method::Libfive, *used, field, *read);
    r.row.milliseconds = *ms;
    return r;
}

} // namespace fl::cli
