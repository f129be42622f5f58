#pragma once
// The gradebook: one SQLite file per course (WAL, so the grading view reads
// while a batch writes). Students (a roster CSV imports them), assignments,
// submissions (content hash, time, lateness), the checker's results per
// requirement, manual rubric scores with comments, overrides (who, when,
// why) — and an audit chain: every grade row records the submission's hash,
// the checker version and the rubric hash, and the hash of the row before
// it, so a row changed behind the gradebook's back shows.
#include "requirement.h"
#include "sqlite_database.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::grading {

inline constexpr int kGradebookSchemaVersion = 3;

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

struct RosterProblem {
    int line = 0;
    std::string message;
};

class Gradebook {
  public:
    // Opens (creating and migrating to kGradebookSchemaVersion) the file.
    explicit Gradebook(const std::string& path);

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

    struct ChainCheck {
        bool intact = true;
        std::int64_t firstBadRow = 0; // grades.id where the chain breaks
        std::size_t rows = 0;
    };
    ChainCheck verifyChain();

  private:
    void migrate();
    std::string rowHash(const GradeRecord& g, const std::string& previous);

    SqliteDatabase db_;
};

// An ISO 8601 UTC time of now ("2026-11-23T22:44:11Z").
std::string utcNow();

} // namespace fl::grading
