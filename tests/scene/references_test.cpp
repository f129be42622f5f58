// Inline and EXTERNPROTO references: files inside the scene's folder tree are
// loaded (nested, each once), everything else — the network, paths climbing
// out of the folder, symbolic links leading out, cycles, too deep a chain —
// is a located warning and the scene still opens.
#include "scene/effects_plan.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

using namespace fl::scene;
namespace fs = std::filesystem;

namespace {

class References : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() / ("functionlab-refs-" + std::to_string(rd()));
        fs::create_directories(dir_ / "scene" / "parts");
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& relative, const std::string& text) {
        const fs::path p = dir_ / relative;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

    static std::string classic(const std::string& body) {
        return "#X3D V3.3 utf8\nPROFILE Full\n" + body;
    }

    std::string warnings(const ReadResult& r) const {
        std::string all;
        for (const auto& d : r.diagnostics)
            all += formatSceneDiagnostic(d) + "\n";
        return all;
    }

    fs::path dir_;
};

const Node* firstOfType(const Scene& scene, std::string_view type) {
    const Node* found = nullptr;
    scene.forEachNode([&](const Node& n) {
        if (!found && n.type == type && !n.inProtoBody) found = &n;
    });
    return found;
}

} // namespace

TEST_F(References, InlineLoadsRelativeFilesNestedAndOnce) {
    write("scene/parts/leaf.x3dv", classic("DEF LEAF Shape { geometry Sphere { radius 2 } }\n"));
    write(
        "scene/parts/branch.x3dv",
        classic(
            "Inline { url \"leaf.x3dv\" }\nTransform { children Inline { url \"leaf.x3dv\" } }\n"));
    const fs::path top = write(
        "scene/top.x3dv", classic("Inline { url [ \"missing.x3dv\" \"parts/branch.x3dv\" ] }\n"));
    ReadResult r = readSceneFile(top);
    ASSERT_TRUE(r.ok()) << warnings(r);
    EXPECT_EQ(warnings(r), "");
    const Node* inl = firstOfType(*r.scene, "Inline");
    ASSERT_NE(inl, nullptr);
    ASSERT_NE(inl->inlined, nullptr);
    const std::vector<const Scene*> shown = scenesShownBy(*r.scene);
    EXPECT_EQ(shown.size(), 3u); // top, branch, leaf (read once for both Inlines)
    // Every node's file indexes the top scene's table.
    const Node* leaf = firstOfType(*shown.back(), "Sphere");
    ASSERT_NE(leaf, nullptr);
    ASSERT_GE(leaf->file, 0);
    EXPECT_NE(r.scene->files[std::size_t(leaf->file)].path.find("leaf.x3dv"), std::string::npos);
}

TEST_F(References, WhatIsNotReadIsAWarningAtTheInline) {
    write("outside.x3dv", classic("Shape {}\n"));
    fs::create_symlink(dir_ / "outside.x3dv", dir_ / "scene" / "link.x3dv");
    const fs::path top = write("scene/top.x3dv", classic(R"(Group { children [
  Inline { url "../outside.x3dv" }
  Inline { url "link.x3dv" }
  Inline { url "http://example.com/x.x3dv" }
  Inline { url "nothing.x3dv" }
  Inline { url "top.x3dv" }
  Inline { url "/etc/passwd" }
  Inline { load FALSE url "nothing.x3dv" }
  Inline { }
] }
)"));
    ReadResult r = readSceneFile(top);
    ASSERT_TRUE(r.ok());
    const std::string w = warnings(r);
    EXPECT_NE(w.find("top.x3dv:4:3: warning: Inline not loaded: '../outside.x3dv': outside the "
                     "scene's folder"),
              std::string::npos)
        << w;
    EXPECT_NE(w.find("'link.x3dv': outside the scene's folder"), std::string::npos) << w;
    EXPECT_NE(w.find("never uses the network"), std::string::npos) << w;
    EXPECT_NE(w.find("'nothing.x3dv': no such file"), std::string::npos) << w;
    EXPECT_NE(w.find("'top.x3dv': it includes itself"), std::string::npos) << w;
    EXPECT_NE(w.find("'/etc/passwd': outside the scene's folder"), std::string::npos) << w;
    EXPECT_EQ(std::count(w.begin(), w.end(), '\n'), 6) << w; // load FALSE and no url: silent
}

