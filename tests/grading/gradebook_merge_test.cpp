// Grading a course in parts (issue 32 §4): shardOf is stable and splits a
// class evenly; parts merged hold the same results as one gradebook, every
// entry of every part (with its own time) and a record of the merge, and a
// log that verifies; parts that overlap, describe a student or an
// assignment differently, or were tampered with are refused, and a refused
// merge writes nothing.
#include "grading/gradebook.h"
#include "grading/gradebook_merge.h"

#include <gtest/gtest.h>

#include <sqlite3.h>

#include <cstdio>
#include <filesystem>
#include <map>

using namespace fl::grading;

namespace {

std::string freshPath(const std::string& name) {
    const auto p = std::filesystem::path(testing::TempDir()) / ("merge-" + name + ".sqlite");
    for (const char* suffix : {"", "-wal", "-shm", ".partial"})
        std::filesystem::remove(p.string() + suffix);
    return p.string();
}

GradeRecord grade(const std::string& student, double score) {
    GradeRecord g;
    g.student = student;
    g.assignment = "lab";
    g.contentHash = "hash-" + student;
    g.submittedAt = "2026-11-20T10:00:00Z";
    g.checkerVersion = "1";
    g.rubricHash = "r1";
    g.gradable = true;
    g.score = score;
    g.maxScore = 100;
    g.gradedAt = "2026-11-23T10:00:00Z";
    g.requirements = {
        {"implicit", RequirementKind::ImplicitSurface, true, score, 100, "ok", {{"a.x3d", 3, 4}}}};
    return g;
}

const char* const kRoster = "id,name\nann,Ann\nbob,Bob\ncid,Cid\ndee,Dee\n";

// A part: the whole roster, the grades of `students`, extras by `extra`.
std::string part(const std::string& name, const std::vector<std::pair<std::string, double>>& grades,
                 const std::function<void(Gradebook&)>& extra = {}) {
    const std::string path = freshPath(name);
    Gradebook book(path);
    book.registerAssignment({"lab", "Lab", 100, 20, "r1", ""});
    book.importRoster(kRoster);
    for (const auto& [student, score] : grades)
        book.recordGrade(grade(student, score));
    if (extra) extra(book);
    return path;
}

std::map<std::string, double> finalScores(const std::string& path) {
    Gradebook book(path);
    std::map<std::string, double> out;
    for (const GradeRecord& g : book.latestGrades("lab"))
        out[g.student] = book.finalScore(g);
    return out;
}

} // namespace

TEST(GradebookMerge, AStudentsPartIsStableAndPartsAreEven) {
    EXPECT_EQ(shardOf("alice", 4), shardOf("alice", 4));
    EXPECT_EQ(shardOf("", 4), shardOf("", 4));
    EXPECT_EQ(shardOf("anyone", 1), 0u);
    // FNV-1a 64 of "a" is 0xaf63dc4c8601ec8c: the same number on every machine.
    EXPECT_EQ(shardOf("a", 1000), std::size_t(0xaf63dc4c8601ec8cull % 1000));
    std::vector<int> counts(4, 0);
    for (int i = 0; i < 2000; ++i)
        ++counts[shardOf("s" + std::to_string(i), 4)];
    for (int c : counts)
        EXPECT_NEAR(c, 500, 75);
}

TEST(GradebookMerge, PartsMergedHoldWhatOneGradebookHolds) {
    const std::string one =
        part("one", {{"ann", 90}, {"bob", 60}, {"cid", 40}, {"dee", 75}}, [](Gradebook& b) {
            b.setManualScore("bob", "lab", "style", 5, "neat", "ta");
            b.addOverride("cid", "lab", 70, "prof", "by hand");
        });
    const std::string a = part("a", {{"ann", 90}, {"bob", 60}}, [](Gradebook& b) {
        b.setManualScore("bob", "lab", "style", 5, "neat", "ta");
    });
    const std::string b = part("b", {{"cid", 40}, {"dee", 75}}, [](Gradebook& g) {
        g.addOverride("cid", "lab", 70, "prof", "by hand");
    });
    const std::string out = freshPath("course");
    std::string why;
    const auto merged = mergeGradebooks({a, b}, out, &why);
    ASSERT_TRUE(merged) << why;
    EXPECT_EQ(merged->sources, 2u);
    EXPECT_EQ(merged->students, 4u);
    EXPECT_EQ(merged->grades, 4u);
    EXPECT_EQ(finalScores(out), finalScores(one));
    EXPECT_EQ(finalScores(out).at("cid"), 70);
    EXPECT_EQ(finalScores(out).at("bob"), 65);
    // Every entry of both parts, in order and with its own time, then the record.
    Gradebook course(out);
    const auto log = course.logEntries();
    std::vector<LogEntry> expected;
    for (const std::string& p : {a, b}) {
        Gradebook book(p);
        const auto entries = book.logEntries();
        expected.insert(expected.end(), entries.begin(), entries.end());
    }
    ASSERT_EQ(log.size(), expected.size() + 1);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(log[i].kind, expected[i].kind);
        EXPECT_EQ(log[i].payload, expected[i].payload);
        EXPECT_EQ(log[i].at, expected[i].at);
    }
    EXPECT_EQ(log.back().kind, "merge");
    Gradebook partB(b);
    EXPECT_NE(log.back().payload.find(partB.head().hash), std::string::npos);
    EXPECT_NE(log.back().payload.find("merge-b.sqlite"), std::string::npos);
    const GradebookCheck check = course.verify();
    EXPECT_TRUE(check.intact) << check.problem;
    EXPECT_EQ(check.entries, log.size());
}

