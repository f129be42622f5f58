// `functionlab pde fit MESH.obj -o MODEL.pde`: a polygon mesh as a few PDE
// patches (the paper's Section 4; docs/pde.md), with the figures that say
// what the model costs and how close it is.
#include "cli/commands.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "mesh/mesh_export.h"
#include "mesh/obj_reader.h"
#include "pde/fit_measure.h"
#include "pde/mesh_fit.h"
#include "pde/pde_scene.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>

namespace fl::cli {
namespace {

// A scene file from `text(classic)`, X3D XML or ClassicVRML by its name.
bool writeScene(const std::string& path, const char* option,
                const std::function<std::string(bool classic)>& text, std::string& why) {
    const bool classic = path.size() > 5 && path.compare(path.size() - 5, 5, ".x3dv") == 0;
    if (!classic && !(path.size() > 4 && path.compare(path.size() - 4, 4, ".x3d") == 0)) {
        why = path + ": " + option + " writes a scene: name it .x3d or .x3dv";
        return false;
    }
    return mesh::writeFileReplacing(path, text(classic), why);
}

} // namespace

const CommandSpec& pdeFitSpec() {
    static const CommandSpec spec{
        .name = "pde fit",
        .summary = "a polygon mesh (.obj) as a few PDE patches (.pde)",
        .synopsis = {"pde fit MESH.obj -o MODEL.pde [--patches N | --error E] [--radii N]\n"
                     "[--smoothing A] [--method points|curves] [--bits B] [--text | --formula K]\n"
                     "[--scene S] [--json]"},
        .description =
            "Cuts the mesh into disk-like regions and fits each with a Bloor-Wilson PDE\n"
            "patch (a cubic spine and N Fourier radii, the u = 0 curve a point), splitting\n"
            "the region the fit misses most until --patches N patches, or until the fit's RMS\n"
            "miss is at most E of the bounding-box diagonal (--error, default 0.003). A mesh\n"
            "of one part shaped like a sphere or a tube is also tried as up to 8 bands across\n"
            "its long axis - caps at its ends, tubes (both ends open curves) between - and\n"
            "kept when that takes fewer patches or misses less. Writes\n"
            "the model to MODEL.pde (binary, coefficients rounded to the diagonal / 2^B), or\n"
            "as text with --text. Then meshes the model and measures it against the mesh:\n"
            "RMS and symmetric Hausdorff distance, exact point-to-triangle, 10^5 samples each\n"
            "way. `functionlab mesh MODEL.pde -o OUT.obj` meshes a model for other tools.\n",
        .positionals = {{.name = "MESH", .help = "the polygon mesh (Wavefront OBJ)"}},
        .options = {{.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "MODEL",
                     .help = "the .pde file to write (required)"},
                    {.name = "patches",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "fit exactly N patches (more when the mesh has more parts than N)",
                     .min = 1,
                     .max = 100000},
                    {.name = "error",
                     .kind = OptionKind::Number,
                     .valueName = "E",
                     .help = "the RMS miss to reach, a fraction of the box diagonal",
                     .defaultValue = "0.003",
                     .min = 0,
                     .minExclusive = true},
                    {.name = "radii",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "the most Fourier radii a patch may have (with --error: 6, 8, 10 ... "
                             "are tried in turn, up to N; with --patches: N)",
                     .defaultValue = "12",
                     .min = 1,
                     .max = 32},
                    {.name = "max-patches",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "stop splitting at N patches when --error is not reached",
                     .defaultValue = "2000",
                     .min = 1,
                     .max = 100000},
                    {.name = "bits",
                     .kind = OptionKind::Integer,
                     .valueName = "B",
                     .help = "coefficients are rounded to the diagonal / 2^B",
                     .defaultValue = "12",
                     .min = 4,
                     .max = 32},
                    {.name = "smoothing",
                     .kind = OptionKind::Number,
                     .valueName = "A",
                     .help = "the PDE's a: the relative rate of smoothing along u and v (the paper "
                             "takes a >= 1; smaller is nearer a cubic along u; bands take the best "
                             "of A/4, A/2 and A each)",
                     .defaultValue = "1",
                     .min = 0.05,
                     .max = 8},
                    {.name = "method",
                     .kind = OptionKind::Choice,
                     .valueName = "M",
                     .help = "points: least squares to every point of each region (with parameter "
                             "correction); curves: the paper's method, the patch through four "
                             "curves read off each region (for comparison)",
                     .defaultValue = "points",
                     .choices = {"points", "curves"}},
                    {.name = "text", .help = "write the readable text form instead of binary"},
                    {.name = "scene",
                     .kind = OptionKind::Path,
                     .valueName = "S",
                     .help = "also write a scene S (.x3d or .x3dv) that shows the model and "
                             "carries it in a data: url, so it stands alone (a class scene may "
                             "name no file)"},
                    {.name = "formula",
                     .kind = OptionKind::Integer,
                     .valueName = "K",
                     .help = "write patch K (from 0) as a parametric FGeometry in a scene (-o "
                             "OUT.x3d or .x3dv) instead of the model: a PDE patch is a "
                             "parametric function of u and v",
                     .min = 0},
                    {.name = "json", .help = "print the figures as one JSON object on stdout"}},
        .notes = "Refused with a located message (exit 1): a file that is not an OBJ mesh, no\n"
                 "faces, coordinates that are not finite, an edge with more than two faces,\n"
                 "faces wound both ways, a file over 256 MiB. Holes and several parts are fitted\n"
                 "(each part and each hole's rim has its own patches). When --error cannot be\n"
                 "reached within --max-patches, the model is still written and the reached error\n"
                 "is said (exit 1).\n",
        .exitStatus = "0 written, 1 the mesh could not be read or fitted (or the error was not "
                      "reached), 2 usage error",
    };
    return spec;
}

int pdeFitCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(pdeFitSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::string out = a->text("output");
    if (out.empty())
        return usageError(pdeFitSpec(), "say where the model goes: -o MODEL.pde", std::cerr);
    const std::string input = a->positional("MESH");
    const auto started = std::chrono::steady_clock::now();
    const mesh::ObjReadResult read = mesh::readObjFile(input);
    if (!read.ok()) {
        std::cerr << read.error << "\n";
        return kExitDiagnostic;
    }
    pde::MeshFitOptions o;
    o.patches = std::size_t(a->number("patches", 0));
    o.error = a->number("error", 0.003);
    o.radii = std::size_t(a->number("radii", 12));
    o.maxPatches = std::size_t(a->number("max-patches", 2000));
    o.a = a->number("smoothing", 1);
    o.method = a->text("method", "points") == "curves" ? pde::FitMethod::BoundaryCurves
                                                       : pde::FitMethod::Points;
    const bool terminal = isatty(STDERR_FILENO);
    if (terminal)
        o.progress = [&](std::size_t patches, double rms) {
            const std::size_t goal = o.patches ? o.patches : o.maxPatches;
            const int filled = int(30.0 * double(patches) / double(goal));
            std::fprintf(stderr, "\r[%-30s] %zu patches, RMS miss %.2e of the diagonal",
                         std::string(std::size_t(std::min(filled, 30)), '#').c_str(), patches, rms);
        };
    std::string why;
    const auto fit = pde::fitMesh(*read.mesh, o, &why, &read.triangleLines);
    if (terminal) std::fprintf(stderr, "\n");
    if (!fit) {
        std::cerr << input << ": " << why << "\n";
        return kExitDiagnostic;
    }
    const double fitMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    if (a->given("formula")) {
        const auto k = std::size_t(a->number("formula", 0));
        if (k >= fit->model.patches.size()) {
            std::cerr << input << ": there is no patch " << k << " (the model has "
                      << fit->model.patches.size() << ", numbered from 0)\n";
            return kExitDiagnostic;
        }
        if (!writeScene(
                out, "--formula",
                [&](bool classic) { return pde::patchScene(fit->model, k, classic); }, why)) {
            std::cerr << why << "\n";
            return kExitDiagnostic;
        }
        std::cerr << out << ": patch " << k << " of " << fit->model.patches.size() << " ("
                  << fit->model.patches[k].radii() << " radii) as a parametric FGeometry\n";
        return kExitOk;
    }
    // Measured as any tool would: the model encoded, read back, meshed,
    // compared; those bytes are the file.
    const pde::EncodeOptions eo{int(a->number("bits", 12))};
    const bool text = a->flag("text");
    const auto measured = pde::measureFit(*read.mesh, fit->model, {text, eo}, &why);
    if (!measured) {
        std::cerr << out << ": " << why << "\n";
        return kExitDiagnostic;
    }
    if (!mesh::writeFileReplacing(out, measured->bytes, why)) {
        std::cerr << why << "\n";
        return kExitDiagnostic;
    }
    if (const std::string scene = a->text("scene"); !scene.empty()) {
        if (!writeScene(
                scene, "--scene",
                [&](bool classic) { return pde::carryingScene(fit->model, eo, classic); }, why)) {
            std::cerr << why << "\n";
            return kExitDiagnostic;
        }
        std::cerr << scene << ": a scene that carries the model in a data: url\n";
    }
    const std::size_t radii = fit->model.maxRadii();
    if (a->flag("json")) {
        // The mesh's path is the user's text: escaped like every JSON string.
        std::cout << "{\"mesh\": " << jsonString(input)
                  << ", \"vertices\": " << read.mesh->vertexCount()
                  << ", \"faces\": " << read.mesh->triangleCount()
                  << ", \"patches\": " << fit->model.patches.size()
                  << ", \"method\": " << jsonString(a->text("method", "points"))
                  << ", \"max_radii\": " << radii
                  << ", \"coefficients\": " << fit->model.coefficientCount()
                  << ", \"bytes\": " << measured->bytes.size() << ", \"bits\": " << eo.bits
                  << ", \"fit_ms\": " << jsonNumber(fitMs)
                  << ", \"fit_rms\": " << jsonNumber(fit->rms)
                  << ", \"rms\": " << jsonNumber(measured->rms())
                  << ", \"hausdorff\": " << jsonNumber(measured->hausdorff())
                  << ", \"samples\": " << measured->distance.samples
                  << ", \"reached\": " << (fit->reached ? "true" : "false") << "}\n";
    }
    std::cerr << out << ": " << fit->model.patches.size() << " patches (at most " << radii
              << " radii), " << measured->bytes.size() << " bytes, fitted in " << long(fitMs)
              << " ms; against the mesh: RMS " << measured->rms() << ", Hausdorff "
              << measured->hausdorff() << " of the diagonal\n";
    if (!fit->reached && !o.patches) {
        std::cerr << input << ": the RMS miss " << fit->rms << " did not reach " << o.error
                  << "; the best was " << fit->model.patches.size()
                  << " patches (more did not lower it, or --max-patches " << o.maxPatches
                  << " was reached). The model is written; ask for a larger --error, or more "
                     "--radii\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
