#include "cli/vtk_peer.h"

#include "parallel/work_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fl::cli {
namespace {

namespace fs = std::filesystem;

std::string python() {
    if (const char* p = std::getenv("FUNCTIONLAB_PYTHON"); p && *p) return p;
    // Debian's interpreter: python3-vtk9 is installed for it (a python3 of
    // pyenv or a virtual environment first on PATH would not see it).
    std::error_code ec;
    return fs::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
}

} // namespace

std::optional<MeshPeerRow> runVtkPeer(const field::ImplicitField& field, double resolution,
                                      int threads, std::string& why) {
    if (threads <= 0) threads = std::max(1, int(std::thread::hardware_concurrency()));
    // Dense marching cubes' grid: cells of the same size along every axis.
    const double longest = std::max({field.box.size(0), field.box.size(1), field.box.size(2)});
    int n[3];
    double h[3];
    for (int a = 0; a < 3; ++a) {
        n[a] = std::max(1, int(std::lround(resolution * field.box.size(a) / longest)));
        h[a] = field.box.size(a) / n[a];
    }
    const std::size_t row = std::size_t(n[0] + 1), plane = row * std::size_t(n[1] + 1);
    const std::size_t points = plane * std::size_t(n[2] + 1);
    std::vector<float> grid(points);
    double samplingMs = 1e300;
    for (int repeat = 0; repeat < 3; ++repeat) {
        std::atomic<int> next{0};
        const auto started = std::chrono::steady_clock::now();
        const std::function<void(int)> sample = [&](int) {
            field::FieldSampler sampler(field);
            std::vector<double> xs(plane), ys(plane), zs(plane), out(plane);
            for (std::size_t j = 0; j <= std::size_t(n[1]); ++j)
                for (std::size_t i = 0; i <= std::size_t(n[0]); ++i) {
                    xs[j * row + i] = field.box.lo[0] + double(i) * h[0];
                    ys[j * row + i] = field.box.lo[1] + double(j) * h[1];
                }
            for (int k = next++; k <= n[2]; k = next++) {
                std::fill(zs.begin(), zs.end(), field.box.lo[2] + k * h[2]);
                sampler.values(xs.data(), ys.data(), zs.data(), plane, out.data());
                float* to = grid.data() + std::size_t(k) * plane;
                for (std::size_t p = 0; p < plane; ++p)
                    to[p] = float(out[p]);
            }
        };
        parallel::WorkPool::shared().run(threads, sample);
        samplingMs = std::min(samplingMs, std::chrono::duration<double, std::milli>(
                                              std::chrono::steady_clock::now() - started)
                                              .count());
    }

    std::error_code ec;
    const fs::path dir = peerScratchDirectory("vtk");
    const fs::path rawPath = dir / "grid.raw", stlPath = dir / "mesh.stl";
    {
        std::ofstream raw(rawPath, std::ios::binary);
        raw.write(reinterpret_cast<const char*>(grid.data()),
                  std::streamsize(grid.size() * sizeof(float)));
        if (!raw) {
            why = "cannot write the grid to " + rawPath.string();
            fs::remove_all(dir, ec);
            return std::nullopt;
        }
    }
    char numbers[512];
    std::snprintf(numbers, sizeof numbers, "%d %d %d %.17g %.17g %.17g %.17g %.17g %.17g %d 3",
                  n[0] + 1, n[1] + 1, n[2] + 1, field.box.lo[0], field.box.lo[1], field.box.lo[2],
                  h[0], h[1], h[2], threads);
    const std::string command =
        shellQuoted(python()) + " " + shellQuoted(FUNCTIONLAB_VTK_PEER_SCRIPT) + " " +
        shellQuoted(rawPath.string()) + " " + numbers + " " + shellQuoted(stlPath.string());
    const std::string output = runCapturing(command);
    const auto ms = jsonNumber(output, "ms");
    std::string problem;
    const auto read = ms ? readBinaryStl(stlPath, problem) : std::nullopt;
    fs::remove_all(dir, ec);
    if (!ms) {
        why = "the VTK peer needs Debian's python3-vtk9 (apt-get install python3-vtk9): " +
              outputTail(output);
        return std::nullopt;
    }
    if (!read) {
        why = "the VTK peer's triangles cannot be read back: " + problem;
        return std::nullopt;
    }
    MeshPeerRow r;
    r.samplingMs = samplingMs;
    r.contourMs = *ms;
    std::smatch m;
    if (std::regex_search(output, m, std::regex("\"backend\":\\s*\"([A-Za-z]+)\"")))
        r.backend = m[1].str();
    r.row = measuredPeerRow(measure::Method::Vtk, resolution, field, *read);
    r.row.evaluations = points;
    r.row.milliseconds = samplingMs + *ms;
    return r;
}

} // namespace fl::cli