TEST(GradebookMerge, PartsThatDisagreeAreRefusedAndNothingIsWritten) {
    const std::string out = freshPath("refused");
    std::string why;
    auto refused = [&](const std::vector<std::string>& parts) {
        why.clear();
        const bool ok = mergeGradebooks(parts, out, &why).has_value();
        EXPECT_FALSE(std::filesystem::exists(out));
        EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
        return !ok;
    };
    const std::string a = part("ra", {{"ann", 90}});
    // The same student's work in two parts (a grade; a manual score alone too).
    EXPECT_TRUE(refused({a, part("rb", {{"ann", 80}})}));
    EXPECT_NE(why.find("the work of ann on lab is in both"), std::string::npos) << why;
    EXPECT_TRUE(refused({a, part("rc", {}, [](Gradebook& b) {
                             b.setManualScore("ann", "lab", "style", 1, "", "ta");
                         })}));
    // A name from the file with an escape sequence is shown, not obeyed.
    EXPECT_TRUE(refused({part("rg", {{"ev\x1b[2Jil", 1}}), part("rh", {{"ev\x1b[2Jil", 2}})}));
    EXPECT_EQ(why.find('\x1b'), std::string::npos) << why;
    EXPECT_NE(why.find("\"ev\\u001b[2Jil\""), std::string::npos) << why;
    // A student or an assignment described differently.
    EXPECT_TRUE(refused({a, part("rd", {{"bob", 1}}, [](Gradebook& b) {
                             b.addStudent({"cid", "Cyd", ""});
                         })}));
    EXPECT_NE(why.find("the student cid"), std::string::npos) << why;
    EXPECT_TRUE(refused({a, part("re", {{"bob", 1}}, [](Gradebook& b) {
                             b.registerAssignment({"lab", "Lab", 100, 20, "r2", ""});
                         })}));
    EXPECT_NE(why.find("the assignment lab"), std::string::npos) << why;
    // A part changed behind its log's back.
    const std::string tampered = part("rf", {{"bob", 10}});
    {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(tampered.c_str(), &db), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(db, "UPDATE grades SET score = 100", nullptr, nullptr, nullptr),
                  SQLITE_OK);
        sqlite3_close(db);
    }
    EXPECT_TRUE(refused({a, tampered}));
    EXPECT_NE(why.find("does not verify"), std::string::npos) << why;
    // A file that is not a gradebook.
    const std::string notes = freshPath("notes");
    {
        std::FILE* f = std::fopen(notes.c_str(), "w");
        ASSERT_TRUE(f);
        std::fputs("these are my notes, not a database\n", f);
        std::fclose(f);
    }
    EXPECT_TRUE(refused({a, notes}));
    EXPECT_NE(why.find("merge-notes.sqlite"), std::string::npos) << why;
    // Another program's database is refused and left as it was (no tables added).
    const std::string other = freshPath("other");
    {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(other.c_str(), &db), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE recipes(name TEXT)", nullptr, nullptr, nullptr),
                  SQLITE_OK);
        sqlite3_close(db);
    }
    EXPECT_TRUE(refused({a, other}));
    EXPECT_NE(why.find("not a FunctionLab gradebook"), std::string::npos) << why;
    {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(other.c_str(), &db), SQLITE_OK);
        sqlite3_stmt* st = nullptr;
        ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT count(*) FROM sqlite_master", -1, &st, nullptr),
                  SQLITE_OK);
        ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
        EXPECT_EQ(sqlite3_column_int(st, 0), 1); // recipes alone
        sqlite3_finalize(st);
        sqlite3_close(db);
    }
    // No part, a missing one, one named twice, an output that exists.
    EXPECT_TRUE(refused({}));
    EXPECT_TRUE(refused({a, freshPath("missing")}));
    EXPECT_TRUE(refused({a, a}));
    std::string kept;
    EXPECT_FALSE(mergeGradebooks({a}, a, &kept));
    EXPECT_NE(kept.find("exists"), std::string::npos);
}
