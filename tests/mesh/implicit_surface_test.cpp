// `implicit` is the surface f = 0, whichever side is positive (the paper's
// first example, x^2 + y^2 + z^2 - R^2 = 0); `explicit` is the FRep solid
// f >= 0 closed by its box.
#include "mesh/mesh_topology.h"
#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace fl;

namespace {

std::unique_ptr<scene::Scene> shapeScene(const std::string& type, const std::string& formula) {
    auto r =
        scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
                              "FShape { geometry FGeometry { type \"" +
                                  type + "\" definition \"" + formula + "\" resolution 40 } }\n",
                              "shape.x3dv");
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
    return std::move(r.scene);
}

mesh::ShapeMesh meshOf(const std::string& type, const std::string& formula) {
    static std::vector<std::unique_ptr<scene::Scene>> keep; // meshes point at their nodes
    keep.push_back(shapeScene(type, formula));
    mesh::SceneMeshes m = mesh::meshScene(*keep.back(), {});
    EXPECT_EQ(m.shapes.size(), 1u);
    return m.shapes.empty() ? mesh::ShapeMesh{} : std::move(m.shapes[0]);
}

// The largest |coordinate| of any vertex: 1 means a vertex on the default box [-1, 1]^3.
double reach(const mesh::Mesh& m) {
    double r = 0;
    for (const auto& p : m.positions)
        for (float c : p)
            r = std::max(r, double(std::abs(c)));
    return r;
}

const char* kPaperSphere = "x^2 + y^2 + z^2 - 0.5";
const char* kTorus = "(sqrt(x*x + z*z) - 0.6)^2 + y*y - 0.2^2";

} // namespace

TEST(ImplicitSurface, ThePapersSphereIsASphereNotABox) {
    const mesh::ShapeMesh s = meshOf("implicit", kPaperSphere);
    ASSERT_TRUE(s.error.empty()) << s.error;
    EXPECT_NEAR(reach(s.mesh), std::sqrt(0.5), 0.02); // no vertex on the box
    const mesh::Topology t = mesh::analyseTopology(s.mesh);
    EXPECT_TRUE(t.closed());
    EXPECT_TRUE(t.consistentlyOriented());
    // Oriented out of the volume it encloses, though f < 0 inside: 4/3 pi r^3.
    EXPECT_NEAR(t.signedVolume, 4.0 / 3.0 * M_PI * std::pow(0.5, 1.5), 0.02);
    EXPECT_TRUE(s.look.solid); // closed: its back is never seen
    // Every normal points away from the centre.
    for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) {
        const auto& p = s.mesh.positions[i];
        const auto& n = s.mesh.normals[i];
        ASSERT_GT(p[0] * n[0] + p[1] * n[1] + p[2] * n[2], 0) << "vertex " << i;
    }
}

TEST(ImplicitSurface, TheTorusWrittenTheMathematiciansWayIsARing) {
    const mesh::ShapeMesh s = meshOf("implicit", kTorus);
    ASSERT_TRUE(s.error.empty()) << s.error;
    EXPECT_NEAR(reach(s.mesh), 0.8, 0.02);
    const mesh::Topology t = mesh::analyseTopology(s.mesh);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.eulerCharacteristic, 0); // a torus, not a box with a toroidal hole (2 + 2)
    EXPECT_NEAR(t.signedVolume, 2 * M_PI * M_PI * 0.6 * 0.2 * 0.2, 0.02);
}

TEST(ImplicitSurface, BothSignConventionsGiveTheSameSurface) {
    const mesh::ShapeMesh negative = meshOf("implicit", kPaperSphere);
    const mesh::ShapeMesh positive = meshOf("implicit", "0.5 - x^2 - y^2 - z^2");
    const mesh::Topology a = mesh::analyseTopology(negative.mesh),
                         b = mesh::analyseTopology(positive.mesh);
    // Both enclose the ball outward; the mesher places crossings by the sign
    // of f, so the triangles differ a little, not the surface.
    EXPECT_GT(a.signedVolume, 0);
    EXPECT_NEAR(a.signedVolume, b.signedVolume, 2e-3);
    EXPECT_NEAR(reach(negative.mesh), reach(positive.mesh), 0.01);
}

TEST(ImplicitSurface, ASurfaceLeavingItsBoxIsOpenAndTwoSided) {
    // A saddle z = x*y/2 crosses the whole box: no box faces close it.
    const mesh::ShapeMesh s = meshOf("implicit", "z - x*y/2");
    ASSERT_TRUE(s.error.empty()) << s.error;
    const mesh::Topology t = mesh::analyseTopology(s.mesh);
    EXPECT_FALSE(t.closed());
    EXPECT_FALSE(s.look.solid); // seen, and lit, from both sides
    // Every vertex is on the saddle, none on a box face off it.
    for (const auto& p : s.mesh.positions)
        ASSERT_NEAR(p[2] - p[0] * p[1] / 2, 0, 0.01);
}

TEST(ImplicitSurface, ExplicitStaysTheClosedFRepSolid) {
    // The same formula as an FRep solid: f >= 0 is everything outside the
    // sphere, cut by the box: a closed box with a spherical cavity.
    const mesh::ShapeMesh s = meshOf("explicit", kPaperSphere);
    EXPECT_NEAR(reach(s.mesh), 1.0, 1e-6);
    const mesh::Topology t = mesh::analyseTopology(s.mesh);
    EXPECT_TRUE(t.closed());
    EXPECT_NEAR(t.signedVolume, 8 - 4.0 / 3.0 * M_PI * std::pow(0.5, 1.5), 0.05);
    EXPECT_TRUE(s.look.solid);
}

