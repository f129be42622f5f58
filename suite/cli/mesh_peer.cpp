#include "cli/mesh_peer.h"

#include "mesh/mesh_error.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sys/wait.h>
#include <unistd.h>

namespace fl::cli {

namespace fs = std::filesystem;

fs::path peerScratchDirectory(const std::string& peer) {
    std::error_code ec;
    const fs::path dir =
        fs::temp_directory_path(ec) / ("functionlab-" + peer + "-" + std::to_string(::getpid()));
    fs::create_directories(dir, ec);
    return dir;
}

std::string shellQuoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string runCapturing(const std::string& command, int seconds) {
    constexpr std::size_t kKept = 64 * 1024;
    std::string output;
    const std::string line = "timeout -k 10 " + std::to_string(seconds) + " " + command + " 2>&1";
    const auto started = std::chrono::steady_clock::now();
    if (FILE* p = ::popen(line.c_str(), "r")) {
        char buf[4096];
        while (std::fgets(buf, sizeof buf, p)) {
            output += buf;
            if (output.size() > 2 * kKept) output.erase(0, output.size() - kKept);
        }
        const int status = ::pclose(p);
        if (output.size() > kKept) output.erase(0, output.size() - kKept);
        if (status != 0) {
            // timeout says 124 when it stopped the command, 137 when it had
            // to kill it; a command ended by a signal reads as 128 + signal.
            const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            const bool late =
                std::chrono::steady_clock::now() - started >= std::chrono::seconds(seconds);
            output += code == 124 || (code == 137 && late)
                          ? "\n(no answer within " + std::to_string(seconds) + " s: stopped)"
                      : code > 128 ? "\n(ended by signal " + std::to_string(code - 128) + ")"
                                   : "\n(exit status " + std::to_string(code) + ")";
        }
    } else {
        output = "cannot start /bin/sh";
    }
    return output;
}

std::string outputTail(const std::string& output, std::size_t most) {
    return output.size() > most ? output.substr(output.size() - most) : output;
}

std::optional<double> jsonNumber(const std::string& text, const std::string& key) {
    const std::regex re("\"" + key + "\":\\s*([-+0-9.eE]+)");
    std::smatch m;
    if (!std::regex_search(text, m, re)) return std::nullopt;
    return std::strtod(m[1].str().c_str(), nullptr);
}

measure::AccuracyRow measuredPeerRow(measure::Method method, double resolution,
                                     const field::ImplicitField& field,
                                     const mesh::Mesh& triangles) {
    measure::AccuracyRow row;
    row.method = method;
    row.resolution = resolution;
    row.triangles = triangles.triangleCount();
    const mesh::SurfaceError e = mesh::measureSurfaceError(field, triangles);
    row.maxError = e.max;
    row.meanError = e.mean;
    return row;
}

std::optional<mesh::Mesh> readBinaryStl(const fs::path& path, std::string& problem) {
    std::ifstream in(path, std::ios::binary);
    char header[80];
    std::uint32_t count = 0;
    if (!in.read(header, sizeof header) ||
        !in.read(reinterpret_cast<char*>(&count), sizeof count)) {
        problem = path.string() + " is not binary STL";
        return std::nullopt;
    }
    std::error_code ec;
    if (fs::file_size(path, ec) != 84 + std::uintmax_t(count) * 50) {
        problem = path.string() + " does not hold the " + std::to_string(count) +
                  " triangles it announces";
        return std::nullopt;
    }
    mesh::Mesh m;
    m.positions.reserve(std::size_t(count) * 3);
    m.triangles.reserve(count);
    char record[50];
    for (std::uint32_t t = 0; t < count && in.read(record, sizeof record); ++t) {
        for (int v = 0; v < 3; ++v) {
            mesh::Vec3f p;
            std::memcpy(p.data(), record + 12 + 12 * v, 12);
            m.positions.push_back(p);
        }
        m.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    return m;
}

} // namespace fl::cli
