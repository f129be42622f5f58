#include "gradebook.h"

#include "gradebook_log.h"
#include "platform/csv.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <filesystem>
#include <sstream>

namespace fl::grading {
namespace {

// Version 1. A later version adds a migration step; the file records which
// it has in PRAGMA user_version.
const char* kSchemaV1 = R"sql(
CREATE TABLE students (
  id TEXT PRIMARY KEY,
  name TEXT NOT NULL DEFAULT '',
  email TEXT NOT NULL DEFAULT ''
);
CREATE TABLE assignments (
  id TEXT PRIMARY KEY,
  title TEXT NOT NULL,
  max_automatic REAL NOT NULL,
  max_manual REAL NOT NULL,
  rubric_hash TEXT NOT NULL,
  due TEXT NOT NULL DEFAULT ''
);
CREATE TABLE submissions (
  id INTEGER PRIMARY KEY,
  student_id TEXT NOT NULL REFERENCES students(id),
  assignment_id TEXT NOT NULL REFERENCES assignments(id),
  content_hash TEXT NOT NULL,
  submitted_at TEXT NOT NULL,
  hours_late REAL NOT NULL DEFAULT 0,
  UNIQUE (student_id, assignment_id, content_hash)
);
CREATE TABLE grades (
  id INTEGER PRIMARY KEY,
  submission_id INTEGER NOT NULL REFERENCES submissions(id),
  checker_version TEXT NOT NULL,
  rubric_hash TEXT NOT NULL,
  gradable INTEGER NOT NULL,
  score REAL NOT NULL,
  max_score REAL NOT NULL,
  late_factor REAL NOT NULL,
  graded_at TEXT NOT NULL,
  diagnostics TEXT NOT NULL DEFAULT '',
  previous_hash TEXT NOT NULL,
  row_hash TEXT NOT NULL
);
CREATE TABLE results (
  grade_id INTEGER NOT NULL REFERENCES grades(id),
  requirement_id TEXT NOT NULL,
  met INTEGER NOT NULL,
  points REAL NOT NULL,
  max_points REAL NOT NULL,
  evidence TEXT NOT NULL,
  locations TEXT NOT NULL,
  PRIMARY KEY (grade_id, requirement_id)
);
CREATE TABLE manual_scores (
  student_id TEXT NOT NULL REFERENCES students(id),
  assignment_id TEXT NOT NULL REFERENCES assignments(id),
  item_id TEXT NOT NULL,
  points REAL NOT NULL,
  comment TEXT NOT NULL DEFAULT '',
  grader TEXT NOT NULL,
  at TEXT NOT NULL,
  PRIMARY KEY (student_id, assignment_id, item_id)
);
CREATE TABLE overrides (
  id INTEGER PRIMARY KEY,
  student_id TEXT NOT NULL REFERENCES students(id),
  assignment_id TEXT NOT NULL REFERENCES assignments(id),
  score REAL NOT NULL,
  who TEXT NOT NULL,
  why TEXT NOT NULL,
  at TEXT NOT NULL
);
CREATE INDEX grades_by_submission ON grades(submission_id);
)sql";

std::string trimmed(std::string s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string{} : s.substr(b, e - b + 1);
}

} // namespace

std::string utcNow() {
    return QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
}

bool removeGradebookFiles(const std::string& path) {
    bool removed = true;
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
        std::error_code ec;
        std::filesystem::remove(path + suffix, ec);
        removed = removed && !ec;
    }
    return removed;
}

Gradebook::Gradebook(const std::string& path) : db_(path) {
    migrate();
}

Gradebook::Gradebook(const std::string& path, ReadOnly) : db_(path, true) {
    const int version = schemaVersion();
    if (version == kGradebookSchemaVersion) return;
    throw platform::SqliteError(
        version == 0 ? "not a FunctionLab gradebook"
        : version > kGradebookSchemaVersion
            ? "written by a newer FunctionLab (schema " + std::to_string(version) + ")"
            : "an older gradebook (schema " + std::to_string(version) +
                  "): bring it up to date first with functionlab grade verify");
}

int Gradebook::schemaVersion() {
    auto s = db_.prepare("PRAGMA user_version");
    return s.step() ? int(s.integer(0)) : 0;
}

