// The gradebook's audit trail (issue 27 §3): every grade-affecting change is
// an entry of one append-only, hash-chained log, the tables are what the log
// rebuilds, and the instructor's key signs its head. Each way someone with
// the file could tamper — change a table row (a grade, a manual score, an
// override), change, insert or delete an entry, delete the tail, hash the
// whole log again without the key — is found, and says where.
#include "grading/gradebook.h"
#include "grading/gradebook_log.h"
#include "grading/signing.h"

#include <gtest/gtest.h>

#include <sqlite3.h>

#include <filesystem>

using namespace fl::grading;

namespace {

std::string freshPath(const std::string& name) {
    const auto p = std::filesystem::path(testing::TempDir()) / ("audit-" + name + ".sqlite");
    for (const char* suffix : {"", "-wal", "-shm"})
        std::filesystem::remove(p.string() + suffix);
    return p.string();
}

void raw(const std::string& path, const std::string& sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* error = nullptr;
    EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK)
        << (error ? error : "") << "\n"
        << sql;
    sqlite3_free(error);
    sqlite3_close(db);
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
    g.isolation = "bubblewrap";
    g.requirements = {
        {"implicit", RequirementKind::ImplicitSurface, true, score, 100, "ok", {{"a.x3d", 3, 4}}}};
    return g;
}

// A class: an assignment, three students, three grades, a manual score and
// an override — nine entries — its head signed.
struct Course {
    std::string path;
    SigningKey key = newSigningKey();
    LogHead signedAt;
};

Course makeCourse(const std::string& name) {
    Course c{freshPath(name), newSigningKey(), {}};
    Gradebook book(c.path);
    book.registerAssignment({"lab", "Lab", 100, 20, "r1", ""});
    book.importRoster("id,name\nann,Ann\nbob,Bob\ncid,Cid\n");
    book.recordGrade(grade("ann", 90));
    book.recordGrade(grade("bob", 60));
    book.recordGrade(grade("cid", 40));
    book.setManualScore("bob", "lab", "style", 5, "neat", "ta");
    book.addOverride("cid", "lab", 70, "prof", "regraded by hand");
    c.signedAt = book.signHead(c.key).head;
    return c;
}

GradebookCheck verified(const std::string& path, VerifyOptions o = {}) {
    Gradebook book(path);
    return book.verify(o);
}

} // namespace

TEST(AuditLog, EveryChangeIsAnEntryAndTheSignedHeadHolds) {
    const Course c = makeCourse("good");
    const GradebookCheck k = verified(c.path, {std::nullopt, c.key.publicHex});
    EXPECT_TRUE(k.intact) << k.problem;
    EXPECT_EQ(k.entries, 9u); // assignment, 3 students, 3 grades, manual score, override
    EXPECT_EQ(k.head.seq, 9);
    ASSERT_TRUE(k.signedHead);
    EXPECT_TRUE(k.signatureHolds);
    EXPECT_EQ(k.signedHead->head.hash, c.signedAt.hash);
    EXPECT_EQ(k.unsignedEntries, 0u);
    // An unchanged assignment or student registered again adds nothing.
    Gradebook book(c.path);
    book.registerAssignment({"lab", "Lab", 100, 20, "r1", ""});
    book.addStudent({"ann", "Ann", ""});
    EXPECT_EQ(book.entries(), 9u);
    book.addOverride("ann", "lab", 95, "prof", "bonus");
    const GradebookCheck later = book.verify({std::nullopt, c.key.publicHex});
    EXPECT_TRUE(later.intact);
    EXPECT_EQ(later.unsignedEntries, 1u); // written after the last signature
}

TEST(AuditLog, ATableChangedBehindTheLogsBackShows) {
    for (const auto& [sql, words] : std::vector<std::pair<std::string, std::string>>{
             {"UPDATE grades SET score = 100 WHERE id = 2", "grades, row 2 (bob"},
             {"UPDATE results SET points = 100", "results"},
             {"UPDATE overrides SET score = 100", "overrides, row 1 (cid"},
             {"UPDATE manual_scores SET points = 20", "manual_scores"},
             {"DELETE FROM overrides", "overrides: a row the log made is missing"},
             {"INSERT INTO overrides(student_id, assignment_id, score, who, why, at) VALUES "
              "('ann', 'lab', 100, 'x', 'y', 'z')",
              "overrides: a row that no entry of the log made"},
             {"UPDATE students SET name = 'Eve' WHERE id = 'ann'", "students"}}) {
        const Course c = makeCourse("table");
        raw(c.path, sql);
        const GradebookCheck k = verified(c.path);
        EXPECT_FALSE(k.intact) << sql;
        EXPECT_NE(k.problem.find(words), std::string::npos) << sql << ": " << k.problem;
        EXPECT_NE(k.problem.find("behind the log's back"), std::string::npos) << k.problem;
    }
}

