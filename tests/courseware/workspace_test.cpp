// The student's own copies and the instructor's solutions (issue 29 §2): an
// example or a starter is copied into the workspace once and never written
// over; the course's file stays as it was; solutions are found only in an
// instructor's folder, and an assignment without them (a student's
// installation) loads all the same.
#include "courseware/assignment.h"
#include "courseware/catalogue.h"
#include "courseware/workspace.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fl::courseware;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void write(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

// A fresh folder under the build's temp, set as the workspace for the test.
class Workspace : public ::testing::Test {
  protected:
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("functionlab-workspace-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root);
        fs::create_directories(root);
        setenv("FUNCTIONLAB_WORKSPACE", (root / "work").c_str(), 1);
    }
    void TearDown() override {
        unsetenv("FUNCTIONLAB_WORKSPACE");
        unsetenv("FUNCTIONLAB_INSTRUCTOR_DIR");
        std::error_code ec; // a read-only course file must not keep the folder
        for (const auto& e : fs::recursive_directory_iterator(root, ec))
            fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(root, ec);
    }
    fs::path root;
};

const fs::path kAssignments = fs::path(FUNCTIONLAB_COURSEWARE_DIR) / "assignments";

} // namespace

TEST_F(Workspace, AStarterIsCopiedOnceAndTheCopyIsNeverWrittenOver) {
    const fs::path course = root / "course" / "starter.x3d";
    write(course, "course text");
    fs::permissions(course, fs::perms::owner_read,
                    fs::perm_options::replace); // installed: read-only
    const WorkingCopy first = workingCopyOf(course, "time");
    ASSERT_TRUE(first.error.empty()) << first.error;
    EXPECT_FALSE(first.existed);
    EXPECT_EQ(first.path, root / "work" / "time" / "starter.x3d");
    EXPECT_EQ(read(first.path), "course text");
    // The student's copy is theirs to write.
    write(first.path, "my work");
    EXPECT_EQ(read(first.path), "my work");
    const WorkingCopy again = workingCopyOf(course, "time");
    EXPECT_TRUE(again.existed);
    EXPECT_EQ(read(again.path), "my work"); // kept
    EXPECT_EQ(read(course), "course text"); // the course's unchanged
}

TEST_F(Workspace, OnlyAPlainFolderNameIsAWorkspaceFolder) {
    const fs::path course = root / "course" / "a.x3d";
    write(course, "x");
    for (const char* bad : {"", ".", "..", "../escape", "a/b"})
        EXPECT_FALSE(workingCopyOf(course, bad).error.empty()) << bad;
    EXPECT_FALSE(fs::exists(root / "escape"));
}

TEST_F(Workspace, TheCoursewareIsKnownSoNothingIsSavedIntoIt) {
    EXPECT_TRUE(isInsideCourseware(coursewareFolder() / "examples" / "watermelon.x3d"));
    EXPECT_TRUE(isInsideCourseware(coursewareFolder() / "examples" / ".." / "examples" / "x.x3d"));
    EXPECT_FALSE(isInsideCourseware(workspaceFolder() / "examples" / "watermelon.x3d"));
    EXPECT_FALSE(isInsideCourseware(coursewareFolder().parent_path() / "coursewareX" / "a.x3d"));
}

TEST_F(Workspace, SolutionsAreTheInstructorsAndTheirAbsenceIsNoError) {
    // Every assignment of the course names solutions the source tree has.
    for (const AssignmentLoad& load : listAssignments(kAssignments)) {
        ASSERT_TRUE(load.assignment);
        EXPECT_FALSE(load.assignment->solutions.empty()) << load.assignment->id;
    }
    // A student's copy of an assignment folder without its solution/ loads,
    // with no solutions and no error.
    const fs::path student = root / "course" / "time";
    fs::create_directories(student);
    for (const char* f : {"manifest.json", "instructions.md", "starter.x3d"})
        fs::copy_file(kAssignments / "time" / f, student / f);
    const AssignmentLoad bare = loadAssignment(student);
    ASSERT_TRUE(bare.assignment) << (bare.diagnostics.empty() ? "" : bare.diagnostics[0].message);
    EXPECT_TRUE(bare.assignment->solutions.empty());
    // The instructor's folder, named by FUNCTIONLAB_INSTRUCTOR_DIR, supplies them.
    const fs::path instructor = root / "instructor";
    fs::create_directories(instructor / "time" / "solution");
    fs::copy_file(kAssignments / "time" / "solution" / "seasons.x3d",
                  instructor / "time" / "solution" / "seasons.x3d");
    setenv("FUNCTIONLAB_INSTRUCTOR_DIR", instructor.c_str(), 1);
    const AssignmentLoad withSolutions = loadAssignment(student);
    ASSERT_TRUE(withSolutions.assignment);
    ASSERT_EQ(withSolutions.assignment->solutions.size(), 1u);
    EXPECT_EQ(withSolutions.assignment->solutions[0],
              instructor / "time" / "solution" / "seasons.x3d");
    // A solution path that leaves the folder is still refused.
    std::string manifest = read(student / "manifest.json");
    manifest.replace(manifest.find("solution/seasons.x3d"), 20, "../../etc/passwd");
    write(student / "manifest.json", manifest);
    EXPECT_FALSE(loadAssignment(student).assignment);
}
