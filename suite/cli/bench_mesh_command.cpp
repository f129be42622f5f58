// `functionlab bench mesh`: FunctionLab's meshers against a peer a graphics
// engineer would pick instead, in one run, at equal max error (issue 31 §3).
#include "cli/arguments.h"
#include "cli/bench_field.h"
#include "cli/commands.h"
#include "cli/vtk_peer.h"
#include "platform/exit_codes.h"

#include "formula/compiler.h"
#include "measure/accuracy_sweep.h"
#include "text/json_text.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& benchMeshSpec() {
    static const CommandSpec spec{
        .name = "bench mesh",
        .summary = "the meshers against a peer (VTK's Flying Edges) at equal max error",
        .synopsis = {"bench mesh FILE --peer vtk [--resolutions N,N,...] [--threads N] [--json]",
                     "bench mesh --formula \"SRC\" --box X0,Y0,Z0,X1,Y1,Z1 --peer vtk [options]"},
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
            "peer's log-log line between the rows that bracket it).\n",
        .positionals = {benchShapePositional()},
        .options = benchShapeOptions(
            {{.name = "peer",
              .kind = OptionKind::Text,
              .valueName = "NAME",
              .help = "the peer: vtk (python3-vtk9's vtkFlyingEdges3D)",
              .defaultValue = "vtk"},
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

int benchMeshCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchMeshSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    auto usage = [](const std::string& problem) {
        return usageError(benchMeshSpec(), problem, std::cerr);
    };
    if (a->text("peer", "vtk") != "vtk")
        return usage("the only peer here is vtk (libfive would need building from source, "
                     "which this project's machines cannot fetch)");
    const auto shape = benchShapeFromArgs(benchMeshSpec(), *a, exit);
    if (!shape) return exit;
    const field::ImplicitField& field = shape->field;
    const std::string& name = shape->name;
    const std::vector<double> resolutions =
        a->numbers("resolutions").value_or(std::vector<double>{64, 128, 256});
    measure::SweepOptions sweep;
    sweep.threads = int(a->integer("threads", 0));
    std::vector<std::string> skipped;
    std::vector<measure::AccuracyRow> rows =
        measure::runAccuracySweep(field, resolutions, sweep, &skipped);
    // One step finer for the peer, so that its rows bracket the adaptive
    // mesher's finest error (the peer's error at a resolution is dense's).
    std::vector<double> peerResolutions = resolutions;
    const double finest = *std::max_element(resolutions.begin(), resolutions.end());
    if (finest * 2 <= 1024) peerResolutions.push_back(finest * 2);
    std::vector<VtkPeerRow> peer;
    for (double r : peerResolutions) {
        std::string why;
        auto row = runVtkPeer(field, r, sweep.threads, why);
        if (!row) {
            std::cerr << "functionlab bench mesh: " << why << "\n";
            return kExitDiagnostic;
        }
        rows.push_back(row->row);
        peer.push_back(*row);
    }
    for (const std::string& s : skipped)
        std::cerr << "note: no row for " << s << "\n";
    if (a->flag("json")) {
        std::cout << measure::accuracyJson(rows);
        return kExitOk;
    }
    std::vector<measure::AccuracyRow> ours;
    for (const measure::AccuracyRow& r : rows)
        if (r.method != measure::Method::Vtk) ours.push_back(r);
    std::cout << "shape: " << name << "\n" << measure::accuracyTableText(ours);
    for (const VtkPeerRow& p : peer)
        std::printf("%-9s %10.4g %10zu %12zu %9.1f %11.3e %11.3e\n", "vtk", p.row.resolution,
                    p.row.triangles, p.row.evaluations, p.row.milliseconds, p.row.maxError,
                    p.row.meanError);
    for (const VtkPeerRow& p : peer)
        std::printf("vtk at %g: sampling %.1f ms + vtkFlyingEdges3D %.1f ms (%s)\n",
                    p.row.resolution, p.samplingMs, p.contourMs, p.backend.c_str());
    for (const measure::AccuracyRow& r : rows) {
        if (r.method != measure::Method::Adaptive) continue;
        const auto vtk = measure::timeAtError(rows, measure::Method::Vtk, r.maxError);
        if (vtk)
            std::printf("at %g (max error %.2e): adaptive %.1f ms, vtk %.1f ms at that error: "
                        "adaptive %.2fx as fast\n",
                        r.resolution, r.maxError, r.milliseconds, *vtk, *vtk / r.milliseconds);
        else
            std::printf("at %g (max error %.2e): adaptive %.1f ms; vtk reaches no such error in "
                        "these resolutions\n",
                        r.resolution, r.maxError, r.milliseconds);
    }
    return kExitOk;
}

} // namespace fl::cli
