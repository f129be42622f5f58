#pragma once
// The gradebook: one SQLite file per course (WAL, so the grading view reads
// while a batch writes). Students (a roster CSV imports them), assignments,
// submissions (content hash, time, lateness), the checker's results per
// requirement, manual rubric scores with comments, overrides (who, when,
// why).
//
// The audit trail (issue 27 §3): every change — an assignment, a student, a
// grade with its results, a manual score, an override — is first an entry
// of one append-only log (`events`), each holding the hash of the one
// before it, and only then applied to the tables the queries read. So the
// tables can always be rebuilt from the log, and verify() finds an entry
// changed, inserted or deleted (the chain breaks) or a table changed behind
// the log's back (the rebuild differs). The instructor's key (signing.h,
// kept outside the gradebook) signs the log's head; a signed head in an
// export, or the public key, finds the tail deleted or the whole log
// re-hashed by someone without the key.
#include "platform/sqlite_database.h"
#include "requirement.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::grading {

inline constexpr int kGradebookSchemaVersion = 4;

struct Student {
    std::string id; // the roster's (a login, a number); submissions are named by it
    std::string name;
    std::string email;
};

struct AssignmentRecord {
    std::string id;
    std::string title;
    double maxAutomatic = 0;
    double maxManual = 0;
    std::string rubricHash; // of the requirements and rubric the grades were made against
    std::string due;        // ISO 8601 UTC, or empty
};

struct GradeRecord {
    std::string student;
    std::string assignment;
    std::string contentHash; // of the submission (submission_hash.h)
    std::string submittedAt; // ISO 8601 UTC
    std::string path;        // where the batch found it (schema 2)
    double hoursLate = 0;
    std::string checkerVersion;
    std::string rubricHash;
    bool gradable = false;
    double score = 0, maxScore = 0; // automatic, before the late factor
    double lateFactor = 1;
    std::string gradedAt;
    std::vector<RequirementResult> requirements;
    std::string diagnostics; // why not gradable, as text
    // What the checker ran under (schema 3): "bubblewrap", "syscall filter",
    // "limits only"; empty when not run by a batch (or before schema 3).
    std::string isolation;
};

struct ManualScore {
    std::string item;
    double points = 0;
    std::string comment;
    std::string grader;
    std::string at;
};

// The newest entry of the log: what a signature covers.
struct LogHead {
    std::int64_t seq = 0; // entries are numbered 1, 2, 3 ... (0: an empty log)
    std::string hash;     // 64 hex digits
};

// A head signed with an instructor's key.
struct SignedHead {
    LogHead head;
    std::string publicKey; // hex
    std::string signature; // hex
    std::string at;
};

// One entry of the log as written: grade merge copies the shards' entries.
struct LogEntry {
    std::int64_t seq = 0;
    std::string at, kind, payload, hash;
};

// What verify() found.
struct GradebookCheck {
    bool intact = true;        // the log's chain holds and the tables are what it says
    std::size_t entries = 0;   // in the log
    LogHead head;              // its newest entry
    std::int64_t badEntry = 0; // the first entry that breaks the chain (0: none, or a table)
    std::string problem;       // what changed and where, for a person; empty when intact
    // Signatures: the newest head signed with the key asked for (or, without
    // one, with any key), and how many entries came after it.
    std::optional<SignedHead> signedHead;
    bool signatureHolds = false;
    std::size_t unsignedEntries = 0;
};

struct VerifyOptions {
    std::optional<std::string> head;      // a head hash from an export: must be in the log
    std::optional<std::string> publicKey; // hex: a head signed with it must hold
};

// The text a head's signature covers.
std::string headMessage(const LogHead& head);

struct RosterProblem {
    int line = 0;
    std::string message;
};

class Gradebook {
  public:
    // Opens (creating and migrating to kGradebookSchemaVersion) the file.
    explicit Gradebook(const std::string& path);
    // Opens an existing gradebook of this schema without writing to it (the
    // parts grade merge reads: files from others). A file that is not such a
    // gradebook — another database, an older gradebook, a newer one — is
    // refused (SqliteError), never changed.
    enum class ReadOnly { Yes };
    Gradebook(const std::string& path, ReadOnly);

    int schemaVersion();

    // "id,name,email" with a header line; quoted fields as spreadsheets write them.
    std::vector<RosterProblem> importRoster(const std::string& csv);
    void addStudent(const Student& s); // or update its name and email
    std::vector<Student> students();

    void registerAssignment(const AssignmentRecord& a);
    std::vector<AssignmentRecord> assignments();

    // Already graded: this student's submission with this content, by this
    // checker against this rubric (a batch run again skips it).
    bool hasGrade(const std::string& student, const std::string& assignment,
                  const std::string& contentHash, const std::string& checkerVersion,
                  const std::string& rubricHash);
    // One transaction: the submission, the grade row (chained) and its results.
    void recordGrade(const GradeRecord& g);
    // Each student's newest grade for the assignment, by student id.
    std::vector<GradeRecord> latestGrades(const std::string& assignment);

    void setManualScore(const std::string& student, const std::string& assignment,
                        const std::string& item, double points, const std::string& comment,
                        const std::string& grader);
    // Manual points per student for the assignment.
    double manualPoints(const std::string& student, const std::string& assignment);
    std::vector<ManualScore> manualScores(const std::string& student,
                                          const std::string& assignment);
    void addOverride(const std::string& student, const std::string& assignment, double score,
                     const std::string& who, const std::string& why);
    std::optional<double> overrideScore(const std::string& student, const std::string& assignment);

    // The final score: the override if any, else automatic x late factor + manual.
    double finalScore(const GradeRecord& g);

    // The log and its signatures (gradebook_log.cpp).
    LogHead head();
    std::size_t entries();
    // Signs the head with `key`, keeps the signature, and returns it.
    SignedHead signHead(const struct SigningKey& key);
    std::vector<SignedHead> signedHeads(); // newest first
    GradebookCheck verify(const VerifyOptions& options = {});
    // The log, oldest first.
    std::vector<LogEntry> logEntries();
    // Entries of other gradebooks' logs (grade merge): each appended with
    // its own time, kind and payload, chained into this log, and applied;
    // one transaction. A "merge" entry (what was merged, see
    // gradebook_merge.h) changes no table.
    void appendFrom(const std::vector<LogEntry>& entries);

  private:
    void migrate();
    void importStateIntoLog(); // schema 4: the state of an older gradebook becomes its log
    // Every change: the entry first, then the tables (one transaction).
    void change(std::string_view kind, const std::string& payload);
    void appendEntry(std::string_view kind, const std::string& payload);
    void appendEntry(std::string_view kind, const std::string& payload, const std::string& at);
    void apply(std::string_view kind, const std::string& payload);
    void applyStudent(const Student& s);
    void applyAssignment(const AssignmentRecord& a);
    void applyGrade(const GradeRecord& g);
    void applyManualScore(const std::string& student, const std::string& assignment,
                          const ManualScore& m);
    void applyOverride(const std::string& student, const std::string& assignment, double score,
                       const std::string& who, const std::string& why, const std::string& at);
    std::string rowHash(const GradeRecord& g, const std::string& previous);

    platform::SqliteDatabase db_;
};

// Removes a gradebook file and SQLite's files beside it (-wal, -shm,
// -journal); false when one is there and cannot be removed.
bool removeGradebookFiles(const std::string& path);

// An ISO 8601 UTC time of now ("2026-11-23T22:44:11Z").
std::string utcNow();

} // namespace fl::grading
