#include "assignment.h"

#include "json_locations.h"

#include <QByteArray>
#include <QCryptographicHash>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace fl::courseware {
namespace {

using scene::Severity;

// Reads a manifest, reporting each problem where it is.
class ManifestReader {
  public:
    ManifestReader(const std::string& text, std::filesystem::path folder, std::string name)
        : text_(text), folder_(std::move(folder)), name_(std::move(name)), where_(text) {}

    AssignmentLoad read() {
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text_), &error);
        if (error.error != QJsonParseError::NoError) {
            const TextPosition p = where_.at(std::size_t(std::max(0, error.offset)));
            out_.diagnostics.push_back({Severity::Error,
                                        path(),
                                        {p.line, p.column},
                                        "not valid JSON: " + error.errorString().toStdString(),
                                        "check the commas and quotes just before this place"});
            return std::move(out_);
        }
        if (!doc.isObject()) {
            problem("", "a manifest is one JSON object { ... }", "");
            return std::move(out_);
        }
        assignment(doc.object());
        if (!failed_) out_.assignment = std::move(a_);
        return std::move(out_);
    }

  private:
    std::string path() const { return (folder_ / name_).string(); }

    void problem(const std::string& pointer, std::string message, std::string suggestion,
                 Severity severity = Severity::Error) {
        const TextPosition p = where_.of(pointer);
        const std::string at = pointer.empty() ? "" : pointer.substr(1) + ": ";
        out_.diagnostics.push_back(
            {severity, path(), {p.line, p.column}, at + message, std::move(suggestion)});
        if (severity == Severity::Error) failed_ = true;
    }

    std::optional<std::string> text(const QJsonObject& o, const std::string& pointer,
                                    const char* key, bool required) {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) {
            if (required)
                problem(pointer, std::string("\"") + key + "\" is missing",
                        std::string("add \"") + key + "\": \"...\"");
            return std::nullopt;
        }
        if (!v.isString() || v.toString().isEmpty()) {
            problem(pointer + "/" + key, "must be a non-empty string", "");
            return std::nullopt;
        }
        return v.toString().toStdString();
    }

    std::optional<double> number(const QJsonObject& o, const std::string& pointer, const char* key,
                                 double lo, double hi, bool required) {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) {
            if (required)
                problem(pointer, std::string("\"") + key + "\" is missing",
                        std::string("add \"") + key + "\": a number");
            return std::nullopt;
        }
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < lo ||
            v.toDouble() > hi) {
            std::ostringstream range;
            range << "must be a number from " << lo << " to " << hi;
            problem(pointer + "/" + key, range.str(), "");
            return std::nullopt;
        }
        return v.toDouble();
    }

    // A file of the assignment: relative, inside its folder, present.
    std::optional<std::filesystem::path> file(const std::string& value,
                                              const std::string& pointer) {
        const std::filesystem::path p(value);
        if (p.is_absolute() || value.find("..") != std::string::npos) {
            problem(pointer, "'" + value + "' must be a path inside the assignment's folder",
                    "write it relative to the folder of manifest.json, without ..");
            return std::nullopt;
        }
        std::error_code ec;
        if (!std::filesystem::is_regular_file(folder_ / p, ec)) {
            problem(pointer, "'" + value + "' is not a file in " + folder_.string(), "");
            return std::nullopt;
        }
        return folder_ / p;
    }

    std::vector<std::filesystem::path> files(const QJsonObject& o, const char* key, bool required) {
        std::vector<std::filesystem::path> out;
        const std::string pointer = std::string("/") + key;
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) {
            if (required)
                problem("", std::string("\"") + key + "\" is missing",
                        std::string("add \"") + key + "\": [\"file.x3d\"]");
            return out;
        }
        if (!v.isArray() || v.toArray().isEmpty()) {
            problem(pointer, "must be a list of file names", "");
            return out;
        }
        const QJsonArray list = v.toArray();
        for (qsizetype i = 0; i < list.size(); ++i) {
            const std::string at = pointer + "/" + std::to_string(i);
            if (!list[i].isString()) {
                problem(at, "must be a file name", "");
                continue;
            }
            if (auto f = file(list[i].toString().toStdString(), at)) out.push_back(*f);
        }
        return out;
    }

    // Reference solutions are the instructor's: looked up in the instructor
    // folder (instructorFolderFor), not beside the starter. A student's
    // installation has none, which is no error; each name must still be a
    // path inside a folder.
    std::vector<std::filesystem::path> solutions(const QJsonObject& o) {
        std::vector<std::filesystem::path> out;
        const QJsonValue v = o.value("solutions");
        if (v.isUndefined()) return out;
        if (!v.isArray()) {
            problem("/solutions", "must be a list of file names", "");
            return out;
        }
        const QJsonArray list = v.toArray();
        const std::filesystem::path from = instructorFolderFor(folder_, a_.id);
        for (qsizetype i = 0; i < list.size(); ++i) {
            const std::string at = "/solutions/" + std::to_string(i);
            const std::string value = list[i].toString().toStdString();
            if (!list[i].isString() || value.empty() ||
                std::filesystem::path(value).is_absolute() ||
                value.find("..") != std::string::npos) {
                problem(at, "must be a file name inside the assignment's folder",
                        "write it relative to the folder of manifest.json, without ..");
                continue;
            }
            std::error_code ec;
            if (!from.empty() && std::filesystem::is_regular_file(from / value, ec))
                out.push_back(from / value);
        }
        return out;
    }

    void assignment(const QJsonObject& o) {
        const auto schema = text(o, "", "schema", true);
        if (schema && *schema != kAssignmentSchema) {
            problem("/schema",
                    "this FunctionLab reads \"" + std::string(kAssignmentSchema) + "\", not \"" +
                        *schema + "\"",
                    "write \"schema\": \"" + std::string(kAssignmentSchema) + "\"");
            return;
        }
        if (auto id = text(o, "", "id", true)) {
            a_.id = *id;
            const bool plain = std::all_of(id->begin(), id->end(), [](char c) {
                return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
            });
            if (!plain)
                problem("/id", "an id is lower-case letters, digits and '-' only", "");
            else if (folder_.filename() != *id && !folder_.filename().empty())
                problem("/id",
                        "the id '" + *id + "' differs from the folder's name '" +
                            folder_.filename().string() + "'",
                        "name the folder after the id", Severity::Warning);
        }
        if (auto title = text(o, "", "title", true)) a_.title = *title;
        if (auto instructions = text(o, "", "instructions", true))
            if (auto f = file(*instructions, "/instructions")) a_.instructions = *f;
        a_.starters = files(o, "starters", true);
        a_.solutions = solutions(o);
        if (auto due = text(o, "", "due", false)) {
            const QDateTime t = QDateTime::fromString(QString::fromStdString(*due), Qt::ISODate);
            if (!t.isValid() || t.timeSpec() != Qt::UTC)
                problem("/due", "'" + *due + "' is not a UTC time",
                        "write it as \"2026-12-14T23:59:00Z\"");
            else
                a_.due = *due;
        }
        if (o.contains("late_policy")) latePolicy(o.value("late_policy"));
        requirements(o.value("requirements"));
        rubric(o.value("rubric"));
        static const std::set<QString> known{"schema",       "id",        "title", "instructions",
                                             "starters",     "solutions", "due",   "late_policy",
                                             "requirements", "rubric"};
        for (const QString& key : o.keys())
            if (!known.count(key))
                problem("/" + key.toStdString(), "unknown key '" + key.toStdString() + "'",
                        "the keys are listed in docs/assignments.md", Severity::Warning);
    }

    void latePolicy(const QJsonValue& v) {
        if (!v.isObject()) {
            problem("/late_policy", "must be an object", "");
            return;
        }
        const QJsonObject o = v.toObject();
        if (auto d = number(o, "/late_policy", "deduction_percent", 0, 100, true))
            a_.late.deductionPercent = *d;
        if (auto h = number(o, "/late_policy", "every_hours", 0.01, 1e5, true))
            a_.late.everyHours = *h;
        if (auto f = number(o, "/late_policy", "floor_percent", 0, 100, false))
            a_.late.floorPercent = *f;
    }

    void requirements(const QJsonValue& v) {
        if (v.isUndefined()) {
            problem("", "\"requirements\" is missing", "add \"requirements\": [ ... ]");
            return;
        }
        if (!v.isArray()) {
            problem("/requirements", "must be a list of requirements", "");
            return;
        }
        const QJsonArray list = v.toArray();
        std::set<std::string> ids;
        for (qsizetype i = 0; i < list.size(); ++i) {
            const std::string at = "/requirements/" + std::to_string(i);
            if (!list[i].isObject()) {
                problem(at, "must be an object", "");
                continue;
            }
            const QJsonObject o = list[i].toObject();
            grading::Requirement r;
            if (auto id = text(o, at, "id", true)) {
                r.id = *id;
                if (!ids.insert(*id).second) problem(at + "/id", "'" + *id + "' again", "");
            }
            if (auto kind = text(o, at, "kind", true)) {
                if (auto k = grading::requirementKindNamed(*kind))
                    r.kind = *k;
                else
                    problem(at + "/kind", "unknown kind '" + *kind + "'",
                            "one of implicit-surface, explicit-solid, parametric, "
                            "set-operations, morphing, animation, level-of-detail, "
                            "function-colour, tangible");
            }
            if (auto d = text(o, at, "description", true)) r.description = *d;
            if (auto p = number(o, at, "points", 0, 1e6, true)) r.points = *p;
            if (auto m = number(o, at, "minimum", 1, 1000, false)) r.minimum = int(*m);
            if (auto m = number(o, at, "minimum_kinds", 1, 3, false)) r.minimumKinds = int(*m);
            if (auto varies = text(o, at, "varies", false)) {
                if (*varies == "over-shape")
                    r.variesOverShape = true;
                else if (*varies != "over-shape-or-time")
                    problem(at + "/varies", "'" + *varies + "' is not a way a colour varies",
                            "write \"over-shape\" (a colour that only changes in time does "
                            "not count) or \"over-shape-or-time\" (the default)");
            }
            a_.requirements.push_back(std::move(r));
        }
    }

    void rubric(const QJsonValue& v) {
        if (v.isUndefined()) return;
        if (!v.isArray()) {
            problem("/rubric", "must be a list of rubric items", "");
            return;
        }
        const QJsonArray list = v.toArray();
        for (qsizetype i = 0; i < list.size(); ++i) {
            const std::string at = "/rubric/" + std::to_string(i);
            if (!list[i].isObject()) {
                problem(at, "must be an object", "");
                continue;
            }
            const QJsonObject o = list[i].toObject();
            RubricItem item;
            if (auto id = text(o, at, "id", true)) item.id = *id;
            if (auto d = text(o, at, "description", true)) item.description = *d;
            if (auto p = number(o, at, "points", 0, 1e6, true)) item.points = *p;
            a_.rubric.push_back(std::move(item));
        }
    }

    const std::string& text_;
    std::filesystem::path folder_;
    std::string name_;
    JsonLocations where_;
    Assignment a_;
    AssignmentLoad out_;
    bool failed_ = false;
};

} // namespace

