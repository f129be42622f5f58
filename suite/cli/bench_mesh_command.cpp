// `functionlab bench mesh`: FunctionLab's meshers against a peer a graphics
// engineer would pick instead, in one run, at equal max error (issue 31 §3).
#include "cli/arguments.h"
#include "cli/bench_field.h"
#include "cli/commands.h"
#include "cli/libfive_peer.h"
#include "cli/vtk_peer.h"
#include "platform/exit_codes.h"

#include "formula/compiler.h"
#include "measure/accuracy_sweep.h"
#include "text/json_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& benchMeshSpec() {
    static const CommandSpec spec{
        .name = "bench mesh",
        .summary = "the meshers against a peer (VTK's Flying Edges, libfive) at equal max error",
        .synopsis = {"bench mesh FILE [--peer vtk|libfive] [--resolutions N,N,...] [--threads N] "
                     "[--json]",
                     "bench mesh --formula \"SRC\" --box X0,Y0,Z0,X1,Y1,Z1 [--peer vtk|libfive] "
                     "[options]"},
        .description =
            "Meshes one shape — the first implicit or explicit FShape of the scene FILE, or\n"
            "a formula over a box — at each resolution with the adaptive mesher, dense\n"
            "marching cubes and the peer, and measures every mesh with the same code (max\n"
            "and mean of |f|/|grad f| on triangle interiors, fractions of the diagonal).\n"
            "The peer `vtk` is what a VTK user does: the formula sampled into the dense\n"
            "grid (same box, same cells; by FunctionLab's own evaluator, the fastest there\n"
            "is, timed) and contoured by vtkFlyingEdges3D with VTK's defaults on its SMP\n"
            "backend (Debian's python3-vtk9, run as a separate process: functionlab links\n"
            "nothing of VTK); its time is sampling plus contouring, each the least of three.\n"
            "The peer also runs at twice the finest resolution, so that its rows bracket\n"
            "the adaptive mesher's finest error. After the table, each resolution's\n"
            "adaptive time against the peer's time at the same max error (read off the\n"
            "peer's log-log line between the rows that bracket it).\n"
            "The peer `libfive` is libfive's dual contouring (github.com/libfive/libfive,\n"
            "not in Debian: built from a source tree given to CMake as\n"
            "FUNCTIONLAB_LIBFIVE_SOURCE, into the program functionlab-libfive-peer next to\n"
            "functionlab), the formula rebuilt in libfive's operations, its defaults but for\n"
            "the threads and the cell size: libfive's octree halves the box, so it meshes at\n"
            "the least power of two at or above each resolution. Its time is the least of\n"
            "three renders. After the table, each resolution's adaptive time against\n"
            "libfive's at that resolution and, where its rows bracket it, at the same max\n"
            "error. A scene FILE's shape is given to libfive as its definition's text.\n",
        .positionals = {benchShapePositional()},
        .options = benchShapeOptions(
            {{.name = "peer",
              .kind = OptionKind::Choice,
              .valueName = "NAME",
              .help = "the peer: vtk (python3-vtk9's vtkFlyingEdges3D) or libfive (built from "
                      "source)",
              .defaultValue = "vtk",
              .choices = {"vtk", "libfive"}},
             {.name = "resolutions",
              .kind = OptionKind::NumberList,
              .valueName = "N,N,...",
              .help = "the resolutions, each 1 to 1024",
              .defaultValue = "64,128,256",
              .min = 1,
              .max = 1024},
             {.name = "threads",
              .kind = OptionKind::Integer,
              .valueName = "N",
              .help = "every method's threads (0: one per core)",
              .defaultValue = "0",
              .min = 0,
              .max = 256},
             {.name = "json",
              .help = "print a list of {\"method\", \"resolution\", \"triangles\", "
                      "\"evaluations\", \"ms\", \"max_error\", \"mean_error\"}"}}),
        .exitStatus = "0 measured, 1 the input has errors or the peer cannot run, 2 usage error",
    };
    return spec;
}

