// FPdeSurface: a PDE model as an ordinary shape of a scene, in all three
// encodings — meshed from its url (read like an Inline's: inside the
// scene's folder only), at its resolution or the level of detail's, and a
// url that cannot be read is that shape's error, never the scene's.
#include "mesh/scene_meshing.h"
#include "mesh/surface_distance.h"
#include "pde/pde_file.h"
#include "pde/pde_mesh.h"
#include "pde/pde_scene.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

using namespace fl;
namespace fs = std::filesystem;

namespace {

pde::Model dome() {
    pde::Patch p;
    p.a = 1;
    p.cap = true;
    p.setRadii(1);
    p.spine = {pde::Vec3{0, 1, 0}, pde::Vec3{0, -1, 0}, pde::Vec3{}, pde::Vec3{}};
    p.cosines[0][1] = {1.2, 0, 0}; // u g(u): grows from the pole
    p.sines[0][1] = {0, 0, 1.2};
    pde::completeCap(p);
    pde::Model m;
    m.lo = {-1, 0, -1};
    m.hi = {1, 1, 1};
    m.patches = {p};
    return m;
}

struct Folder {
    fs::path root;
    Folder() {
        root = fs::temp_directory_path() / ("functionlab-pde-node-" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "scenes");
        std::ofstream(root / "scenes" / "dome.pde", std::ios::binary) << pde::encodeBinary(dome());
        std::ofstream(root / "outside.pde", std::ios::binary) << pde::encodeBinary(dome());
        std::ofstream(root / "scenes" / "garbage.pde", std::ios::binary)
            << std::string("FLPDE\0\1\0garbage", 15);
    }
    ~Folder() { fs::remove_all(root); }
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path p = root / "scenes" / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
};

std::string xmlScene(const std::string& url, const std::string& extra = "") {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<X3D profile='Immersive' version='3.3'><head><component name='FunctionLab' "
           "level='1'/></head><Scene>\n"
           "<FShape DEF='DOME'><FPdeSurface url='\"" +
           url + "\"' resolution='16'" + extra + "/></FShape>\n</Scene></X3D>\n";
}

mesh::SceneMeshes meshed(const fs::path& file, mesh::SceneMeshOptions o = {}) {
    const scene::ReadResult r = scene::readSceneFile(file);
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << scene::formatSceneDiagnostic(d);
    return mesh::meshScene(*r.scene, o);
}

} // namespace

TEST(PdeSurfaceNode, IsMeshedFromItsUrlInEveryEncoding) {
    const Folder f;
    const std::size_t expected = pde::meshModel(dome(), pde::meshOptionsFor(16)).triangleCount();
    const std::string classic =
        "FShape { geometry FPdeSurface { url \"dome.pde\" resolution 16 } }\n";
    for (const auto& [name, text] :
         {std::pair{std::string("dome.x3d"), xmlScene("dome.pde")},
          std::pair{std::string("dome.x3dv"), "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT "
                                              "FunctionLab:1\n" +
                                                  classic},
          std::pair{std::string("dome.wrl"), "#VRML V2.0 utf8\n" + classic}}) {
        const mesh::SceneMeshes m = meshed(f.write(name, text));
        ASSERT_EQ(m.shapes.size(), 1u) << name;
        const mesh::ShapeMesh& s = m.shapes[0];
        EXPECT_TRUE(s.error.empty()) << name << ": " << s.error;
        EXPECT_EQ(s.mesh.triangleCount(), expected) << name;
        EXPECT_EQ(s.resolution, 16) << name;
        EXPECT_TRUE(s.levelOfDetail) << name;                              // lod TRUE by default
        EXPECT_EQ(s.mesh.parameters.size(), s.mesh.vertexCount()) << name; // u, v for colour
    }
}

TEST(PdeSurfaceNode, OneSurfaceUsedTwiceIsMeshedForEachShape) {
    const Folder f;
    const mesh::SceneMeshes m = meshed(f.write(
        "twice.x3dv", "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
                      "FShape { geometry DEF D FPdeSurface { url \"dome.pde\" } }\n"
                      "Transform { translation 3 0 0 children FShape { geometry USE D } }\n"));
    ASSERT_EQ(m.shapes.size(), 2u);
    EXPECT_EQ(m.shapes[0].mesh.triangleCount(), m.shapes[1].mesh.triangleCount());
    EXPECT_GT(m.shapes[1].mesh.triangleCount(), 0u);
}

TEST(PdeSurfaceNode, TheLevelOfDetailsResolutionIsTaken) {
    const Folder f;
    const fs::path file = f.write("dome.x3d", xmlScene("dome.pde"));
    const scene::ReadResult r = scene::readSceneFile(file);
    ASSERT_TRUE(r.ok());
    mesh::SceneMeshOptions o;
    const mesh::SceneMeshes first = mesh::meshScene(*r.scene, o);
    ASSERT_EQ(first.shapes.size(), 1u);
    o.resolutions[first.shapes[0].geometry] = 64;
    const mesh::SceneMeshes finer = mesh::meshScene(*r.scene, o);
    EXPECT_EQ(finer.shapes[0].resolution, 64);
    EXPECT_GT(finer.shapes[0].mesh.triangleCount(), 4 * first.shapes[0].mesh.triangleCount());
}

