// `functionlab mesh`: polygonize a scene's function shapes, or one formula,
// and write STL, OBJ, PLY, glTF binary or X3D.
#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

#include "formula/compiler.h"
#include "mesh/error_driven.h"
#include "mesh/mesh_export.h"
#include "mesh/mesh_topology.h"
#include "mesh/point_cloud.h"
#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"
#include "text_outliner.h"

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
        text =
            text || n.type == "Text" || (n.inlined && depth < 32 && hasText(*n.inlined, depth + 1));
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

const char* kMeshHelp =
    R"(usage: functionlab mesh FILE -o OUT [--time T] [--error E | --resolution N | --points N]
       functionlab mesh --formula "SRC" --box X0,Y0,Z0,X1,Y1,Z1 -o OUT [options]

Polygonizes the shapes of the scene FILE — implicit and explicit function
shapes in their domain boxes, parametric curves (as tubes), surfaces and solids
over their u, v, w ranges, and the standard geometry (Box ... IndexedFaceSet,
triangle/fan/strip/quad sets, Geometry2D, NURBS, Text in the system's fonts) —
coloured by their FMaterial or Material and placed by the Transform/FTransform
nodes above them; or one formula (f >= 0 inside) over a box. Writes OUT in
the format its extension names: .stl (binary), .obj, .ply (binary), .glb
(glTF 2.0 binary), .x3d (vertex colours where the format has them). An
FGeometry with `points` N > 0, or --points, gives a point cloud instead: on an
implicit surface, through an explicit solid, over a parametric object's
parameters (.ply, .obj, .glb or .x3d; STL holds only triangles).

options:
  -o, --output OUT     the file to write
  --time T             the moment, in scene seconds (default 0); wall-clock nodes
                       read it as seconds since 1970-01-01 UTC
  --resolution N       cells along the longest side of each domain box (a real
                       number; default: each FGeometry's resolution, 64 for --formula)
  --error E            mesh each shape until its measured error (largest distance
                       from the surface, on triangle interiors) is at most E times
                       its box diagonal, e.g. 0.001
  --points N           about N points per shape instead of a mesh (with --formula:
                       on the surface; --solid: through the inside)
  --solid              with --formula and --points: fill the inside (f > 0)
  --open               leave the mesh open where a shape leaves its box
                       (default: the box closes it)
  --threads K          worker threads (default: one per core)
  --memory MIB         memory budget (default 2048)

Warnings (no sign change, undefined regions, ...) go to stderr; the exit status
is still 0 when a file was written.

exit status: 0 written, 1 the input could not be read or nothing could be
written, 2 usage error
)";

bool parseBox(const std::string& text, mesh::Box3& box) {
    std::vector<double> v;
    if (!parseNumberList(text, v) || v.size() != 6) return false;
    box = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    return box.valid();
}

int usage(const std::string& problem) {
    std::cerr << "functionlab mesh: " << problem << "\n\n" << kMeshHelp;
    return kExitUsage;
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

} // namespace

int meshCommand(const Args& args) {
    std::string file, formula, output, boxText;
    double time = 0, resolution = 0, error = 0, memory = 2048, threads = 0, points = 0;
    bool open = false, solid = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](const char* what) -> const std::string* {
            if (i + 1 >= args.size()) return nullptr;
            (void)what;
            return &args[++i];
        };
        if (a == "--help" || a == "-h") {
            std::cout << kMeshHelp;
            return kExitOk;
        }
        const std::string* v = nullptr;
        if (a == "-o" || a == "--output") {
            if (!(v = value("OUT"))) return usage("-o needs a file name");
            output = *v;
        } else if (a == "--formula") {
            if (!(v = value("SRC"))) return usage("--formula needs the formula");
            formula = *v;
        } else if (a == "--box") {
            if (!(v = value("box"))) return usage("--box needs X0,Y0,Z0,X1,Y1,Z1");
            boxText = *v;
        } else if (a == "--time" || a == "--resolution" || a == "--error" || a == "--memory" ||
                   a == "--threads" || a == "--points") {
            double d = 0;
            if (!(v = value("number")) || !parseNumber(*v, d)) return usage(a + " needs a number");
            (a == "--time"         ? time
             : a == "--resolution" ? resolution
             : a == "--error"      ? error
             : a == "--memory"     ? memory
             : a == "--points"     ? points
                                   : threads) = d;
        } else if (a == "--open") {
            open = true;
        } else if (a == "--solid") {
            solid = true;
        } else if (a.starts_with("-")) {
            return usage("unknown option '" + a + "'");
        } else if (file.empty()) {
            file = a;
        } else {
            return usage("give one scene FILE");
        }
    }
    if (output.empty()) return usage("give the output file with -o OUT");
    if (file.empty() == formula.empty()) return usage("give a scene FILE or --formula, not both");
    if (!mesh::meshFormatForPath(output))
        return usage("cannot tell the format from '" + output +
                     "'; use .stl, .obj, .ply, .glb or .x3d");
    if (resolution && error) return usage("give --resolution or --error, not both");
    if (resolution < 0 || error < 0 || memory <= 0 || threads < 0)
        return usage("--resolution, --error, --memory and --threads must be positive");
    if (points != 0 && !(points >= 1 && points <= 1e7 && points == std::floor(points)))
        return usage("--points needs a whole number from 1 to 10000000");
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
        mesh::ImplicitField field;
        if (boxText.empty() || !parseBox(boxText, field.box))
            return usage("--formula needs --box X0,Y0,Z0,X1,Y1,Z1 with max above min");
        auto tape = compileFormulaArgument(formula, formula::DefinitionKind::Implicit);
        if (!tape) return kExitDiagnostic;
        field.tape = std::move(*tape);
        field.t = time;
        field.boundary = open ? mesh::BoxBoundary::Open : mesh::BoxBoundary::Closed;
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
