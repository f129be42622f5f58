#pragma once
// What bench mesh's peers share (issue 31 §3): a peer is a program outside
// functionlab (VTK's vtkFlyingEdges3D under Debian's python3, libfive's dual
// contouring built from source) that meshes the same shape in the same box
// and writes its triangles as binary STL, with one line of JSON on stdout
// saying what it took. Nothing of a peer is linked into functionlab.
#include "field/field_sampler.h"
#include "measure/accuracy_sweep.h"
#include "mesh/mesh.h"

#include <filesystem>
#include <optional>
#include <string>

namespace fl::cli {

// Which peer; the kind of thing bench mesh branches on.
enum class MeshPeer { Vtk, Libfive };

struct MeshPeerRow {
    measure::AccuracyRow row; // milliseconds: what the peer took in all
    double samplingMs = 0;    // VTK: sampling the grid (least of three); libfive: 0
    double contourMs = 0;     // the peer's own time (least of its repeats)
    std::string backend;      // VTK's SMP backend ("TBB"); libfive: ""
};

// A private directory for one peer run's files, under the temporary directory.
std::filesystem::path peerScratchDirectory(const std::string& peer);

// `s` as one word for /bin/sh.
std::string shellQuoted(const std::string& s);

// Runs `command` (a program and its arguments, for /bin/sh) with stderr
// joined to stdout, stopped after `seconds` (coreutils' timeout: a peer that
// hangs does not hang the benchmark); returns what it printed (its last
// 64 KiB), with "(exit status N)", the signal that ended it or the timeout
// appended when it did not exit with 0.
std::string runCapturing(const std::string& command, int seconds = 900);

// The last `most` characters of a peer's output (what to show of its failure).
std::string outputTail(const std::string& output, std::size_t most = 400);

// The value of "key": NUMBER in a line of JSON.
std::optional<double> jsonNumber(const std::string& text, const std::string& key);

// A peer's row of `method` at `resolution`: its triangles counted and their
// error measured against `field` by the same code as every other mesh's
// (evaluations and time are the caller's to fill).
measure::AccuracyRow measuredPeerRow(measure::Method method, double resolution,
                                     const field::ImplicitField& field,
                                     const mesh::Mesh& triangles);

// A binary STL file's triangles, each with its own three corners (the error
// measure needs them unwelded only); none with `problem` when the file is
// short, long or not STL.
std::optional<mesh::Mesh> readBinaryStl(const std::filesystem::path& path, std::string& problem);

} // namespace fl::cli
