// The gradebook: a real SQLite file — roster import, grades with their
// results, resuming, manual scores and overrides, the audit chain that shows
// tampering, schema versions — and the exports an LMS reads.
#include "grading/grade_export.h"
#include "grading/gradebook.h"

#include <gtest/gtest.h>

#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fl::grading;

namespace {

std::string freshPath(const std::string& name) {
    const auto p = std::filesystem::path(testing::TempDir()) / (name + ".sqlite");
    for (const char* suffix : {"", "-wal", "-shm"})
        std::filesystem::remove(p.string() + suffix);
    return p.string();
}

GradeRecord grade(const std::string& student, const std::string& hash, double score) {
    GradeRecord g;
    g.student = student;
    g.assignment = "lab";
    g.contentHash = hash;
    g.submittedAt = "2026-11-20T10:00:00Z";
    g.checkerVersion = "1";
    g.rubricHash = "r1";
    g.gradable = true;
    g.score = score;
    g.maxScore = 100;
    g.gradedAt = "2026-11-23T10:00:00Z";
    g.requirements = {{"implicit",
                       RequirementKind::ImplicitSurface,
                       score > 0,
                       score,
                       100,
                       "=HYPERLINK(\"x\")",
                       {{"a.x3d", 3, 4}}}};
    return g;
}

AssignmentRecord lab() {
    return {"lab", "Lab, one", 100, 20, "r1", ""};
}

void raw(const std::string& path, const std::string& sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* error = nullptr;
    EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK)
        << (error ? error : "");
    sqlite3_free(error);
    sqlite3_close(db);
}

} // namespace

TEST(Gradebook, ARosterNameMayHoldALineBreak) {
    // An LMS export quotes a name with a line break in it: one student, not
    // two broken rows (the roster was once read line by line).
    Gradebook book(freshPath("roster-newline"));
    const auto problems = book.importRoster(
        "\xEF\xBB\xBFid,name\r\nalice,\"Alice\nLiddell\"\r\nbob,Bob\r\ncarol,\"Carol");
    ASSERT_EQ(problems.size(), 1u); // the unclosed quote, on the line it opens
    EXPECT_EQ(problems[0].line, 5);
    const auto students = book.students();
    ASSERT_EQ(students.size(), 2u);
    EXPECT_EQ(students[0].id, "alice");
    EXPECT_EQ(students[0].name, "Alice\nLiddell");
    EXPECT_EQ(students[1].id, "bob");
}

TEST(Gradebook, RosterGradesAndResultsRoundTrip) {
    const std::string path = freshPath("roundtrip");
    Gradebook book(path);
    EXPECT_EQ(book.schemaVersion(), kGradebookSchemaVersion);
    const auto problems = book.importRoster(
        "email,id,name\r\nalice@example.org,alice,\"Smith, Alice\"\n,bob,Bob \"B\"\n\n,,nobody\n");
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].line, 5);
    const auto students = book.students();
    ASSERT_EQ(students.size(), 2u);
    EXPECT_EQ(students[0].name, "Smith, Alice");
    EXPECT_EQ(students[0].email, "alice@example.org");
    book.registerAssignment(lab());
    book.recordGrade(grade("alice", "h1", 40));
    book.recordGrade(grade("alice", "h2", 90)); // a second submission: the newest counts
    book.recordGrade(grade("bob", "h3", 0));
    EXPECT_TRUE(book.hasGrade("alice", "lab", "h1", "1", "r1"));
    EXPECT_FALSE(book.hasGrade("alice", "lab", "h1", "2", "r1")) << "a new checker grades again";
    EXPECT_FALSE(book.hasGrade("alice", "lab", "h1", "1", "r2")) << "so does a new rubric";
    const auto latest = book.latestGrades("lab");
    ASSERT_EQ(latest.size(), 2u);
    EXPECT_EQ(latest[0].student, "alice");
    EXPECT_EQ(latest[0].score, 90);
    ASSERT_EQ(latest[0].requirements.size(), 1u);
    EXPECT_EQ(latest[0].requirements[0].locations, (std::vector<Location>{{"a.x3d", 3, 4}}));
    // A second connection reads what the first wrote (WAL).
    Gradebook reader(path);
    EXPECT_EQ(reader.latestGrades("lab").size(), 2u);
}

