// The gradebook's log: every change an entry first (change()), the tables
// after (apply()); the tables rebuilt from the log to verify them; heads
// signed with the instructor's key.
#include "gradebook_log.h"

#include "text/json_text.h"

#include "signing.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <sstream>

namespace fl::grading {

const char* const kLogSchema = R"sql(
CREATE TABLE events (
  seq INTEGER PRIMARY KEY,
  at TEXT NOT NULL,
  kind TEXT NOT NULL,
  payload TEXT NOT NULL,
  previous_hash TEXT NOT NULL,
  hash TEXT NOT NULL
);
CREATE TRIGGER events_are_never_changed BEFORE UPDATE ON events
  BEGIN SELECT RAISE(ABORT, 'the gradebook log is append-only'); END;
CREATE TRIGGER events_are_never_deleted BEFORE DELETE ON events
  BEGIN SELECT RAISE(ABORT, 'the gradebook log is append-only'); END;
CREATE TABLE signed_heads (
  id INTEGER PRIMARY KEY,
  seq INTEGER NOT NULL,
  hash TEXT NOT NULL,
  public_key TEXT NOT NULL,
  signature TEXT NOT NULL,
  at TEXT NOT NULL
);
)sql";

namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

std::string text(const QJsonObject& o, const char* key) {
    return o.value(QLatin1String(key)).toString().toStdString();
}

double number(const QJsonObject& o, const char* key) {
    return o.value(QLatin1String(key)).toDouble();
}

std::string canonical(const QJsonObject& o) {
    // QJsonObject keeps its keys sorted and writes numbers to round-trip.
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

QJsonObject parsed(const std::string& payload) {
    return QJsonDocument::fromJson(QByteArray::fromStdString(payload)).object();
}

const std::string kNoHash(64, '0');

} // namespace

std::string sha256(const std::string& textToHash) {
    return QCryptographicHash::hash(QByteArray::fromStdString(textToHash),
                                    QCryptographicHash::Sha256)
        .toHex()
        .toStdString();
}

std::string studentPayload(const Student& s) {
    return canonical({{"id", q(s.id)}, {"name", q(s.name)}, {"email", q(s.email)}});
}

std::string assignmentPayload(const AssignmentRecord& a) {
    return canonical({{"id", q(a.id)},
                      {"title", q(a.title)},
                      {"maxAutomatic", a.maxAutomatic},
                      {"maxManual", a.maxManual},
                      {"rubricHash", q(a.rubricHash)},
                      {"due", q(a.due)}});
}

std::string gradePayload(const GradeRecord& g) {
    QJsonArray requirements;
    for (const RequirementResult& r : g.requirements)
        requirements.append(QJsonObject{{"id", q(r.id)},
                                        {"met", r.met},
                                        {"points", r.points},
                                        {"maxPoints", r.maxPoints},
                                        {"evidence", q(r.evidence)},
                                        {"locations", q(locationsJson(r.locations))}});
    return canonical({{"student", q(g.student)},
                      {"assignment", q(g.assignment)},
                      {"contentHash", q(g.contentHash)},
                      {"submittedAt", q(g.submittedAt)},
                      {"path", q(g.path)},
                      {"hoursLate", g.hoursLate},
                      {"checkerVersion", q(g.checkerVersion)},
                      {"rubricHash", q(g.rubricHash)},
                      {"gradable", g.gradable},
                      {"score", g.score},
                      {"maxScore", g.maxScore},
                      {"lateFactor", g.lateFactor},
                      {"gradedAt", q(g.gradedAt)},
                      {"diagnostics", q(g.diagnostics)},
                      {"isolation", q(g.isolation)},
                      {"requirements", requirements}});
}

std::string manualScorePayload(const std::string& student, const std::string& assignment,
                               const ManualScore& m) {
    return canonical({{"student", q(student)},
                      {"assignment", q(assignment)},
                      {"item", q(m.item)},
                      {"points", m.points},
                      {"comment", q(m.comment)},
                      {"grader", q(m.grader)},
                      {"at", q(m.at)}});
}

std::string overridePayload(const std::string& student, const std::string& assignment, double score,
                            const std::string& who, const std::string& why, const std::string& at) {
    return canonical({{"student", q(student)},
                      {"assignment", q(assignment)},
                      {"score", score},
                      {"who", q(who)},
                      {"why", q(why)},
                      {"at", q(at)}});
}