void Gradebook::migrate() {
    const int version = schemaVersion();
    if (version > kGradebookSchemaVersion)
        throw platform::SqliteError("this gradebook was written by a newer FunctionLab (schema " +
                                    std::to_string(version) + "; this one reads up to " +
                                    std::to_string(kGradebookSchemaVersion) + ")");
    if (version < 1) {
        platform::SqliteDatabase::Transaction t(db_);
        db_.execute(kSchemaV1);
        db_.execute("PRAGMA user_version = 1");
        t.commit();
    }
    if (schemaVersion() < 2) { // 2: where each submission was found (grade similar reads it)
        platform::SqliteDatabase::Transaction t(db_);
        db_.execute("ALTER TABLE submissions ADD COLUMN path TEXT NOT NULL DEFAULT ''");
        db_.execute("PRAGMA user_version = 2");
        t.commit();
    }
    if (schemaVersion() < 3) { // 3: the isolation each check ran under
        platform::SqliteDatabase::Transaction t(db_);
        db_.execute("ALTER TABLE grades ADD COLUMN isolation TEXT NOT NULL DEFAULT ''");
        db_.execute("PRAGMA user_version = 3");
        t.commit();
    }
    if (schemaVersion() < 4) { // 4: the log of every change, and signed heads
        platform::SqliteDatabase::Transaction t(db_);
        db_.execute(kLogSchema);
        importStateIntoLog();
        db_.execute("PRAGMA user_version = 4");
        t.commit();
    }
}

std::vector<RosterProblem> Gradebook::importRoster(const std::string& csv) {
    std::vector<RosterProblem> problems;
    const platform::CsvText text = platform::readCsv(csv);
    int idColumn = -1, nameColumn = -1, emailColumn = -1;
    platform::SqliteDatabase::Transaction t(db_);
    for (const platform::CsvRecord& record : text.records) {
        const std::vector<std::string>& fields = record.fields;
        bool blank = true;
        for (const std::string& f : fields)
            blank = blank && trimmed(f).empty();
        if (blank) continue;
        if (idColumn < 0) { // the header names the columns
            for (std::size_t i = 0; i < fields.size(); ++i) {
                const std::string f = trimmed(fields[i]);
                if (f == "id" || f == "student" || f == "login") idColumn = int(i);
                if (f == "name") nameColumn = int(i);
                if (f == "email") emailColumn = int(i);
            }
            if (idColumn < 0) {
                problems.push_back({record.line, "the first line must name the columns, one of "
                                                 "them id (e.g. id,name,email)"});
                return problems;
            }
            continue;
        }
        auto field = [&](int c) {
            return c >= 0 && std::size_t(c) < fields.size() ? trimmed(fields[std::size_t(c)])
                                                            : std::string{};
        };
        Student s{field(idColumn), field(nameColumn), field(emailColumn)};
        if (s.id.empty()) {
            problems.push_back({record.line, "no id"});
            continue;
        }
        addStudent(s);
    }
    if (!text.error.empty()) problems.push_back({text.errorLine, text.error});
    t.commit();
    return problems;
}

void Gradebook::addStudent(const Student& s) {
    // What the row would become (an empty name or email keeps the old one):
    // no entry when nothing changes.
    auto now = db_.prepare("SELECT name, email FROM students WHERE id = ?1");
    now.bind(1, s.id);
    if (now.step() && (s.name.empty() || s.name == now.text(0)) &&
        (s.email.empty() || s.email == now.text(1)))
        return;
    change("student", studentPayload(s));
}

void Gradebook::applyStudent(const Student& s) {
    db_.prepare("INSERT INTO students(id, name, email) VALUES(?1, ?2, ?3) "
                "ON CONFLICT(id) DO UPDATE SET name = CASE WHEN ?2 = '' THEN name ELSE ?2 END, "
                "email = CASE WHEN ?3 = '' THEN email ELSE ?3 END")
        .bind(1, s.id)
        .bind(2, s.name)
        .bind(3, s.email)
        .run();
}

std::vector<Student> Gradebook::students() {
    std::vector<Student> out;
    auto s = db_.prepare("SELECT id, name, email FROM students ORDER BY id");
    while (s.step())
        out.push_back({s.text(0), s.text(1), s.text(2)});
    return out;
}

void Gradebook::registerAssignment(const AssignmentRecord& a) {
    for (const AssignmentRecord& known : assignments()) // every batch registers it again
        if (known.id == a.id && known.title == a.title && known.maxAutomatic == a.maxAutomatic &&
            known.maxManual == a.maxManual && known.rubricHash == a.rubricHash &&
            known.due == a.due)
            return;
    change("assignment", assignmentPayload(a));
}

void Gradebook::applyAssignment(const AssignmentRecord& a) {
    db_.prepare("INSERT INTO assignments(id, title, max_automatic, max_manual, rubric_hash, due) "
                "VALUES(?1, ?2, ?3, ?4, ?5, ?6) ON CONFLICT(id) DO UPDATE SET title = ?2, "
                "max_automatic = ?3, max_manual = ?4, rubric_hash = ?5, due = ?6")
        .bind(1, a.id)
        .bind(2, a.title)
        .bind(3, a.maxAutomatic)
        .bind(4, a.maxManual)
        .bind(5, a.rubricHash)
        .bind(6, a.due)
        .run();
}