TEST(PdeSurfaceNode, AUrlThatCannotBeReadIsTheShapesErrorNotTheScenes) {
    const Folder f;
    struct Case {
        std::string url, says;
    } cases[] = {
        {"../outside.pde", "outside the scene's folder"},
        {"/etc/passwd", "outside the scene's folder"},
        {"https://example.com/bunny.pde", "never uses the network"},
        {"missing.pde", "missing.pde"},
        {"garbage.pde", "garbage.pde: byte"},
        {"", "names no file"},
        // Markup and control characters are a file name like any other.
        {"&lt;b&gt;x&#9;&lt;/b&gt;.pde", "\"<b>x\t</b>.pde\""},
    };
    for (const Case& c : cases) {
        const mesh::SceneMeshes m = meshed(f.write("bad.x3d", xmlScene(c.url)));
        ASSERT_EQ(m.shapes.size(), 1u) << c.url;
        EXPECT_NE(m.shapes[0].error.find(c.says), std::string::npos)
            << c.url << ": " << m.shapes[0].error;
        EXPECT_TRUE(m.shapes[0].mesh.empty());
    }
    // Read from memory there is no folder: said, not guessed.
    const scene::ReadResult r = scene::readSceneBytes(xmlScene("dome.pde"), "");
    ASSERT_TRUE(r.ok());
    const mesh::SceneMeshes m = mesh::meshScene(*r.scene, {});
    ASSERT_EQ(m.shapes.size(), 1u);
    EXPECT_NE(m.shapes[0].error.find("not read from a file"), std::string::npos)
        << m.shapes[0].error;
}

TEST(PdeSurfaceNode, APatchWrittenAsAFormulaIsTheSameSurface) {
    // pde fit --formula: the patch as a parametric FGeometry; meshed by the
    // parametric mesher it lies on the patch meshed by meshModel.
    pde::Model m = dome();
    m.patches[0].setRadii(3);
    m.patches[0].cosines[2][0] = {0.05, 0.02, -0.03};
    m.patches[0].sines[1][1] = {0.0, 0.04, 0.01};
    pde::completeCap(m.patches[0]);
    const mesh::Mesh reference = pde::meshModel(m, {48, 96});
    for (bool classic : {false, true}) {
        const std::string text = pde::patchScene(m, 0, classic);
        const scene::ReadResult r = scene::readSceneBytes(text, classic ? "p.x3dv" : "p.x3d");
        ASSERT_TRUE(r.ok()) << text;
        for (const auto& d : r.diagnostics)
            ADD_FAILURE() << scene::formatSceneDiagnostic(d);
        mesh::SceneMeshOptions o;
        o.useFileResolution = false;
        o.mesh.resolution = 64;
        const mesh::SceneMeshes meshes = mesh::meshScene(*r.scene, o);
        ASSERT_EQ(meshes.shapes.size(), 1u);
        ASSERT_TRUE(meshes.shapes[0].error.empty()) << meshes.shapes[0].error;
        const mesh::SurfaceDistance d =
            mesh::compareSurfaces(meshes.shapes[0].mesh, reference, 5000);
        EXPECT_LT(d.hausdorff, 0.01 * m.diagonal()) << (classic ? "classic" : "xml");
        EXPECT_LT(d.rms, 0.002 * m.diagonal()) << (classic ? "classic" : "xml");
    }
}

TEST(PdeSurfaceNode, AModelOfVeryManyPatchesIsMeshedCoarserOrRefusedNeverWithoutBound) {
    // A .pde file from others may hold up to a million patches: meshing is
    // bounded by grid cells, not by what the file asks.
    const Folder f;
    pde::Model many = dome();
    many.patches.assign(80000, many.patches[0]); // 80 000 x 8 x 16 cells asked
    std::ofstream(f.root / "scenes" / "many.pde", std::ios::binary) << pde::encodeBinary(many);
    const mesh::SceneMeshes m = meshed(f.write("many.x3d", xmlScene("many.pde", " lod='false'")));
    ASSERT_EQ(m.shapes.size(), 1u);
    EXPECT_TRUE(m.shapes[0].error.empty()) << m.shapes[0].error;
    ASSERT_FALSE(m.shapes[0].warnings.empty());
    EXPECT_NE(m.shapes[0].warnings[0].find("coarser than asked"), std::string::npos);
    EXPECT_LE(m.shapes[0].mesh.triangleCount(), std::size_t(2 * pde::MeshOptions{}.maxCells));
    // More patches than even the coarsest grid allows: the shape's error.
    pde::Model tooMany = dome();
    tooMany.patches.assign(3000, tooMany.patches[0]);
    pde::MeshOptions small;
    small.maxCells = 3000; // 3 000 patches x 1 x 3 cells do not fit
    EXPECT_FALSE(pde::boundedGrid(tooMany, small).fits);
    EXPECT_TRUE(pde::meshModel(tooMany, small).empty());
}

TEST(PdeSurfaceNode, AFileNameOfAnyTextIsWrittenAsTheSceneReadsItBack) {
    // pde::modelScene names a file chosen by someone (the import dialog's
    // Save): quotes, markup, a backslash, a tab and a line break must come
    // back as they were, in both syntaxes. (Other control characters XML
    // cannot hold at all: the dialog refuses such names.)
    const std::string name = "a \"b\" 'c' <d> & e\\f\ng\th.pde";
    for (bool classic : {false, true}) {
        const std::string text = pde::modelScene(name, classic);
        scene::ReadResult r = scene::readSceneBytes(text, classic ? "named.x3dv" : "named.x3d");
        ASSERT_TRUE(r.ok()) << text;
        const scene::Node* surface = nullptr;
        for (const scene::Node* n : r.scene->roots)
            for (const auto& f : n->fields)
                for (const scene::Node* c : f.value.nodes)
                    if (c->kind() == scene::NodeKind::FPdeSurface) surface = c;
        ASSERT_NE(surface, nullptr) << text;
        EXPECT_EQ(scene::stringsField(*surface, "url"), std::vector<std::string>{name}) << text;
    }
}
