// The grader against submissions with known verdicts, for every lab that
// comes with FunctionLab: honest work in several styles scores full marks;
// work that is hidden, dead or not felt does not earn the requirement it
// aims at (tests/grading/submissions/<lab>/expected.txt, README there).
#include "courseware/catalogue.h"
#include "grading/checker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace fl;

namespace {

const std::filesystem::path kCorpus = FUNCTIONLAB_SUBMISSIONS_DIR;

const grading::RequirementResult* requirement(const grading::CheckReport& r,
                                              const std::string& id) {
    for (const auto& q : r.requirements)
        if (q.id == id) return &q;
    return nullptr;
}

std::string verdicts(const grading::CheckReport& r) {
    std::string out = "score " + std::to_string(r.score) + "/" + std::to_string(r.maxScore);
    for (const auto& q : r.requirements)
        out += "\n  " + q.id + (q.met ? " met: " : " not: ") + q.evidence;
    return out;
}

std::vector<std::string> labs() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(kCorpus))
        if (entry.is_directory() && std::filesystem::exists(entry.path() / "expected.txt"))
            out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

class SubmissionCorpus : public testing::TestWithParam<std::string> {};

TEST_P(SubmissionCorpus, EverySubmissionGetsItsKnownVerdict) {
    const std::string lab = GetParam();
    const courseware::AssignmentLoad load = courseware::findAssignment(lab);
    ASSERT_TRUE(load.assignment) << lab << " is not an assignment of the course";
    const auto& requirements = load.assignment->requirements;
    std::ifstream list(kCorpus / lab / "expected.txt");
    std::map<std::string, grading::CheckReport> reports;
    std::string line;
    int lineNumber = 0, checked = 0;
    while (std::getline(list, line)) {
        ++lineNumber;
        std::istringstream fields(line);
        std::string file, what, expected;
        if (!(fields >> file) || file[0] == '#') continue;
        ASSERT_TRUE(fields >> what >> expected) << "expected.txt:" << lineNumber << ": " << line;
        if (!reports.count(file)) {
            ASSERT_TRUE(std::filesystem::exists(kCorpus / lab / file)) << file;
            reports[file] = grading::checkSubmission((kCorpus / lab / file).string(), requirements);
        }
        const grading::CheckReport& r = reports.at(file);
        ASSERT_TRUE(r.gradable) << lab << "/" << file;
        const std::string where = lab + "/expected.txt:" + std::to_string(lineNumber) + " " + file;
        if (what == "score") {
            EXPECT_EQ(r.score, std::stoi(expected)) << where << "\n" << verdicts(r);
        } else if (what == "budget_exceeded") {
            EXPECT_EQ(r.budgetExceeded, expected == "yes") << where << "\n" << verdicts(r);
        } else {
            const grading::RequirementResult* q = requirement(r, what);
            ASSERT_TRUE(q) << where << ": no requirement " << what;
            ASSERT_TRUE(expected == "met" || expected == "not") << where;
            EXPECT_EQ(q->met, expected == "met") << where << ": " << q->evidence;
        }
        ++checked;
    }
    EXPECT_GE(checked, 5) << lab << ": two honest styles and three dishonest scenes at least";
}

INSTANTIATE_TEST_SUITE_P(Labs, SubmissionCorpus, testing::ValuesIn(labs()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// `--assignment time` in a folder that holds a folder named "time" (a
// student's work, say) still means the course's lab.
TEST(Manifest, AnIdIsTheCoursesEvenBesideAFolderOfThatName) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "assignment-id-cwd";
    std::filesystem::create_directories(dir / "time");
    std::ofstream(dir / "time" / "scene.x3dv") << "#X3D V3.3 utf8\n";
    const auto before = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    const courseware::AssignmentLoad id = courseware::findAssignment("time");
    const courseware::AssignmentLoad folder = courseware::findAssignment("./time");
    std::filesystem::current_path(before);
    ASSERT_TRUE(id.assignment) << "the course's lab";
    EXPECT_EQ(id.assignment->id, "time");
    EXPECT_FALSE(folder.assignment) << "a path is the folder it names, and it has no manifest";
    ASSERT_FALSE(folder.diagnostics.empty());
}