TEST(ImplicitSurface, NegativeInsideWhereAnInsideMattersIsWarnedWithTheFix) {
    auto warnings = [](const std::string& body) {
        auto r = scene::readSceneBytes(
            "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n" + body, "w.x3dv");
        EXPECT_TRUE(r.ok());
        std::vector<std::string> out;
        for (const auto& d : r.diagnostics)
            if (d.severity == scene::Severity::Warning &&
                d.message.find("negative inside") != std::string::npos)
                out.push_back(d.message + " | " + d.suggestion + " | " +
                              std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column));
        return out;
    };
    const std::string sphere = "FShape { geometry FGeometry { type \"implicit\" definition \"" +
                               std::string(kPaperSphere) + "\" } }\n";
    // In a union: warned, at the FGeometry, with the negated formula.
    const auto inUnion = warnings("FTransform { operation \"union\" children [\n" + sphere +
                                  "FShape { geometry FGeometry { type \"explicit\" definition "
                                  "\"0.3 - abs(x)\" } } ] }\n");
    ASSERT_EQ(inUnion.size(), 1u);
    EXPECT_NE(inUnion[0].find("union"), std::string::npos) << inUnion[0];
    EXPECT_NE(inUnion[0].find("type 'explicit'"), std::string::npos) << inUnion[0];
    EXPECT_NE(inUnion[0].find("-(x^2 + y^2 + z^2 - 0.5)"), std::string::npos) << inUnion[0];
    EXPECT_NE(inUnion[0].find("| 5:19"), std::string::npos) << inUnion[0]; // the FGeometry
    // Nested below a Transform in a morph: warned too.
    EXPECT_EQ(warnings("FTransform { operation \"morph\" children Transform { children [\n" +
                       sphere + "] } }\n")
                  .size(),
              1u);
    // With a displacement texture or a density: warned.
    EXPECT_EQ(warnings("FShape { geometry FGeometry { type \"implicit\" definition \"" +
                       std::string(kPaperSphere) +
                       "\" } appearance FAppearance { texture FTexture3D { definition "
                       "\"0.01*sin(9*x)\" } } }\n")
                  .size(),
              1u);
    EXPECT_EQ(warnings("FShape { geometry FGeometry { type \"implicit\" definition \"" +
                       std::string(kPaperSphere) +
                       "\" } physics FPhysics { density FDensity { definition \"1\" } } }\n")
                  .size(),
              1u);
    // Alone, as a surface, nothing to warn about; positive inside in a union neither.
    EXPECT_TRUE(warnings(sphere).empty());
    EXPECT_TRUE(warnings("FTransform { operation \"union\" children [ FShape { geometry FGeometry "
                         "{ type \"implicit\" definition \"0.5 - x^2 - y^2 - z^2\" } } ] }\n")
                    .empty());
    // A surface that crosses its box is not judged (its sides are both outside).
    EXPECT_TRUE(warnings("FTransform { operation \"union\" children [ FShape { geometry FGeometry "
                         "{ type \"implicit\" definition \"z - x*y/2\" } } ] }\n")
                    .empty());
    // Issue 29 §7: the same mistake inside one formula, an operand of & | \.
    auto inFormula = [&](const std::string& definition) {
        return warnings("FShape { geometry FGeometry { type \"implicit\" definition \"" +
                        definition + "\" } }\n");
    };
    const auto operand = inFormula("(x^2 + y^2 + z^2 - 0.5) & (0.2 - y)");
    ASSERT_EQ(operand.size(), 1u);
    EXPECT_NE(operand[0].find("operand (x^2 + y^2 + z^2 - 0.5) of &"), std::string::npos)
        << operand[0];
    EXPECT_NE(operand[0].find("-((x^2 + y^2 + z^2 - 0.5))"), std::string::npos) << operand[0];
    EXPECT_EQ(inFormula("(0.2 - y) | (x^2 + y^2 + z^2 - 0.5)").size(), 1u);
    // Written the FRep way: nothing; a script is not judged (its operands are locals).
    EXPECT_TRUE(inFormula("(0.5 - x^2 - y^2 - z^2) & (0.2 - y)").empty());
    EXPECT_TRUE(inFormula("s = x^2 + y^2 + z^2 - 0.5; return s & (0.2 - y);").empty());
    // A costly operand is not judged: the check's work stays bounded.
    // (64 groups of 64 terms: within the formula's nesting bound, past the check's tape bound.)
    std::string costly = "(x^2 + y^2 + z^2 - 0.5 + 0*(0";
    for (int g = 0; g < 64; ++g) {
        costly += " + (0";
        for (int k = 1; k <= 64; ++k)
            costly += " + sin(" + std::to_string(64 * g + k) + "*x)";
        costly += ")";
    }
    EXPECT_TRUE(inFormula(costly + ")) & (0.2 - y)").empty());
    EXPECT_EQ(inFormula("(x^2 + y^2 + z^2 - 0.5 + 0*(sin(x))) & (0.2 - y)").size(), 1u);
}