TEST(AuditLog, TheLogRefusesChangesAndDeletionsItself) {
    const Course c = makeCourse("append-only");
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(c.path.c_str(), &db), SQLITE_OK);
    EXPECT_NE(sqlite3_exec(db, "UPDATE events SET payload = '{}' WHERE seq = 5", nullptr, nullptr,
                           nullptr),
              SQLITE_OK);
    EXPECT_NE(sqlite3_exec(db, "DELETE FROM events WHERE seq = 9", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
    EXPECT_TRUE(verified(c.path).intact);
}

// Past the triggers (anyone with sqlite3 can drop them), the chain shows.
const char* kDropTriggers =
    "DROP TRIGGER events_are_never_changed; DROP TRIGGER events_are_never_deleted;";

TEST(AuditLog, AChangedEntryShows) {
    const Course c = makeCourse("changed");
    raw(c.path, std::string(kDropTriggers) +
                    "UPDATE events SET payload = replace(payload, '\"score\":60', "
                    "'\"score\":100') WHERE seq = 6");
    const GradebookCheck k = verified(c.path);
    EXPECT_FALSE(k.intact);
    EXPECT_EQ(k.badEntry, 6);
    EXPECT_NE(k.problem.find("entry 6 (a grade of bob for lab"), std::string::npos) << k.problem;
    EXPECT_NE(k.problem.find("was changed"), std::string::npos);
}

TEST(AuditLog, AnEntryDeletedInTheMiddleShows) {
    const Course c = makeCourse("deleted");
    raw(c.path, std::string(kDropTriggers) + "DELETE FROM events WHERE seq = 5");
    const GradebookCheck k = verified(c.path);
    EXPECT_FALSE(k.intact);
    EXPECT_EQ(k.badEntry, 5);
    EXPECT_NE(k.problem.find("entry 5 is missing"), std::string::npos) << k.problem;
}

TEST(AuditLog, AnEntryInsertedInTheMiddleShows) {
    // Room is made by moving the later entries up one; the new one is
    // chained to its predecessor, but its successor is not chained to it.
    const Course c = makeCourse("inserted");
    raw(c.path, std::string(kDropTriggers) +
                    "UPDATE events SET seq = seq + 100 WHERE seq >= 7;"
                    "UPDATE events SET seq = seq - 99 WHERE seq >= 107;"
                    "INSERT INTO events(seq, at, kind, payload, previous_hash, hash) SELECT 7, at, "
                    "kind, payload, hash, hash FROM events WHERE seq = 6;");
    const GradebookCheck k = verified(c.path);
    EXPECT_FALSE(k.intact);
    EXPECT_TRUE(k.badEntry == 7 || k.badEntry == 8) << k.problem;
}

TEST(AuditLog, ADeletedTailShowsAgainstAnExportsHeadOrItsSignature) {
    // The last two entries (the manual score and the override) and what
    // they made are deleted: chain and tables agree with what is left...
    const Course c = makeCourse("tail");
    raw(c.path, std::string(kDropTriggers) +
                    "DELETE FROM events WHERE seq >= 8; DELETE FROM overrides; DELETE FROM "
                    "manual_scores;");
    // ... but the head an export carried is not in the log any more,
    const GradebookCheck withHead = verified(c.path, {c.signedAt.hash, std::nullopt});
    EXPECT_FALSE(withHead.intact);
    EXPECT_NE(withHead.problem.find("is not in the log"), std::string::npos) << withHead.problem;
    // and the signed head is past the log's end.
    const GradebookCheck withKey = verified(c.path, {std::nullopt, c.key.publicHex});
    EXPECT_FALSE(withKey.intact);
    EXPECT_NE(withKey.problem.find("its last entries were deleted"), std::string::npos)
        << withKey.problem;
}

TEST(AuditLog, HashingTheLogAgainWithoutTheKeyShows) {
    // The forger writes the whole gradebook again, bob's 60 made 100: every
    // entry chained and every table rebuilt from them — all consistent. The
    // instructor's signatures are kept; they cannot be made anew.
    const Course c = makeCourse("original");
    const std::string forged = freshPath("forged");
    {
        Gradebook book(forged);
        book.registerAssignment({"lab", "Lab", 100, 20, "r1", ""});
        book.importRoster("id,name\nann,Ann\nbob,Bob\ncid,Cid\n");
        book.recordGrade(grade("ann", 90));
        book.recordGrade(grade("bob", 100));
        book.recordGrade(grade("cid", 40));
        book.setManualScore("bob", "lab", "style", 5, "neat", "ta");
        book.addOverride("cid", "lab", 70, "prof", "regraded by hand");
    }
    raw(forged, "ATTACH '" + c.path +
                    "' AS original; INSERT INTO signed_heads SELECT * FROM "
                    "original.signed_heads;");
    // The kept signature no longer covers the log (with the key or without).
    for (const std::optional<std::string>& key :
         {std::optional<std::string>{}, std::optional<std::string>{c.key.publicHex}}) {
        const GradebookCheck k = verified(forged, {std::nullopt, key});
        EXPECT_FALSE(k.intact);
        EXPECT_NE(k.problem.find("no longer the log's"), std::string::npos) << k.problem;
    }
    // Removing the signatures: the forgery then holds together on its own
    // (nothing in the file can tell), but the instructor's key finds none.
    raw(forged, "DELETE FROM signed_heads");
    EXPECT_TRUE(verified(forged).intact);
    const GradebookCheck none = verified(forged, {std::nullopt, c.key.publicHex});
    EXPECT_FALSE(none.intact);
    EXPECT_NE(none.problem.find("no head of the log is signed with that key"), std::string::npos)
        << none.problem;
}

TEST(AuditLog, AnOlderGradebookGetsItsStateAsItsLog) {
    const std::string path = freshPath("schema3");
    {
        Gradebook book(path);
        book.registerAssignment({"lab", "Lab", 100, 20, "r1", ""});
        book.recordGrade(grade("ann", 90));
        book.addOverride("ann", "lab", 95, "prof", "why");
    }
    // Back to schema 3: no log.
    raw(path, "DROP TABLE events; DROP TABLE signed_heads; PRAGMA user_version = 3");
    Gradebook book(path);
    EXPECT_EQ(book.schemaVersion(), kGradebookSchemaVersion);
    EXPECT_EQ(book.entries(), 4u); // assignment, student, grade, override
    const GradebookCheck k = book.verify();
    EXPECT_TRUE(k.intact) << k.problem;
}

TEST(Signing, KeysSignAndOthersDoNot) {
    const SigningKey a = newSigningKey(), b = newSigningKey();
    const std::string signature = sign(a, "head 9");
    EXPECT_TRUE(signatureHolds(a.publicHex, "head 9", signature));
    EXPECT_FALSE(signatureHolds(a.publicHex, "head 8", signature));
    EXPECT_FALSE(signatureHolds(b.publicHex, "head 9", signature));
    EXPECT_FALSE(signatureHolds("zz", "head 9", signature));
    const std::string file =
        (std::filesystem::path(testing::TempDir()) / "grading-test.key").string();
    std::filesystem::remove(file);
    std::filesystem::remove(file + ".pub");
    std::string why;
    ASSERT_TRUE(writeSigningKey(a, file, why)) << why;
    EXPECT_FALSE(writeSigningKey(b, file, why)); // never overwritten
    const auto back = readSigningKey(file, why);
    ASSERT_TRUE(back) << why;
    EXPECT_EQ(back->publicHex, a.publicHex);
    EXPECT_EQ(readPublicKey(file + ".pub", why).value_or(""), a.publicHex);
    std::filesystem::permissions(file, std::filesystem::perms::group_read,
                                 std::filesystem::perm_options::add);
    EXPECT_FALSE(readSigningKey(file, why)); // a secret readable by others is refused
}
