#include "grading/check_report_json.h"

#include "scene/scene_diagnostic_json.h"
#include "text/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <limits>

namespace fl::grading {
namespace {

using text::jsonNumber;
using text::jsonString;

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

// Reading a field with its type and range checked; the first problem is
// kept in `error` and the rest of the read is abandoned by the caller.
class FieldReader {
  public:
    explicit FieldReader(std::string* error) : error_(error) {}
    bool failed() const { return failed_; }

    bool fail(const std::string& what) {
        if (!failed_ && error_) *error_ = what;
        failed_ = true;
        return false;
    }

    bool boolean(const QJsonObject& o, const char* key, bool& out, const std::string& where) {
        const QJsonValue v = o.value(key);
        if (!v.isBool()) return fail(where + key + " must be true or false");
        out = v.toBool();
        return true;
    }

    bool number(const QJsonObject& o, const char* key, double& out, const std::string& where,
                double lo = -std::numeric_limits<double>::max(),
                double hi = std::numeric_limits<double>::max()) {
        const QJsonValue v = o.value(key);
        const double d = v.toDouble();
        if (!v.isDouble() || !std::isfinite(d) || d < lo || d > hi)
            return fail(where + key + " must be a number in range");
        out = d;
        return true;
    }

    bool integer(const QJsonObject& o, const char* key, int& out, const std::string& where) {
        double d = 0;
        if (!number(o, key, d, where, 0, double(std::numeric_limits<int>::max()))) return false;
        if (d != std::floor(d)) return fail(where + key + " must be a whole number");
        out = int(d);
        return true;
    }

    bool text(const QJsonObject& o, const char* key, std::string& out, const std::string& where,
              bool optional = false) {
        const QJsonValue v = o.value(key);
        if (optional && v.isUndefined()) return true;
        if (!v.isString()) return fail(where + key + " must be text");
        out = v.toString().toStdString();
        return true;
    }

  private:
    std::string* error_;
    bool failed_ = false;
};

// {"file", "line", "column"}: false (and `read` failed) when a field is wrong.
bool readLocation(FieldReader& read, const QJsonObject& o, Location& l, const std::string& at) {
    return read.text(o, "file", l.file, at) && read.integer(o, "line", l.line, at) &&
           read.integer(o, "column", l.column, at);
}

std::optional<formula::Severity> severityNamed(const std::string& name) {
    for (formula::Severity s :
         {formula::Severity::Error, formula::Severity::Warning, formula::Severity::Note})
        if (name == formula::severityName(s)) return s;
    return std::nullopt;
}

} // namespace

std::string locationsJson(const std::vector<Location>& locations) {
    // QJson's compact form: the gradebook stores it, and its log verifies
    // the tables against a rebuild written the same way.
    QJsonArray a;
    for (const Location& l : locations)
        a.append(QJsonObject{{"file", q(l.file)}, {"line", l.line}, {"column", l.column}});
    return QJsonDocument(a).toJson(QJsonDocument::Compact).toStdString();
}

std::vector<Location> locationsOf(std::string_view json) {
    std::vector<Location> out;
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArray(json.data(), qsizetype(json.size())));
    for (const QJsonValue& v : doc.array()) {
        const QJsonObject o = v.toObject();
        Location l;
        FieldReader read(nullptr);
        if (readLocation(read, o, l, "")) out.push_back(std::move(l));
    }
    return out;
}

std::string checkReportJson(const CheckReportDocument& d) {
    const CheckReport& r = d.report;
    std::string out = "{\"assignment\":";
    out += jsonString(d.assignment);
    out += ",\"gradable\":";
    out += r.gradable ? "true" : "false";
    out += ",\"score\":" + jsonNumber(r.score);
    out += ",\"max_score\":" + jsonNumber(r.maxScore);
    out += ",\"checker_version\":";
    out += jsonString(d.checkerVersion);
    out += ",\"requirements\":[";
    for (std::size_t i = 0; i < r.requirements.size(); ++i) {
        const RequirementResult& req = r.requirements[i];
        if (i) out += ",";
        out += "{\"id\":";
        out += jsonString(req.id);
        out += ",\"met\":";
        out += req.met ? "true" : "false";
        out += ",\"points\":" + jsonNumber(req.points);
        out += ",\"max_points\":" + jsonNumber(req.maxPoints);
        out += ",\"evidence\":";
        out += jsonString(req.evidence);
        out += ",\"locations\":";
        out += locationsJson(req.locations);
        out += "}";
    }
    out += "],\"manual_max\":" + jsonNumber(d.manualMax);
    out += ",\"budget_exceeded\":";
    out += r.budgetExceeded ? "true" : "false";
    out += ",\"diagnostics\":[";
    for (std::size_t i = 0; i < r.diagnostics.size(); ++i) {
        if (i) out += ",";
        out += scene::sceneDiagnosticJson(r.diagnostics[i]);
    }
    return out + "]}";
}