std::string entryHash(const std::string& previous, std::int64_t seq, const std::string& at,
                      std::string_view kind, const std::string& payload) {
    std::ostringstream entry;
    entry << previous << '\n' << seq << '\n' << at << '\n' << kind << '\n' << payload;
    return sha256(entry.str());
}

std::string headMessage(const LogHead& head) {
    return "FunctionLab gradebook head\nentry " + std::to_string(head.seq) + "\nhash " + head.hash +
           "\n";
}

// ---------------------------------------------------------------- writing

void Gradebook::change(std::string_view kind, const std::string& payload) {
    platform::SqliteDatabase::Transaction t(db_);
    appendEntry(kind, payload);
    apply(kind, payload);
    t.commit();
}

void Gradebook::appendEntry(std::string_view kind, const std::string& payload) {
    appendEntry(kind, payload, utcNow());
}

void Gradebook::appendEntry(std::string_view kind, const std::string& payload,
                            const std::string& at) {
    const LogHead last = head();
    const std::int64_t seq = last.seq + 1;
    db_.prepare("INSERT INTO events(seq, at, kind, payload, previous_hash, hash) "
                "VALUES(?1, ?2, ?3, ?4, ?5, ?6)")
        .bind(1, seq)
        .bind(2, at)
        .bind(3, kind)
        .bind(4, payload)
        .bind(5, last.hash)
        .bind(6, entryHash(last.hash, seq, at, kind, payload))
        .run();
}

void Gradebook::apply(std::string_view kind, const std::string& payload) {
    const QJsonObject o = parsed(payload);
    if (kind == "student") {
        applyStudent({text(o, "id"), text(o, "name"), text(o, "email")});
    } else if (kind == "assignment") {
        applyAssignment({text(o, "id"), text(o, "title"), number(o, "maxAutomatic"),
                         number(o, "maxManual"), text(o, "rubricHash"), text(o, "due")});
    } else if (kind == "grade") {
        GradeRecord g;
        g.student = text(o, "student");
        g.assignment = text(o, "assignment");
        g.contentHash = text(o, "contentHash");
        g.submittedAt = text(o, "submittedAt");
        g.path = text(o, "path");
        g.hoursLate = number(o, "hoursLate");
        g.checkerVersion = text(o, "checkerVersion");
        g.rubricHash = text(o, "rubricHash");
        g.gradable = o.value("gradable").toBool();
        g.score = number(o, "score");
        g.maxScore = number(o, "maxScore");
        g.lateFactor = number(o, "lateFactor");
        g.gradedAt = text(o, "gradedAt");
        g.diagnostics = text(o, "diagnostics");
        g.isolation = text(o, "isolation");
        for (const QJsonValue& v : o.value("requirements").toArray()) {
            const QJsonObject r = v.toObject();
            RequirementResult result;
            result.id = text(r, "id");
            result.met = r.value("met").toBool();
            result.points = number(r, "points");
            result.maxPoints = number(r, "maxPoints");
            result.evidence = text(r, "evidence");
            result.locations = locationsOf(text(r, "locations"));
            g.requirements.push_back(std::move(result));
        }
        applyGrade(g);
    } else if (kind == "manual-score") {
        applyManualScore(text(o, "student"), text(o, "assignment"),
                         {text(o, "item"), number(o, "points"), text(o, "comment"),
                          text(o, "grader"), text(o, "at")});
    } else if (kind == "override") {
        applyOverride(text(o, "student"), text(o, "assignment"), number(o, "score"), text(o, "who"),
                      text(o, "why"), text(o, "at"));
    } else if (kind == "merge") {
        // What grade merge combined (its sources' heads): a record, no table.
    } else {
        throw platform::SqliteError("the gradebook log holds an entry of an unknown kind '" +
                                    std::string(kind) + "' (written by a newer FunctionLab?)");
    }
}