std::vector<AssignmentRecord> Gradebook::assignments() {
    std::vector<AssignmentRecord> out;
    auto s = db_.prepare("SELECT id, title, max_automatic, max_manual, rubric_hash, due FROM "
                         "assignments ORDER BY id");
    while (s.step())
        out.push_back({s.text(0), s.text(1), s.number(2), s.number(3), s.text(4), s.text(5)});
    return out;
}

bool Gradebook::hasGrade(const std::string& student, const std::string& assignment,
                         const std::string& contentHash, const std::string& checkerVersion,
                         const std::string& rubricHash) {
    auto s = db_.prepare("SELECT 1 FROM grades g JOIN submissions s ON g.submission_id = s.id "
                         "WHERE s.student_id = ?1 AND s.assignment_id = ?2 AND s.content_hash = "
                         "?3 AND g.checker_version = ?4 AND g.rubric_hash = ?5 LIMIT 1");
    s.bind(1, student).bind(2, assignment).bind(3, contentHash).bind(4, checkerVersion);
    s.bind(5, rubricHash);
    return s.step();
}

std::string Gradebook::rowHash(const GradeRecord& g, const std::string& previous) {
    std::ostringstream row;
    row.precision(17);
    row << previous << '\x1f' << g.student << '\x1f' << g.assignment << '\x1f' << g.contentHash
        << '\x1f' << g.checkerVersion << '\x1f' << g.rubricHash << '\x1f' << g.gradable << '\x1f'
        << g.score << '\x1f' << g.maxScore << '\x1f' << g.lateFactor << '\x1f' << g.gradedAt;
    if (!g.isolation.empty()) row << '\x1f' << g.isolation; // schema 3 (older rows: none)
    return sha256(row.str());
}

void Gradebook::recordGrade(const GradeRecord& g) {
    change("grade", gradePayload(g));
}

void Gradebook::applyGrade(const GradeRecord& g) {
    applyStudent({g.student, "", ""});
    db_.prepare("INSERT INTO submissions(student_id, assignment_id, content_hash, submitted_at, "
                "hours_late, path) VALUES(?1, ?2, ?3, ?4, ?5, ?6) ON CONFLICT DO UPDATE SET "
                "path = ?6")
        .bind(1, g.student)
        .bind(2, g.assignment)
        .bind(3, g.contentHash)
        .bind(4, g.submittedAt)
        .bind(5, g.hoursLate)
        .bind(6, g.path)
        .run();
    auto find = db_.prepare("SELECT id FROM submissions WHERE student_id = ?1 AND "
                            "assignment_id = ?2 AND content_hash = ?3");
    find.bind(1, g.student).bind(2, g.assignment).bind(3, g.contentHash);
    if (!find.step()) throw platform::SqliteError("the submission row vanished");
    const std::int64_t submission = find.integer(0);
    auto last = db_.prepare("SELECT row_hash FROM grades ORDER BY id DESC LIMIT 1");
    const std::string previous = last.step() ? last.text(0) : std::string(64, '0');
    db_.prepare("INSERT INTO grades(submission_id, checker_version, rubric_hash, gradable, score, "
                "max_score, late_factor, graded_at, diagnostics, previous_hash, row_hash, "
                "isolation) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)")
        .bind(1, submission)
        .bind(2, g.checkerVersion)
        .bind(3, g.rubricHash)
        .bind(4, std::int64_t(g.gradable))
        .bind(5, g.score)
        .bind(6, g.maxScore)
        .bind(7, g.lateFactor)
        .bind(8, g.gradedAt)
        .bind(9, g.diagnostics)
        .bind(10, previous)
        .bind(11, rowHash(g, previous))
        .bind(12, g.isolation)
        .run();
    const std::int64_t grade = db_.lastInsertId();
    auto result =
        db_.prepare("INSERT INTO results(grade_id, requirement_id, met, points, "
                    "max_points, evidence, locations) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    for (const RequirementResult& r : g.requirements) {
        result.bind(1, grade)
            .bind(2, r.id)
            .bind(3, std::int64_t(r.met))
            .bind(4, r.points)
            .bind(5, r.maxPoints)
            .bind(6, r.evidence)
            .bind(7, locationsJson(r.locations));
        result.run();
        result.reset();
    }
}

