// Batch grading: each submission in its own child; a hang costs its own
// time limit, never the batch; a batch run again skips what is unchanged;
// a batch killed half-way keeps every result it had finished.
#include "grading/batch_grading.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace fl::grading;

namespace {

const char* kVerdict = R"({"assignment": "lab", "gradable": true, "score": 7, "max_score": 10,
  "requirements": [{"id": "r", "met": true, "points": 7, "max_points": 10, "evidence": "e",
  "locations": [{"file": "f", "line": 1, "column": 2}]}], "diagnostics": []})";

struct Class {
    std::filesystem::path folder, db, verdict;
};

Class makeClass(const std::string& name, const std::vector<std::string>& students) {
    Class c;
    c.folder = std::filesystem::path(testing::TempDir()) / name;
    std::filesystem::remove_all(c.folder);
    std::filesystem::create_directories(c.folder / "submissions");
    for (const std::string& s : students)
        std::ofstream(c.folder / "submissions" / (s + ".x3d")) << "<X3D/> " << s;
    c.db = c.folder / "gradebook.sqlite";
    c.verdict = c.folder / "verdict.json";
    std::ofstream(c.verdict) << kVerdict;
    return c;
}

// A stand-in checker: prints the verdict, but hangs for students named "slow*".
BatchOptions options(const Class& c) {
    BatchOptions o;
    o.jobs = 2;
    o.limits.wallSeconds = 1;
    o.checkerVersion = "1";
    o.command = [verdict = c.verdict.string()](const BatchSubmission& s) {
        const std::string script =
            s.student.rfind("slow", 0) == 0 ? "sleep 30" : "cat '" + verdict + "'";
        return std::vector<std::string>{"/bin/sh", "-c", script};
    };
    return o;
}

AssignmentRecord lab() {
    return {"lab", "Lab", 10, 0, "r1", ""};
}

} // namespace

TEST(BatchGrading, AHangCostsItsOwnTimeNeverTheBatch) {
    const Class c = makeClass("batch-hang", {"ann", "slowpoke", "ben", "cid"});
    std::vector<std::string> skipped;
    const auto subs = findSubmissions(c.folder / "submissions", skipped);
    ASSERT_EQ(subs.size(), 4u);
    Gradebook book(c.db.string());
    const auto start = std::chrono::steady_clock::now();
    const BatchSummary s = gradeBatch(book, lab(), subs, options(c));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    EXPECT_EQ(s.graded, 3u);
    EXPECT_EQ(s.failed, 1u);
    ASSERT_EQ(s.problems.size(), 1u);
    EXPECT_NE(s.problems[0].find("slowpoke: the checker ran out of time"), std::string::npos);
    const auto grades = book.latestGrades("lab");
    ASSERT_EQ(grades.size(), 4u);
    EXPECT_EQ(grades[0].score, 7);
    EXPECT_EQ(grades[0].requirements.at(0).locations.at(0).column, 2);
    // Run again: everything is unchanged (the hang too: the same bytes).
    const BatchSummary again = gradeBatch(book, lab(), subs, options(c));
    EXPECT_EQ(again.skipped, 4u);
    EXPECT_EQ(again.graded, 0u);
    // A changed submission is graded again.
    std::ofstream(c.folder / "submissions" / "ann.x3d") << "<X3D/> changed";
    EXPECT_EQ(gradeBatch(book, lab(), subs, options(c)).graded, 1u);
    EXPECT_TRUE(book.verify().intact);
}

TEST(BatchGrading, AKilledBatchKeepsWhatItFinished) {
    const Class c = makeClass("batch-killed", {"a1", "a2", "slow1", "slow2", "slow3"});
    std::vector<std::string> skipped;
    const auto subs = findSubmissions(c.folder / "submissions", skipped);
    { Gradebook create(c.db.string()); }
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        Gradebook book(c.db.string());
        BatchOptions o = options(c);
        o.jobs = 1;
        o.limits.wallSeconds = 30;
        gradeBatch(book, lab(), subs, o);
        ::_exit(0);
    }
    // Wait until the two quick ones are in, then kill the batch mid-hang.
    bool twoIn = false;
    for (int i = 0; i < 200 && !twoIn; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        Gradebook reader(c.db.string());
        twoIn = reader.latestGrades("lab").size() == 2;
    }
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(twoIn);
    Gradebook book(c.db.string());
    EXPECT_EQ(book.latestGrades("lab").size(), 2u);
    EXPECT_TRUE(book.verify().intact);
    // Run again: what was finished is skipped, only the rest is graded.
    const BatchSummary again = gradeBatch(book, lab(), subs, options(c));
    EXPECT_EQ(again.skipped, 2u);
    EXPECT_EQ(again.graded + again.failed + again.notGradable, 3u);
    EXPECT_EQ(book.latestGrades("lab").size(), 5u);
    EXPECT_TRUE(book.verify().intact);
}

TEST(BatchGrading, OnlyPlainNamesAreSubmissions) {
    const auto folder = std::filesystem::path(testing::TempDir()) / "batch-names";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "dora");
    std::ofstream(folder / "eve.x3dv.gz") << "x";
    std::ofstream(folder / ".hidden.x3d") << "x";
    std::ofstream(folder / "notes.txt") << "x";
    std::ofstream(folder / "bad\x01name.x3d") << "x";
    std::vector<std::string> skipped;
    const auto subs = findSubmissions(folder, skipped);
    ASSERT_EQ(subs.size(), 2u);
    EXPECT_EQ(subs[0].student, "dora");
    EXPECT_EQ(subs[1].student, "eve");
    EXPECT_EQ(skipped.size(), 3u);
}

TEST(BatchGrading, CheckJsonIsReadBackOrRefused) {
    GradeRecord g;
    EXPECT_TRUE(gradeFromCheckJson(kVerdict, g));
    EXPECT_EQ(g.score, 7);
    EXPECT_FALSE(gradeFromCheckJson("", g));
    EXPECT_FALSE(gradeFromCheckJson("[1]", g));
    EXPECT_FALSE(gradeFromCheckJson("{\"gradable\": 3}", g));
}