// An older gradebook's tables become the first entries of its log, in an
// order whose replay rebuilds them: from then on every change is logged.
void Gradebook::importStateIntoLog() {
    for (const AssignmentRecord& a : assignments())
        appendEntry("assignment", assignmentPayload(a));
    for (const Student& s : students())
        appendEntry("student", studentPayload(s));
    auto grades = db_.prepare(
        "SELECT g.id, s.student_id, s.assignment_id, s.content_hash, s.submitted_at, "
        "s.hours_late, s.path, g.checker_version, g.rubric_hash, g.gradable, g.score, "
        "g.max_score, g.late_factor, g.graded_at, g.diagnostics, g.isolation FROM grades g "
        "JOIN submissions s ON g.submission_id = s.id ORDER BY g.id");
    auto results = db_.prepare("SELECT requirement_id, met, points, max_points, evidence, "
                               "locations FROM results WHERE grade_id = ?1 ORDER BY rowid");
    std::vector<std::string> payloads;
    while (grades.step()) {
        GradeRecord g;
        g.student = grades.text(1);
        g.assignment = grades.text(2);
        g.contentHash = grades.text(3);
        g.submittedAt = grades.text(4);
        g.hoursLate = grades.number(5);
        g.path = grades.text(6);
        g.checkerVersion = grades.text(7);
        g.rubricHash = grades.text(8);
        g.gradable = grades.integer(9) != 0;
        g.score = grades.number(10);
        g.maxScore = grades.number(11);
        g.lateFactor = grades.number(12);
        g.gradedAt = grades.text(13);
        g.diagnostics = grades.text(14);
        g.isolation = grades.text(15);
        results.bind(1, grades.integer(0));
        while (results.step())
            g.requirements.push_back({results.text(0),
                                      {},
                                      results.integer(1) != 0,
                                      results.number(2),
                                      results.number(3),
                                      results.text(4),
                                      locationsOf(results.text(5))});
        results.reset();
        payloads.push_back(gradePayload(g));
    }
    for (const std::string& p : payloads)
        appendEntry("grade", p);
    auto manual = db_.prepare("SELECT student_id, assignment_id, item_id, points, comment, "
                              "grader, at FROM manual_scores ORDER BY at, student_id, item_id");
    payloads.clear();
    while (manual.step())
        payloads.push_back(manualScorePayload(
            manual.text(0), manual.text(1),
            {manual.text(2), manual.number(3), manual.text(4), manual.text(5), manual.text(6)}));
    for (const std::string& p : payloads)
        appendEntry("manual-score", p);
    auto overrides = db_.prepare(
        "SELECT student_id, assignment_id, score, who, why, at FROM overrides ORDER BY id");
    payloads.clear();
    while (overrides.step())
        payloads.push_back(overridePayload(overrides.text(0), overrides.text(1),
                                           overrides.number(2), overrides.text(3),
                                           overrides.text(4), overrides.text(5)));
    for (const std::string& p : payloads)
        appendEntry("override", p);
}

// ------------------------------------------------------------ heads

LogHead Gradebook::head() {
    auto s = db_.prepare("SELECT seq, hash FROM events ORDER BY seq DESC LIMIT 1");
    if (!s.step()) return {0, kNoHash};
    return {s.integer(0), s.text(1)};
}

std::size_t Gradebook::entries() {
    auto s = db_.prepare("SELECT COUNT(*) FROM events");
    return s.step() ? std::size_t(s.integer(0)) : 0;
}

SignedHead Gradebook::signHead(const SigningKey& key) {
    SignedHead signedHead{head(), key.publicHex, {}, utcNow()};
    signedHead.signature = sign(key, headMessage(signedHead.head));
    db_.prepare("INSERT INTO signed_heads(seq, hash, public_key, signature, at) "
                "VALUES(?1, ?2, ?3, ?4, ?5)")
        .bind(1, signedHead.head.seq)
        .bind(2, signedHead.head.hash)
        .bind(3, signedHead.publicKey)
        .bind(4, signedHead.signature)
        .bind(5, signedHead.at)
        .run();
    return signedHead;
}

std::vector<SignedHead> Gradebook::signedHeads() {
    std::vector<SignedHead> out;
    auto s = db_.prepare(
        "SELECT seq, hash, public_key, signature, at FROM signed_heads ORDER BY seq DESC, id DESC");
    while (s.step())
        out.push_back({{s.integer(0), s.text(1)}, s.text(2), s.text(3), s.text(4)});
    return out;
}

std::vector<LogEntry> Gradebook::logEntries() {
    std::vector<LogEntry> out;
    auto s = db_.prepare("SELECT seq, at, kind, payload, hash FROM events ORDER BY seq");
    while (s.step())
        out.push_back({s.integer(0), s.text(1), s.text(2), s.text(3), s.text(4)});
    return out;
}

void Gradebook::appendFrom(const std::vector<LogEntry>& entries) {
    platform::SqliteDatabase::Transaction t(db_);
    for (const LogEntry& e : entries) {
        appendEntry(e.kind, e.payload, e.at);
        apply(e.kind, e.payload);
    }
    t.commit();
}

