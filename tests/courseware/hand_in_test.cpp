// File → Hand in: the scene (as the editor holds it) and the files it uses,
// at the same relative places, in a new folder that `grade check` reads.
#include "courseware/catalogue.h"
#include "courseware/hand_in.h"
#include "grading/checker.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace fl;

namespace {

std::filesystem::path fresh(const std::string& name) {
    const auto p = std::filesystem::path(testing::TempDir()) / name;
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

} // namespace

TEST(HandIn, PacksTheSceneAndWhatItUses) {
    const auto work = fresh("handin-work");
    std::filesystem::create_directories(work / "parts" / "img");
    std::ofstream(work / "parts" / "ball.x3dv")
        << "#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Sphere {} }\n";
    // A 1x1 PNG is not needed to pack: the bytes are copied as they are.
    std::ofstream(work / "parts" / "img" / "wood.png", std::ios::binary) << "not really a png";
    const std::string text = R"(#X3D V3.3 utf8
PROFILE Immersive
COMPONENT FunctionLab:1
Inline { url "parts/ball.x3dv" }
Shape { appearance Appearance { texture ImageTexture { url [ "missing.png" "parts/img/wood.png" ] } }
        geometry Box {} }
FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" } }
)";
    std::ofstream(work / "world.x3dv") << text;
    const scene::ReadResult read = scene::readSceneFile(work / "world.x3dv");
    ASSERT_TRUE(read.ok());
    const auto out = std::filesystem::path(testing::TempDir()) / "handin-out";
    std::filesystem::remove_all(out);
    const courseware::HandIn done =
        courseware::packSubmission(*read.scene, work / "world.x3dv", text + "# edited\n", out);
    ASSERT_TRUE(done.ok) << (done.problems.empty() ? "" : done.problems[0]);
    EXPECT_TRUE(done.problems.empty());
    EXPECT_EQ(done.packed, (std::vector<std::filesystem::path>{"world.x3dv", "parts/ball.x3dv",
                                                               "parts/img/wood.png"}));
    std::ifstream in(out / "world.x3dv");
    const std::string packed((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(packed.find("# edited"), std::string::npos) << "the editor's text, not the file's";
    // What grade check reads.
    const auto lab = courseware::findAssignment("implicit-fantasies");
    ASSERT_TRUE(lab.assignment);
    const grading::CheckReport r =
        grading::checkSubmission(out.string(), lab.assignment->requirements);
    EXPECT_TRUE(r.gradable);
    // A folder that holds something is not written into.
    const courseware::HandIn again =
        courseware::packSubmission(*read.scene, work / "world.x3dv", text, out);
    EXPECT_FALSE(again.ok);
}
