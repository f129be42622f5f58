// `functionlab mesh`: polygonize a scene's function shapes, or one formula,
// and write STL, OBJ, PLY, glTF binary or X3D.
#include "cli/arguments.h"
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "field/field_sampler.h"
#include "formula/compiler.h"
#include "mesh/error_driven.h"
#include "mesh/mesh_export.h"
#include "mesh/mesh_topology.h"
#include "mesh/point_cloud.h"
#include "mesh/scene_meshing.h"
#include "pde/pde_file.h"
#include "pde/pde_mesh.h"
#include "scene/scene_reader.h"
#include "viewer/text_outliner.h"

#include <QGuiApplication>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace fl::cli {
namespace {

// Text needs Qt's font database, which lives in a QGuiApplication; the
// offscreen platform needs no display. Made only for scenes with Text.
bool hasText(const scene::Scene& scene, int depth = 0) {
    bool text = false;
    scene.forEachNode([&](const scene::Node& n) {
        text = text || n.kind() == scene::NodeKind::Text ||
               (n.inlined && depth < 32 && hasText(*n.inlined, depth + 1));
    });
    return text;
}

std::unique_ptr<QGuiApplication> fontsFor(const scene::Scene& scene) {
    if (!hasText(scene) || QCoreApplication::instance()) return nullptr;
    static int argc = 3;
    static char arg0[] = "functionlab", arg1[] = "-platform", arg2[] = "offscreen";
    static char* argv[] = {arg0, arg1, arg2, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

void describe(const std::string& name, const mesh::Mesh& m, const mesh::MeshStats& s,
              double measuredError) {
    if (m.isPointCloud()) {
        std::cerr << name << ": " << m.vertexCount() << " points, "
                  << s.evaluations.points + s.evaluations.gradients << " evaluations, "
                  << std::lround(s.milliseconds) << " ms\n";
        return;
    }
    const mesh::Topology t = mesh::analyseTopology(m);
    std::cerr << name << ": " << m.triangleCount() << " triangles, " << m.vertexCount()
              << " vertices, " << s.evaluations.points + s.evaluations.gradients << " evaluations, "
              << std::lround(s.milliseconds) << " ms, " << (t.closed() ? "closed" : "open")
              << (t.manifold() ? "" : ", not manifold");
    if (measuredError >= 0) std::cerr << ", measured error " << measuredError << " of the diagonal";
    std::cerr << "\n";
}

bool isPdeModel(const std::string& file) {
    return file.size() > 4 && file.compare(file.size() - 4, 4, ".pde") == 0;
}

} // namespace

const CommandSpec& meshSpec() {
    static const CommandSpec spec{
        .name = "mesh",
        .summary = "polygonize function shapes; .stl .obj .ply .glb .x3d",
        .synopsis = {"mesh FILE -o OUT [--time T] [--error E | --resolution N | --points N]",
                     "mesh MODEL.pde -o OUT [--resolution N]",
                     "mesh --formula \"SRC\" --box X0,Y0,Z0,X1,Y1,Z1 -o OUT [--open]\n"
                     "[--error E | --resolution N | --points N [--solid]]"},
        .description =
            "Polygonizes the shapes of the scene FILE — implicit and explicit function\n"
            "shapes in their domain boxes, parametric curves (as tubes), surfaces and solids\n"
            "over their u, v, w ranges, and the standard geometry (Box ... IndexedFaceSet,\n"
            "triangle/fan/strip/quad sets, Geometry2D, NURBS, Text in the system's fonts) —\n"
            "coloured by their FMaterial or Material and placed by the Transform/FTransform\n"
            "nodes above them; or one formula (f >= 0 inside) over a box. Writes OUT in\n"
            "the format its extension names: .stl (binary), .obj, .ply (binary), .glb\n"
            "(glTF 2.0 binary), .x3d (vertex colours where the format has them). An\n"
            "FGeometry with `points` N > 0, or --points, gives a point cloud instead: on an\n"
            "implicit surface, through an explicit solid, over a parametric object's\n"
            "parameters (.ply, .obj, .glb or .x3d; STL holds only triangles). A PDE model\n"
            "(MODEL.pde, from `pde fit`) is meshed patch by patch on a grid of N/2 steps\n"
            "along u and N round v (--resolution, default 32).\n",
        .positionals = {{.name = "FILE",
                         .help = "the scene (or give --formula and --box instead)",
                         .required = false}},
        .options =
            {{.name = "output",
              .shortName = 'o',
              .kind = OptionKind::Path,
              .valueName = "OUT",
              .help = "the file to write (required)"},
             {.name = "formula",
              .kind = OptionKind::Text,
              .valueName = "SRC",
              .help = "mesh this formula (f >= 0 inside) instead of a scene; needs --box"},
             {.name = "box",
              .kind = OptionKind::NumberList,
              .valueName = "X0,Y0,Z0,X1,Y1,Z1",
              .help = "the formula's box, max above min on every axis",
              .count = 6},
             {.name = "time",
              .kind = OptionKind::Number,
              .valueName = "T",
              .help = "the moment, in scene seconds; wall-clock nodes read it as seconds since "
                      "1970-01-01 UTC",
              .defaultValue = "0"},
             {.name = "resolution",
              .kind = OptionKind::Number,
              .valueName = "N",
              .help = "cells along the longest side of each domain box (a real number; default: "
                      "each FGeometry's resolution, 64 for --formula)",
              .min = 0},
             {.name = "error",
              .kind = OptionKind::Number,
              .valueName = "E",
              .help = "mesh each shape until its measured error (largest distance from the "
                      "surface, on triangle interiors) is at most E times its box diagonal, e.g. "
                      "0.001",
              .min = 0},
             {.name = "points",
              .kind = OptionKind::Integer,
              .valueName = "N",
              .help = "about N points per shape instead of a mesh (with --formula: on the "
                      "surface; --solid: through the inside)",
              .min = 0,
              .max = 10000000},
             {.name = "solid", .help = "with --formula and --points: fill the inside (f > 0)"},
             {.name = "open",
              .help = "leave the mesh open where a shape leaves its box (default: the box "
                      "closes it)"},
             {.name = "threads",
              .kind = OptionKind::Integer,
              .valueName = "K",
              .help = "worker threads (0: one per core)",
              .defaultValue = "0",
              .min = 0,
              .max = 1024},
             {.name = "memory",
              .kind = OptionKind::Number,
              .valueName = "MIB",
              .help = "memory budget in MiB",
              .defaultValue = "2048",
              .min = 0,
              .minExclusive = true}},
        .notes = "Warnings (no sign change, undefined regions, ...) go to stderr; the exit status\n"
                 "is still 0 when a file was written.\n",
        .exitStatus =
            "0 written, 1 the input could not be read or nothing could be written, 2 usage error",
    };
    return spec;
}

int meshCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(meshSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    auto usage = [](const std::string& problem) {
        return usageError(meshSpec(), problem, std::cerr);
    };
    const std::string file = a->positional("FILE"), formula = a->text("formula"),
                      output = a->text("output");
    const double time = a->number("time", 0), resolution = a->number("resolution", 0),
                 error = a->number("error", 0), memory = a->number("memory", 2048);
    const std::int64_t threads = a->integer("threads", 0), points = a->integer("points", 0);
    const bool open = a->flag("open"), solid = a->flag("solid");
    if (output.empty()) return usage("give the output file with -o OUT");
    if (file.empty() == formula.empty()) return usage("give a scene FILE or --formula, not both");
    if (!mesh::meshFormatForPath(output))
        return usage("cannot tell the format from '" + output +
                     "'; use .stl, .obj, .ply, .glb or .x3d");
    if (resolution && error) return usage("give --resolution or --error, not both");
    if (points > 0 && (resolution > 0 || error > 0))
        return usage("--points draws points, not a mesh: leave out --resolution and --error");
    if (points > 0 && mesh::meshFormatForPath(output) == mesh::MeshFormat::Stl)
        return usage("STL holds triangles only; write a point cloud as .ply, .obj, .glb or .x3d");
    if (solid && (points == 0 || formula.empty()))
        return usage("--solid goes with --formula and --points");

    mesh::MeshOptions options;
    options.threads = int(threads);
    options.memoryBudgetBytes = std::size_t(memory * 1024 * 1024);
    mesh::Mesh result;
    bool anything = false;
    if (!formula.empty()) {
        field::ImplicitField field;
        const auto box = a->numbers("box");
        if (!box) return usage("--formula needs --box X0,Y0,Z0,X1,Y1,Z1");
        field.box = {{(*box)[0], (*box)[1], (*box)[2]}, {(*box)[3], (*box)[4], (*box)[5]}};
        if (!field.box.valid()) return usage("--box needs max above min on every axis");
        auto tape = compileFormulaArgument(formula, formula::DefinitionKind::Implicit);
        if (!tape) return kExitDiagnostic;
        field.tape = std::move(*tape);
        field.t = time;
        field.boundary = open ? field::BoxBoundary::Open : field::BoxBoundary::Closed;
        mesh::MeshResult r;
        double measured = -1;
        if (points > 0) {
            mesh::PointCloudOptions pc;
            pc.count = std::size_t(points);
            pc.threads = options.threads;
            r = solid ? mesh::pointsInSolid(field, pc) : mesh::pointsOnSurface(field, pc);
        } else if (error > 0) {
            mesh::ErrorDrivenResult e = mesh::meshForError(field, error, options);
            r = std::move(e.result);
            measured = e.error.max;
            if (r.ok() && !e.met)
                std::cerr << "warning: the target error was not reached (" << measured << ")\n";
        } else {
            options.resolution = resolution > 0 ? resolution : 64;
            r = mesh::meshImplicit(field, options);
        }
        for (const auto& w : r.warnings)
            std::cerr << "warning: " << w << "\n";
        if (!r.ok()) {
            std::cerr << "functionlab mesh: " << r.error << "\n";
            return kExitDiagnostic;
        }
        describe("formula", r.mesh, r.stats, measured);
        result = std::move(r.mesh);
        anything = true;
    } else if (isPdeModel(file)) {
        // A PDE model (pde fit's .pde): its patches on a (u, v) grid.
        if (open || points > 0 || error > 0) return usage("a .pde model takes --resolution only");
        const pde::ReadResult r = pde::readModelFile(file);
        if (!r.ok()) {
            std::cerr << r.error << "\n";
            return kExitDiagnostic;
        }
        const pde::BoundedGrid grid =
            pde::boundedGrid(*r.model, pde::meshOptionsFor(resolution > 0 ? resolution : 32));
        if (!grid.fits) {
            std::cerr << file << ": " << r.model->patches.size()
                      << " patches: more than can be meshed\n";
            return kExitDiagnostic;
        }
        if (grid.reduced)
            std::cerr << "note: " << file << ": meshed coarser than asked ("
                      << r.model->patches.size() << " patches)\n";
        const pde::MeshOptions po = grid.options;
        result = pde::meshModel(*r.model, po);
        std::cerr << file << ": " << r.model->patches.size() << " patches, " << po.stepsU << " x "
                  << po.stepsV << " each, " << result.triangleCount() << " triangles\n";
        anything = !result.empty();
    } else {
        if (open)
            return usage("--open applies to --formula only (a scene's FGeometry boxes close it)");
        scene::ReadResult r = scene::readSceneFile(file);
        for (const auto& d : r.diagnostics)
            std::cerr << scene::formatSceneDiagnostic(d) << "\n";
        if (!r.ok()) return kExitDiagnostic;
        mesh::SceneMeshOptions so;
        so.mesh = options;
        so.sceneSeconds = time;
        so.targetError = error;
        so.useFileResolution = resolution <= 0;
        so.points = std::size_t(points);
        if (resolution > 0) so.mesh.resolution = resolution;
        const auto fonts = fontsFor(*r.scene);
        so.text = viewer::qtTextOutliner();
        mesh::SceneMeshes meshes = mesh::meshScene(*r.scene, so);
        for (const auto& note : meshes.notes)
            std::cerr << "note: " << note << "\n";
        for (const auto& s : meshes.shapes) {
            for (const auto& w : s.warnings)
                std::cerr << "warning: " << s.name << ": " << w << "\n";
            if (!s.error.empty()) {
                std::cerr << "error: " << s.name << ": " << s.error << "\n";
                continue;
            }
            describe(s.name, s.mesh, s.stats, s.measuredError);
            anything = anything || !s.mesh.empty();
        }
        // One file holds one kind: triangles, or points.
        const mesh::Mesh triangles = mesh::mergeMeshes(meshes.shapes);
        const mesh::Mesh cloud = mesh::mergeMeshes(meshes.shapes, mesh::Primitive::Points);
        if (!triangles.empty() && !cloud.empty()) {
            std::cerr << "functionlab mesh: " << file
                      << " has both meshes and point clouds (FGeometry points > 0), and one file "
                         "holds one kind; give --points N to write every shape as points\n";
            return kExitDiagnostic;
        }
        const mesh::Mesh lines = mesh::mergeMeshes(meshes.shapes, mesh::Primitive::Lines);
        if (!lines.empty() && (!triangles.empty() || !cloud.empty()))
            std::cerr << "note: the scene's line sets are left out of " << output
                      << " (one file holds one kind)\n";
        result = !cloud.empty() ? cloud : !triangles.empty() ? triangles : lines;
        if (meshes.shapes.empty()) {
            std::cerr << "functionlab mesh: " << file << " has no shape to mesh\n";
            return kExitDiagnostic;
        }
    }
    std::string problem;
    if (!mesh::writeMesh(result, output, problem)) {
        std::cerr << "functionlab mesh: " << problem << "\n";
        return kExitDiagnostic;
    }
    if (!anything) std::cerr << "warning: the mesh is empty\n";
    std::cerr << "wrote " << output << " ("
              << mesh::meshFormatName(*mesh::meshFormatForPath(output)) << ", ";
    if (result.isPointCloud())
        std::cerr << result.vertexCount() << " points)\n";
    else
        std::cerr << result.triangleCount() << " triangles)\n";
    return kExitOk;
}

} // namespace fl::cli