// ------------------------------------------------------------ verifying

namespace {

// Who an entry is about, for a person: "a grade of bob for implicit-fantasies".
std::string describe(const std::string& kind, const std::string& payload) {
    // Names from the file: shown, never obeyed, on a terminal.
    const QJsonObject o = parsed(payload);
    if (kind == "student") return "the student " + text::shownName(text(o, "id"));
    if (kind == "assignment") return "the assignment " + text::shownName(text(o, "id"));
    const std::string whom =
        text::shownName(text(o, "student")) + " for " + text::shownName(text(o, "assignment"));
    if (kind == "grade") return "a grade of " + whom;
    if (kind == "manual-score") return "a manual score of " + whom;
    if (kind == "override") return "an override of " + whom;
    if (kind == "merge") return "the record of a merge";
    return "an entry of kind " + text::shownName(kind);
}

// The tables as the log determines them, without the row ids SQLite picks:
// what a rebuild from the log must reproduce exactly.
struct View {
    const char* name;
    const char* sql;
};
constexpr View kViews[] = {
    {"assignments", "SELECT id, title, max_automatic, max_manual, rubric_hash, due FROM "
                    "assignments ORDER BY id"},
    {"students", "SELECT id, name, email FROM students ORDER BY id"},
    {"submissions", "SELECT student_id, assignment_id, content_hash, submitted_at, hours_late, "
                    "path FROM submissions ORDER BY student_id, assignment_id, content_hash"},
    {"grades", "SELECT s.student_id, s.assignment_id, g.graded_at, s.content_hash, "
               "g.checker_version, g.rubric_hash, g.gradable, g.score, g.max_score, "
               "g.late_factor, g.diagnostics, g.isolation, g.previous_hash, g.row_hash FROM grades "
               "g JOIN submissions s ON g.submission_id = s.id ORDER BY g.id"},
    {"results", "SELECT s.student_id, s.assignment_id, g.graded_at, r.requirement_id, r.met, "
                "r.points, r.max_points, r.evidence, r.locations FROM results r JOIN grades g ON "
                "r.grade_id = g.id JOIN submissions s ON g.submission_id = s.id ORDER BY g.id, "
                "r.rowid"},
    {"manual_scores", "SELECT student_id, assignment_id, item_id, points, comment, grader, at "
                      "FROM manual_scores ORDER BY student_id, assignment_id, item_id"},
    {"overrides", "SELECT student_id, assignment_id, score, who, why, at FROM overrides ORDER "
                  "BY id"},
};

std::vector<std::vector<std::string>> rowsOf(platform::SqliteDatabase& db, const char* sql,
                                             std::vector<std::string>& columns) {
    auto s = db.prepare(sql);
    std::vector<std::vector<std::string>> rows;
    columns.clear();
    for (int c = 0; c < s.columns(); ++c)
        columns.push_back(s.columnName(c));
    while (s.step()) {
        std::vector<std::string> row;
        for (int c = 0; c < s.columns(); ++c)
            row.push_back(s.isNull(c) ? "NULL" : s.text(c));
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string rowName(const std::vector<std::string>& row) {
    std::string out;
    for (std::size_t i = 0; i < row.size() && i < 3; ++i)
        out += (i ? ", " : "") + row[i];
    return out;
}

// The first way `table` differs from `rebuilt`, or empty.
std::string firstDifference(const char* name, const std::vector<std::string>& columns,
                            const std::vector<std::vector<std::string>>& table,
                            const std::vector<std::vector<std::string>>& rebuilt) {
    const std::size_t n = std::min(table.size(), rebuilt.size());
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < columns.size(); ++c)
            if (table[i][c] != rebuilt[i][c])
                return std::string(name) + ", row " + std::to_string(i + 1) + " (" +
                       rowName(rebuilt[i]) + "): " + columns[c] + " is '" + table[i][c] +
                       "' in the table, '" + rebuilt[i][c] + "' in the log";
    if (table.size() > n)
        return std::string(name) + ": a row that no entry of the log made (" + rowName(table[n]) +
               ")";
    if (rebuilt.size() > n)
        return std::string(name) + ": a row the log made is missing from the table (" +
               rowName(rebuilt[n]) + ")";
    return {};
}

} // namespace

GradebookCheck Gradebook::verify(const VerifyOptions& options) {
    GradebookCheck c;
    auto fail = [&](std::int64_t entry, std::string why) {
        if (!c.intact) return; // the first problem is the one said
        c.intact = false;
        c.badEntry = entry;
        c.problem = std::move(why);
    };
    // 1. The chain: numbered without gaps, each holding its predecessor's
    // hash and hashing to what it says.
    Gradebook rebuilt(":memory:");
    std::vector<std::string> hashes{kNoHash}; // hashes[seq]
    auto s = db_.prepare("SELECT seq, at, kind, payload, previous_hash, hash FROM events ORDER "
                         "BY seq");
    std::string previous = kNoHash;
    std::int64_t expected = 1;
    while (s.step()) {
        const std::int64_t seq = s.integer(0);
        const std::string at = s.text(1), kind = s.text(2), payload = s.text(3);
        const std::string prior = s.text(4), hash = s.text(5);
        if (seq != expected)
            fail(expected, "entry " + std::to_string(expected) + " is missing: the log goes from " +
                               std::to_string(expected - 1) + " to " + std::to_string(seq) +
                               " (entries were deleted)");
        else if (prior != previous)
            fail(seq, "entry " + std::to_string(seq) + " (" + describe(kind, payload) +
                          ") does not follow entry " + std::to_string(seq - 1) +
                          ": an entry was inserted, deleted or changed before it");
        else if (hash != entryHash(previous, seq, at, kind, payload))
            fail(seq, "entry " + std::to_string(seq) + " (" + describe(kind, payload) +
                          ", written " + at + ") was changed: it no longer hashes to what it says");
        if (c.intact) {
            try {
                rebuilt.apply(kind, payload);
            } catch (const std::exception& e) {
                fail(seq, "entry " + std::to_string(seq) + " cannot be applied: " + e.what());
            }
        }
        previous = hash;
        hashes.push_back(hash);
        ++c.entries;
        expected = seq + 1;
        c.head = {seq, hash};
    }
    if (c.entries == 0) c.head = {0, kNoHash};
    // 2. The tables: what a rebuild from the log gives, exactly.
    if (c.intact)
        for (const View& v : kViews) {
            std::vector<std::string> columns, ignored;
            const auto table = rowsOf(db_, v.sql, columns);
            const auto fromLog = rowsOf(rebuilt.db_, v.sql, ignored);
            if (std::string d = firstDifference(v.name, columns, table, fromLog); !d.empty()) {
                fail(0, "the table " + d + ": it was changed behind the log's back");
                break;
            }
        }
    auto entryHashAt = [&](std::int64_t seq) -> const std::string* {
        return seq >= 0 && std::size_t(seq) < hashes.size() ? &hashes[std::size_t(seq)] : nullptr;
    };
    // 3. A head from elsewhere (an export) must be one of the log's.
    if (options.head) {
        bool found = false;
        for (const std::string& h : hashes)
            found = found || h == *options.head;
        if (!found)
            fail(0, "the head " + options.head->substr(0, 16) +
                        "… is not in the log: entries it covered were changed or deleted");
    }
    // 4. Signatures: the newest head signed with the key (any key when none
    // is given) must hold and still be the log's.
    for (const SignedHead& h : signedHeads()) {
        if (options.publicKey && h.publicKey != *options.publicKey) continue;
        c.signedHead = h;
        const std::string* now = entryHashAt(h.head.seq);
        const bool stillTheLogs = now && *now == h.head.hash;
        c.signatureHolds =
            stillTheLogs && signatureHolds(h.publicKey, headMessage(h.head), h.signature);
        if (!now)
            fail(h.head.seq, "a head was signed at entry " + std::to_string(h.head.seq) +
                                 " but the log ends at " + std::to_string(c.head.seq) +
                                 ": its last entries were deleted");
        else if (!stillTheLogs)
            fail(h.head.seq, "the head signed at entry " + std::to_string(h.head.seq) +
                                 " is no longer the log's: entries up to it were changed and "
                                 "hashed again");
        else if (!c.signatureHolds)
            fail(h.head.seq, "the signature of the head at entry " + std::to_string(h.head.seq) +
                                 " does not hold");
        c.unsignedEntries = std::size_t(c.head.seq - h.head.seq);
        break;
    }
    if (options.publicKey && !c.signedHead)
        fail(0, "no head of the log is signed with that key: it was never signed with it, or "
                "its signatures were removed");
    if (!c.signedHead) c.unsignedEntries = c.entries;
    return c;
}

} // namespace fl::grading