std::vector<GradeRecord> Gradebook::latestGrades(const std::string& assignment) {
    std::vector<GradeRecord> out;
    auto s = db_.prepare(
        "SELECT g.id, s.student_id, s.content_hash, s.submitted_at, s.hours_late, "
        "g.checker_version, g.rubric_hash, g.gradable, g.score, g.max_score, g.late_factor, "
        "g.graded_at, g.diagnostics, s.path, g.isolation FROM grades g JOIN submissions s ON "
        "g.submission_id = s.id "
        "WHERE s.assignment_id = ?1 AND g.id = (SELECT MAX(g2.id) FROM grades g2 JOIN "
        "submissions s2 ON g2.submission_id = s2.id WHERE s2.student_id = s.student_id AND "
        "s2.assignment_id = ?1) ORDER BY s.student_id");
    s.bind(1, assignment);
    auto results = db_.prepare("SELECT requirement_id, met, points, max_points, evidence, "
                               "locations FROM results WHERE grade_id = ?1 ORDER BY rowid");
    while (s.step()) {
        GradeRecord g;
        g.student = s.text(1);
        g.assignment = assignment;
        g.contentHash = s.text(2);
        g.submittedAt = s.text(3);
        g.hoursLate = s.number(4);
        g.checkerVersion = s.text(5);
        g.rubricHash = s.text(6);
        g.gradable = s.integer(7) != 0;
        g.score = s.number(8);
        g.maxScore = s.number(9);
        g.lateFactor = s.number(10);
        g.gradedAt = s.text(11);
        g.diagnostics = s.text(12);
        g.path = s.text(13);
        g.isolation = s.text(14);
        results.bind(1, s.integer(0));
        while (results.step()) {
            RequirementResult r;
            r.id = results.text(0);
            r.met = results.integer(1) != 0;
            r.points = results.number(2);
            r.maxPoints = results.number(3);
            r.evidence = results.text(4);
            r.locations = locationsOf(results.text(5));
            g.requirements.push_back(std::move(r));
        }
        results.reset();
        out.push_back(std::move(g));
    }
    return out;
}

void Gradebook::setManualScore(const std::string& student, const std::string& assignment,
                               const std::string& item, double points, const std::string& comment,
                               const std::string& grader) {
    change("manual-score",
           manualScorePayload(student, assignment, {item, points, comment, grader, utcNow()}));
}

void Gradebook::applyManualScore(const std::string& student, const std::string& assignment,
                                 const ManualScore& m) {
    db_.prepare("INSERT INTO manual_scores(student_id, assignment_id, item_id, points, comment, "
                "grader, at) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7) ON CONFLICT DO UPDATE SET "
                "points = ?4, comment = ?5, grader = ?6, at = ?7")
        .bind(1, student)
        .bind(2, assignment)
        .bind(3, m.item)
        .bind(4, m.points)
        .bind(5, m.comment)
        .bind(6, m.grader)
        .bind(7, m.at)
        .run();
}

double Gradebook::manualPoints(const std::string& student, const std::string& assignment) {
    auto s = db_.prepare("SELECT COALESCE(SUM(points), 0) FROM manual_scores WHERE student_id = "
                         "?1 AND assignment_id = ?2");
    s.bind(1, student).bind(2, assignment);
    return s.step() ? s.number(0) : 0;
}

std::vector<ManualScore> Gradebook::manualScores(const std::string& student,
                                                 const std::string& assignment) {
    std::vector<ManualScore> out;
    auto s = db_.prepare("SELECT item_id, points, comment, grader, at FROM manual_scores WHERE "
                         "student_id = ?1 AND assignment_id = ?2 ORDER BY item_id");
    s.bind(1, student).bind(2, assignment);
    while (s.step())
        out.push_back({s.text(0), s.number(1), s.text(2), s.text(3), s.text(4)});
    return out;
}

void Gradebook::addOverride(const std::string& student, const std::string& assignment, double score,
                            const std::string& who, const std::string& why) {
    change("override", overridePayload(student, assignment, score, who, why, utcNow()));
}

void Gradebook::applyOverride(const std::string& student, const std::string& assignment,
                              double score, const std::string& who, const std::string& why,
                              const std::string& at) {
    db_.prepare("INSERT INTO overrides(student_id, assignment_id, score, who, why, at) "
                "VALUES(?1, ?2, ?3, ?4, ?5, ?6)")
        .bind(1, student)
        .bind(2, assignment)
        .bind(3, score)
        .bind(4, who)
        .bind(5, why)
        .bind(6, at)
        .run();
}

std::optional<double> Gradebook::overrideScore(const std::string& student,
                                               const std::string& assignment) {
    auto s = db_.prepare("SELECT score FROM overrides WHERE student_id = ?1 AND assignment_id = "
                         "?2 ORDER BY id DESC LIMIT 1");
    s.bind(1, student).bind(2, assignment);
    if (s.step()) return s.number(0);
    return std::nullopt;
}

double Gradebook::finalScore(const GradeRecord& g) {
    if (auto o = overrideScore(g.student, g.assignment)) return *o;
    return g.score * g.lateFactor + manualPoints(g.student, g.assignment);
}

} // namespace fl::grading