namespace {

// The option's value is one of its choices (checked by the option table).
MeshPeer peerNamed(const std::string& name) {
    return name == "libfive" ? MeshPeer::Libfive : MeshPeer::Vtk;
}

measure::Method peerMethod(MeshPeer peer) {
    switch (peer) {
    case MeshPeer::Vtk:
        return measure::Method::Vtk;
    case MeshPeer::Libfive:
        return measure::Method::Libfive;
    }
    return measure::Method::Vtk;
}

// The peer's resolutions: VTK's error at a resolution is dense marching
// cubes', so it runs one step finer too, for its rows to bracket the adaptive
// mesher's finest error; libfive's is the adaptive mesher's kind, so the
// same ones, each raised to a power of two (its octree halves the box), once.
std::vector<double> peerResolutions(MeshPeer peer, std::vector<double> resolutions) {
    const double finest = *std::max_element(resolutions.begin(), resolutions.end());
    if (peer == MeshPeer::Vtk && finest * 2 <= 1024) resolutions.push_back(finest * 2);
    if (peer == MeshPeer::Libfive) {
        for (double& r : resolutions)
            r = std::ldexp(1.0, int(std::ceil(std::log2(r) - 1e-9)));
        std::sort(resolutions.begin(), resolutions.end());
        resolutions.erase(std::unique(resolutions.begin(), resolutions.end()), resolutions.end());
    }
    return resolutions;
}

std::optional<MeshPeerRow> runPeer(MeshPeer peer, const BenchShape& shape, double resolution,
                                   int threads, std::string& why) {
    switch (peer) {
    case MeshPeer::Vtk:
        return runVtkPeer(shape.field, resolution, threads, why);
    case MeshPeer::Libfive:
        return runLibfivePeer(shape.field, shape.source, shape.setOperations, resolution, threads,
                              why);
    }
    return std::nullopt;
}

void printPeerDetails(MeshPeer peer, const std::vector<MeshPeerRow>& rows) {
    for (const MeshPeerRow& p : rows) {
        if (peer == MeshPeer::Vtk)
            std::printf("vtk at %g: sampling %.1f ms + vtkFlyingEdges3D %.1f ms (%s)\n",
                        p.row.resolution, p.samplingMs, p.contourMs, p.backend.c_str());
    }
}

// Each adaptive row against the peer: at the same resolution (libfive, whose
// mesher is of the same kind; its power of two at or above) and at the same
// max error (both peers).
void printComparison(MeshPeer peer, const std::vector<measure::AccuracyRow>& rows) {
    const measure::Method method = peerMethod(peer);
    const char* name = measure::methodName(method);
    for (const measure::AccuracyRow& r : rows) {
        if (r.method != measure::Method::Adaptive) continue;
        std::printf("at %g (max error %.2e): adaptive %.1f ms", r.resolution, r.maxError,
                    r.milliseconds);
        if (peer == MeshPeer::Libfive) {
            // libfive's row for this resolution: the least power of two at or above it
            const measure::AccuracyRow* same = nullptr;
            for (const measure::AccuracyRow& p : rows)
                if (p.method == method && p.resolution >= r.resolution &&
                    (!same || p.resolution < same->resolution))
                    same = &p;
            if (same)
                std::printf("; %s at %g %.1f ms, %zu triangles against %zu, max error %.2e: "
                            "adaptive %.2fx as fast",
                            name, same->resolution, same->milliseconds, same->triangles,
                            r.triangles, same->maxError, same->milliseconds / r.milliseconds);
        }
        if (const auto t = measure::timeAtError(rows, method, r.maxError))
            std::printf("; %s %.1f ms at that error: adaptive %.2fx as fast\n", name, *t,
                        *t / r.milliseconds);
        else
            std::printf("; %s reaches no such error in these resolutions\n", name);
    }
}

} // namespace

int benchMeshCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchMeshSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const MeshPeer peer = peerNamed(a->text("peer", "vtk"));
    const auto shape = benchShapeFromArgs(benchMeshSpec(), *a, exit);
    if (!shape) return exit;
    if (std::string why; peer == MeshPeer::Libfive && !libfivePeerBuilt(why)) {
        std::cerr << "functionlab bench mesh: " << why << "\n"; // before the sweep, not after
        return kExitDiagnostic;
    }
    const std::vector<double> resolutions =
        a->numbers("resolutions").value_or(std::vector<double>{64, 128, 256});
    measure::SweepOptions sweep;
    sweep.threads = int(a->integer("threads", 0));
    std::vector<std::string> skipped;
    std::vector<measure::AccuracyRow> rows =
        measure::runAccuracySweep(shape->field, resolutions, sweep, &skipped);
    std::vector<MeshPeerRow> peerRows;
    for (double r : peerResolutions(peer, resolutions)) {
        std::string why;
        auto row = runPeer(peer, *shape, r, sweep.threads, why);
        if (!row) {
            std::cerr << "functionlab bench mesh: " << why << "\n";
            return kExitDiagnostic;
        }
        rows.push_back(row->row);
        peerRows.push_back(*row);
    }
    for (const std::string& s : skipped)
        std::cerr << "note: no row for " << s << "\n";
    if (a->flag("json")) {
        std::cout << measure::accuracyJson(rows);
        return kExitOk;
    }
    std::vector<measure::AccuracyRow> ours;
    for (const measure::AccuracyRow& r : rows)
        if (r.method != peerMethod(peer)) ours.push_back(r);
    std::cout << "shape: " << shape->name << "\n" << measure::accuracyTableText(ours);
    for (const MeshPeerRow& p : peerRows)
        std::printf("%-9s %10.4g %10zu %12zu %9.1f %11.3e %11.3e\n",
                    measure::methodName(p.row.method), p.row.resolution, p.row.triangles,
                    p.row.evaluations, p.row.milliseconds, p.row.maxError, p.row.meanError);
    printPeerDetails(peer, peerRows);
    printComparison(peer, rows);
    return kExitOk;
}

} // namespace fl::cli