TEST_F(References, ChainsStopAtTheDepthLimit) {
    for (int i = 0; i < 12; ++i)
        write("scene/c" + std::to_string(i) + ".x3dv",
              classic("Inline { url \"c" + std::to_string(i + 1) + ".x3dv\" }\n"));
    write("scene/c12.x3dv", classic("Shape {}\n"));
    ReadResult r = readSceneFile(dir_ / "scene" / "c0.x3dv");
    ASSERT_TRUE(r.ok());
    EXPECT_NE(warnings(r).find("nest more than 8 deep"), std::string::npos) << warnings(r);
}

TEST_F(References, BrokenInlinedFileIsReportedWhereItIsBroken) {
    write("scene/bad.x3dv", classic("Shape { geometry Box { size 1 2 } }\n"));
    ReadResult r = readSceneFile(write("scene/top.x3dv", classic("Inline { url \"bad.x3dv\" }\n")));
    ASSERT_TRUE(r.ok());
    const std::string w = warnings(r);
    EXPECT_NE(w.find("bad.x3dv:3:"), std::string::npos) << w;
    EXPECT_NE(w.find("'bad.x3dv': it has errors"), std::string::npos) << w;
}

TEST_F(References, ExternProtoLoadsTheNamedProtoAndExpands) {
    write("scene/protos/lib.x3dv", classic(R"(PROTO First [] { Group {} }
PROTO Ball [ initializeOnly SFFloat r 1 ] {
  FShape { geometry FGeometry { definition IS def } }
}
)"));
    // The library above has an IS to an undeclared field: use a correct one.
    write("scene/protos/lib.x3dv", classic(R"(PROTO First [] { Group {} }
PROTO Ball [ initializeOnly SFFloat r 1 ] {
  Shape { geometry Sphere { radius IS r } }
}
)"));
    const fs::path top =
        write("scene/top.x3dv", classic(R"(EXTERNPROTO Ball [ initializeOnly SFFloat r ]
  [ "protos/lib.x3dv#Ball" ]
EXTERNPROTO Wrong [ initializeOnly SFVec3f r ] "protos/lib.x3dv#Ball"
EXTERNPROTO Gone [] "protos/gone.x3dv"
Ball { r 3 }
Wrong {}
)"));
    ReadResult r = readSceneFile(top);
    ASSERT_TRUE(r.ok()) << warnings(r);
    const std::string w = warnings(r);
    EXPECT_NE(
        w.find("top.x3dv:5:13: warning: EXTERNPROTO Wrong not loaded: 'protos/lib.x3dv#Ball': "
               "PROTO Ball there has no initializeOnly SFVec3f r"),
        std::string::npos)
        << w;
    EXPECT_NE(w.find("EXTERNPROTO Gone not loaded: 'protos/gone.x3dv': no such file"),
              std::string::npos)
        << w;
    const Node* ball = firstOfType(*r.scene, "Ball");
    ASSERT_NE(ball, nullptr);
    ASSERT_EQ(ball->expansion.size(), 1u);
    const Node* sphere = nodeField(*ball->expansion[0], "geometry");
    ASSERT_NE(sphere, nullptr);
    EXPECT_EQ(numberField(*sphere, "radius"), 3);
}

TEST_F(References, FormulaErrorsInAnExternProtoPointIntoItsFile) {
    write("scene/lib.x3dv", classic("PROTO Blob [] {\n  FShape { geometry FGeometry { definition "
                                    "\"1 - sine(x)\" } }\n}\n"));
    ReadResult r = readSceneFile(
        write("scene/top.x3dv", classic("EXTERNPROTO Blob [] \"lib.x3dv\"\nBlob {}\n")));
    const std::string w = warnings(r);
    EXPECT_NE(w.find("lib.x3dv:4:"), std::string::npos) << w;
}

TEST_F(References, AScreenReadFromMemoryFollowsNothing) {
    ReadResult r = readSceneBytes(classic("Inline { url \"a.x3dv\" }\n"), "mem.x3dv");
    ASSERT_TRUE(r.ok());
    EXPECT_NE(warnings(r).find("not read from a file"), std::string::npos);
}

TEST_F(References, ThePlanSeesInlinedFunctionShapes) {
    write(
        "scene/shape.x3dv",
        classic("FShape { geometry FGeometry { definition \"1 - x*x - y*y - z*z + sin(t)\" } }\n"));
    ReadResult r =
        readSceneFile(write("scene/top.x3dv", classic("Inline { url \"shape.x3dv\" }\n")));
    ASSERT_TRUE(r.ok()) << warnings(r);
    const EffectsPlan plan = makeEffectsPlan(*r.scene);
    EXPECT_EQ(plan.functionShapes, 1u);
    EXPECT_TRUE(plan.timeVarying & kGeometry);
}