std::optional<CheckReportDocument> readCheckReportJson(std::string_view json, std::string* error) {
    FieldReader read(error);
    if (json.size() > kMaxCheckReportBytes) {
        read.fail("the report is larger than 16 MiB");
        return std::nullopt;
    }
    QJsonParseError parse;
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArray(json.data(), qsizetype(json.size())), &parse);
    if (parse.error != QJsonParseError::NoError || !doc.isObject()) {
        read.fail(parse.error != QJsonParseError::NoError
                      ? "not JSON: " + parse.errorString().toStdString() + " at byte " +
                            std::to_string(parse.offset)
                      : std::string("not a JSON object"));
        return std::nullopt;
    }
    const QJsonObject o = doc.object();
    CheckReportDocument d;
    CheckReport& r = d.report;
    const double most = 1e9; // points beyond any rubric
    read.text(o, "assignment", d.assignment, "", true);
    read.text(o, "checker_version", d.checkerVersion, "", true);
    read.boolean(o, "gradable", r.gradable, "");
    read.number(o, "score", r.score, "", 0, most);
    read.number(o, "max_score", r.maxScore, "", 0, most);
    if (o.contains("manual_max")) read.number(o, "manual_max", d.manualMax, "", 0, most);
    if (o.contains("budget_exceeded")) read.boolean(o, "budget_exceeded", r.budgetExceeded, "");
    if (!o.value("requirements").isArray()) read.fail("requirements must be a list");
    if (read.failed()) return std::nullopt;
    const QJsonArray requirements = o.value("requirements").toArray();
    for (qsizetype i = 0; i < requirements.size() && !read.failed(); ++i) {
        const std::string where = "requirements[" + std::to_string(i) + "].";
        if (!requirements[i].isObject()) {
            read.fail(where + " must be an object");
            break;
        }
        const QJsonObject qo = requirements[i].toObject();
        RequirementResult req;
        read.text(qo, "id", req.id, where);
        read.boolean(qo, "met", req.met, where);
        read.number(qo, "max_points", req.maxPoints, where, 0, most);
        // Points never exceed their maximum (a rounding's worth allowed).
        read.number(qo, "points", req.points, where, 0, req.maxPoints * (1 + 1e-12) + 1e-12);
        read.text(qo, "evidence", req.evidence, where, true);
        if (qo.contains("locations") && !qo.value("locations").isArray())
            read.fail(where + "locations must be a list");
        const QJsonArray locations = qo.value("locations").toArray();
        for (qsizetype k = 0; k < locations.size() && !read.failed(); ++k) {
            const std::string at = where + "locations[" + std::to_string(k) + "].";
            const QJsonObject lo = locations[k].toObject();
            Location l;
            if (readLocation(read, lo, l, at)) req.locations.push_back(std::move(l));
        }
        r.requirements.push_back(std::move(req));
    }
    if (o.contains("diagnostics") && !o.value("diagnostics").isArray())
        read.fail("diagnostics must be a list");
    const QJsonArray diagnostics = o.value("diagnostics").toArray();
    for (qsizetype i = 0; i < diagnostics.size() && !read.failed(); ++i) {
        const std::string where = "diagnostics[" + std::to_string(i) + "].";
        const QJsonObject dobj = diagnostics[i].toObject();
        scene::SceneDiagnostic diagnostic;
        std::string severity;
        read.text(dobj, "file", diagnostic.file, where);
        read.integer(dobj, "line", diagnostic.pos.line, where);
        read.integer(dobj, "column", diagnostic.pos.column, where);
        read.text(dobj, "severity", severity, where);
        read.text(dobj, "message", diagnostic.message, where);
        read.text(dobj, "suggestion", diagnostic.suggestion, where, true);
        if (read.failed()) break;
        const auto s = severityNamed(severity);
        if (!s) {
            read.fail(where + "severity must be error, warning or note");
            break;
        }
        diagnostic.severity = *s;
        r.diagnostics.push_back(std::move(diagnostic));
    }
    if (read.failed()) return std::nullopt;
    return d;
}

} // namespace fl::grading
