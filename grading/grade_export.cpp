#include "grade_export.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>
#include <fstream>
#include <map>

namespace fl::grading {
namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string row(std::initializer_list<std::string> cells) {
    std::string out;
    for (const std::string& c : cells) {
        if (!out.empty()) out += ',';
        out += csvCell(c);
    }
    return out + "\r\n";
}

std::map<std::string, Student> studentsById(Gradebook& book) {
    std::map<std::string, Student> out;
    for (Student& s : book.students())
        out[s.id] = std::move(s);
    return out;
}

} // namespace

std::string csvCell(const std::string& text) {
    std::string cell = text;
    // OWASP's CSV injection rule: a leading = + - @ tab or CR makes a formula.
    if (!cell.empty() && std::string_view("=+-@\t\r").find(cell.front()) != std::string::npos)
        cell = "'" + cell;
    if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (char c : cell) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string exportCsvText(Gradebook& book, const AssignmentRecord& a, ExportFormat format) {
    const auto students = studentsById(book);
    const std::vector<GradeRecord> grades = book.latestGrades(a.id);
    const double max = a.maxAutomatic + a.maxManual;
    std::string out;
    if (format == ExportFormat::Canvas) {
        // Canvas matches rows by SIS Login ID; the column is the assignment's
        // title with its points, as Canvas's own export writes it.
        out += row({"Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                    a.title + " (" + number(max) + ")"});
        out += row({"Points Possible", "", "", "", "", number(max)});
        for (const GradeRecord& g : grades) {
            const Student& s = students.count(g.student) ? students.at(g.student) : Student{};
            out += row({s.name.empty() ? g.student : s.name, "", g.student, g.student, "",
                        number(book.finalScore(g))});
        }
    } else if (format == ExportFormat::Moodle) {
        // Moodle's "Import grades: CSV file": a column to map users by, one
        // per grade item, one for feedback.
        out += row({"Username", "Email address", a.title, a.title + " feedback"});
        for (const GradeRecord& g : grades) {
            const Student& s = students.count(g.student) ? students.at(g.student) : Student{};
            std::string feedback;
            for (const RequirementResult& r : g.requirements)
                if (!r.met) feedback += r.id + ": " + r.evidence + "\n";
            out += row({g.student, s.email, number(book.finalScore(g)), feedback});
        }
    } else {
        std::vector<std::string> ids;
        if (!grades.empty())
            for (const RequirementResult& r : grades.front().requirements)
                ids.push_back(r.id);
        std::string header = row({"student", "name", "email", "gradable", "automatic",
                                  "max_automatic", "late_factor", "manual", "override", "final",
                                  "submitted_at", "hours_late", "content_hash", "checker_version"});
        header.resize(header.size() - 2);
        for (const std::string& id : ids)
            header += "," + csvCell(id);
        out += header + "\r\n";
        for (const GradeRecord& g : grades) {
            const Student& s = students.count(g.student) ? students.at(g.student) : Student{};
            const auto o = book.overrideScore(g.student, a.id);
            std::string line = row({g.student, s.name, s.email, g.gradable ? "yes" : "no",
                                    number(g.score), number(g.maxScore), number(g.lateFactor),
                                    number(book.manualPoints(g.student, a.id)), o ? number(*o) : "",
                                    number(book.finalScore(g)), g.submittedAt, number(g.hoursLate),
                                    g.contentHash, g.checkerVersion});
            line.resize(line.size() - 2);
            for (const std::string& id : ids) {
                std::string points;
                for (const RequirementResult& r : g.requirements)
                    if (r.id == id) points = number(r.points);
                line += "," + csvCell(points);
            }
            out += line + "\r\n";
        }
    }
    return out;
}

void exportGradescope(Gradebook& book, const AssignmentRecord& a,
                      const std::filesystem::path& folder) {
    for (const GradeRecord& g : book.latestGrades(a.id)) {
        // Gradescope's autograder results: score, and a test per requirement.
        QJsonArray tests;
        for (const RequirementResult& r : g.requirements)
            tests.append(QJsonObject{{"name", QString::fromStdString(r.id)},
                                     {"score", r.points},
                                     {"max_score", r.maxPoints},
                                     {"status", r.met ? "passed" : "failed"},
                                     {"output", QString::fromStdString(r.evidence)},
                                     {"visibility", "visible"}});
        QJsonObject results{
            {"score", g.score * g.lateFactor},
            {"output", QString::fromStdString(g.gradable ? "graded by FunctionLab's checker " +
                                                               g.checkerVersion
                                                         : "not gradable: " + g.diagnostics)},
            {"tests", tests}};
        // A roster's id becomes a folder name: only a plain one.
        if (g.student.empty() || g.student[0] == '.' ||
            g.student.find_first_of("/\\") != std::string::npos)
            continue;
        const std::filesystem::path dir = folder / g.student;
        std::filesystem::create_directories(dir);
        std::ofstream(dir / "results.json", std::ios::binary)
            << QJsonDocument(results).toJson().toStdString();
    }
}

} // namespace fl::grading