TEST(Gradebook, ManualScoresOverridesAndLateness) {
    Gradebook book(freshPath("final"));
    book.registerAssignment(lab());
    GradeRecord g = grade("carol", "h", 80);
    g.lateFactor = 0.9;
    book.recordGrade(g);
    EXPECT_DOUBLE_EQ(book.finalScore(book.latestGrades("lab")[0]), 72);
    book.setManualScore("carol", "lab", "fantasy", 10, "lovely", "ta");
    book.setManualScore("carol", "lab", "fantasy", 12, "lovelier", "ta"); // replaced
    book.setManualScore("carol", "lab", "explanation", 3, "", "ta");
    EXPECT_DOUBLE_EQ(book.finalScore(book.latestGrades("lab")[0]), 72 + 15);
    book.addOverride("carol", "lab", 95, "prof", "regraded by hand");
    EXPECT_DOUBLE_EQ(book.finalScore(book.latestGrades("lab")[0]), 95);
}

TEST(Gradebook, ANewerSchemaIsRefusedNotDamaged) {
    const std::string path = freshPath("newer");
    { Gradebook book(path); }
    raw(path, "PRAGMA user_version = 99");
    EXPECT_THROW(Gradebook{path}, fl::platform::SqliteError);
    EXPECT_THROW(Gradebook{"/nonexistent/folder/gb.sqlite"}, fl::platform::SqliteError);
}

TEST(GradeExport, FormulasAreEscapedAndQuotesDoubled) {
    EXPECT_EQ(csvCell("=1+1"), "'=1+1");
    EXPECT_EQ(csvCell("@SUM(A1)"), "'@SUM(A1)");
    EXPECT_EQ(csvCell("-2"), "'-2");
    EXPECT_EQ(csvCell("a,b"), "\"a,b\"");
    EXPECT_EQ(csvCell("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csvCell("plain"), "plain");
    Gradebook book(freshPath("export"));
    book.importRoster("id,name,email\nalice,\"=cmd|' /C calc'!A0\",a@example.org\n");
    book.registerAssignment(lab());
    book.recordGrade(grade("alice", "h", 50));
    const std::string csv = exportCsvText(book, lab(), ExportFormat::Csv);
    EXPECT_NE(csv.find("'=cmd"), std::string::npos) << csv;
    EXPECT_EQ(csv.find(",=cmd"), std::string::npos) << csv;
    const std::string canvas = exportCsvText(book, lab(), ExportFormat::Canvas);
    EXPECT_EQ(canvas.substr(0, canvas.find("\r\n")),
              "Student,ID,SIS User ID,SIS Login ID,Section,\"Lab, one (120)\"");
    const std::string moodle = exportCsvText(book, lab(), ExportFormat::Moodle);
    EXPECT_NE(moodle.find("alice,a@example.org,50"), std::string::npos) << moodle;
    const auto folder = std::filesystem::path(testing::TempDir()) / "gradescope";
    std::filesystem::remove_all(folder);
    exportGradescope(book, lab(), folder);
    std::ifstream in(folder / "alice" / "results.json");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("\"score\": 50"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("\"name\": \"implicit\""), std::string::npos);
}

// A gradebook written by schema 1 (no submission paths) is migrated on open,
// its grades kept.
TEST(Gradebook, SchemaOneIsMigrated) {
    const std::string path = freshPath("migrate");
    {
        Gradebook book(path);
        book.registerAssignment(lab());
        book.recordGrade(grade("ann", "h", 70));
    }
    // Back to what schema 1 wrote: no path or isolation column, user_version 1.
    raw(path, "ALTER TABLE submissions DROP COLUMN path; ALTER TABLE grades DROP COLUMN "
              "isolation; DROP TABLE events; DROP TABLE signed_heads; PRAGMA user_version = 1");
    Gradebook book(path);
    EXPECT_EQ(book.schemaVersion(), kGradebookSchemaVersion);
    const auto grades = book.latestGrades("lab");
    ASSERT_EQ(grades.size(), 1u);
    EXPECT_EQ(grades[0].score, 70);
    EXPECT_EQ(grades[0].path, "");
    EXPECT_EQ(grades[0].isolation, "");
    EXPECT_TRUE(book.verify().intact) << book.verify().problem;
}