double LatePolicy::factor(double hoursLate) const {
    if (!(hoursLate > 0) || deductionPercent <= 0) return 1;
    const double intervals = std::ceil(hoursLate / everyHours);
    const double percent = std::max(floorPercent, 100 - deductionPercent * intervals);
    return std::clamp(percent, 0.0, 100.0) / 100;
}

double Assignment::automaticPoints() const {
    double sum = 0;
    for (const auto& r : requirements)
        sum += r.points;
    return sum;
}

double Assignment::manualPoints() const {
    double sum = 0;
    for (const auto& r : rubric)
        sum += r.points;
    return sum;
}

std::string Assignment::rubricHash() const {
    std::ostringstream text;
    text.precision(17);
    for (const auto& r : requirements)
        text << "requirement\x1f" << r.id << '\x1f' << grading::requirementKindName(r.kind)
             << '\x1f' << r.points << '\x1f' << r.minimum << '\x1f' << r.minimumKinds << '\n';
    for (const auto& r : rubric)
        text << "rubric\x1f" << r.id << '\x1f' << r.points << '\n';
    return QCryptographicHash::hash(QByteArray::fromStdString(text.str()),
                                    QCryptographicHash::Sha256)
        .toHex()
        .toStdString();
}

grading::AssignmentRecord Assignment::record() const {
    return {id, title, automaticPoints(), manualPoints(), rubricHash(), due.value_or("")};
}

AssignmentLoad parseAssignment(const std::string& manifestText, const std::filesystem::path& folder,
                               const std::string& manifestName) {
    AssignmentLoad load = ManifestReader(manifestText, folder, manifestName).read();
    if (load.assignment) load.assignment->folder = folder;
    return load;
}

AssignmentLoad loadAssignment(const std::filesystem::path& folder) {
    const std::filesystem::path manifest = folder / "manifest.json";
    std::ifstream in(manifest, std::ios::binary);
    if (!in) {
        AssignmentLoad load;
        load.diagnostics.push_back({Severity::Error,
                                    manifest.string(),
                                    {1, 1},
                                    "no manifest.json in " + folder.string(),
                                    "an assignment is a folder holding manifest.json"});
        return load;
    }
    // A manifest is small; a huge file is not one.
    std::string text;
    text.resize(1 << 20);
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    if (in.peek() != std::char_traits<char>::eof()) {
        AssignmentLoad load;
        load.diagnostics.push_back(
            {Severity::Error, manifest.string(), {1, 1}, "larger than 1 MiB: not a manifest", ""});
        return load;
    }
    return parseAssignment(text, folder);
}

} // namespace fl::courseware
