#include "grade_report.h"

#include "scene/scene_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace fl::grading {
namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; max-width: 60em; color: #222; }
table { border-collapse: collapse; } td, th { border: 1px solid #ccc; padding: 0.3em 0.6em; }
.met { color: #2e7d32; } .not { color: #c62828; } .where { color: #666; font-size: 90%; }
img { border: 1px solid #ccc; margin-right: 1em; }
</style>)";

// A page name from a student id: letters, digits, - and _ kept, the rest hex.
std::string pageName(const std::string& student) {
    std::string out;
    for (unsigned char c : student) {
        if (std::isalnum(c) || c == '-' || c == '_') {
            out += char(c);
        } else {
            char buf[4];
            std::snprintf(buf, sizeof buf, "%02x", c);
            out += buf;
        }
    }
    return (out.empty() ? "student" : out);
}

std::string histogramSvg(const std::vector<double>& percents) {
    int bins[10] = {};
    for (double p : percents)
        ++bins[std::clamp(int(p / 10), 0, 9)];
    const int most = std::max(1, *std::max_element(std::begin(bins), std::end(bins)));
    std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='480' height='190' "
                      "role='img' aria-label='score distribution'>";
    for (int i = 0; i < 10; ++i) {
        const int h = 120 * bins[i] / most, x = 20 + i * 44;
        svg += "<rect x='" + std::to_string(x) + "' y='" + std::to_string(150 - h) +
               "' width='38' height='" + std::to_string(h) + "' fill='#5c7cfa'/>";
        svg += "<text x='" + std::to_string(x + 19) +
               "' y='166' font-size='9' "
               "text-anchor='middle'>" +
               std::to_string(i * 10) + "–" + std::to_string(i * 10 + 10) + "</text>";
        if (bins[i])
            svg += "<text x='" + std::to_string(x + 19) + "' y='" + std::to_string(145 - h) +
                   "' font-size='11' text-anchor='middle'>" + std::to_string(bins[i]) + "</text>";
    }
    return svg + "<text x='240' y='184' font-size='11' text-anchor='middle'>final score, "
                 "percent of the maximum</text></svg>";
}

std::string passRateSvg(const std::vector<std::pair<std::string, double>>& rates) {
    const int height = 24 * int(rates.size()) + 10;
    std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='520' height='" +
                      std::to_string(height) + "' role='img' aria-label='pass rate'>";
    for (std::size_t i = 0; i < rates.size(); ++i) {
        const int y = 5 + 24 * int(i);
        svg += "<text x='150' y='" + std::to_string(y + 15) +
               "' font-size='12' text-anchor='end'>" + scene::xmlEscape(rates[i].first) + "</text>";
        svg += "<rect x='158' y='" + std::to_string(y) + "' width='" +
               std::to_string(int(300 * rates[i].second)) +
               "' height='18' fill='#40c057'/><text x='" +
               std::to_string(164 + int(300 * rates[i].second)) + "' y='" + std::to_string(y + 14) +
               "' font-size='11'>" + number(std::round(100 * rates[i].second)) + "%</text>";
    }
    return svg + "</svg>";
}

} // namespace

// Which state of the gradebook the page shows: its log's head, and who
// signed it (functionlab grade verify --head HASH checks it later).
static std::string headParagraph(const LogHead& head, const std::optional<SignedHead>& signedHead) {
    std::string p = "<p class='head'>Made from the gradebook's log at entry " +
                    std::to_string(head.seq) + ", hash <code>" + head.hash + "</code>";
    if (signedHead && signedHead->head.hash == head.hash)
        p += ", signed with key <code>" + signedHead->publicKey + "</code>: signature <code>" +
             signedHead->signature + "</code>";
    else
        p += " (not signed)";
    return p + ". Check it with <code>functionlab grade verify GRADEBOOK --head HASH</code>.</p>";
}

ReportResult writeReport(Gradebook& book, const AssignmentRecord& a,
                         const std::vector<std::string>& ids, const std::filesystem::path& folder,
                         const ReportOptions& options) {
    ReportResult result;
    std::filesystem::create_directories(folder / "pictures");
    const std::vector<GradeRecord> grades = book.latestGrades(a.id);
    std::map<std::string, Student> names;
    for (Student& s : book.students())
        names[s.id] = std::move(s);
    const double max = a.maxAutomatic + a.maxManual;
    std::vector<double> percents;
    std::map<std::string, int> passed;
    std::string rows;
    for (const GradeRecord& g : grades) {
        const double final = book.finalScore(g);
        percents.push_back(max > 0 ? 100 * final / max : 0);
        for (const RequirementResult& r : g.requirements)
            passed[r.id] += r.met ? 1 : 0;
        const std::string page = pageName(g.student) + ".html";
        const std::string name = names.count(g.student) ? names.at(g.student).name : "";
        rows += "<tr><td><a href='" + page + "'>" + scene::xmlEscape(g.student) + "</a></td><td>" +
                scene::xmlEscape(name) + "</td><td>" + number(final) + "</td><td>" +
                (g.gradable ? "yes" : "<span class='not'>no</span>") + "</td></tr>\n";

        // The student's page.
        std::string html =
            "<!DOCTYPE html><html><head><meta charset='utf-8'><title>" +
            scene::xmlEscape(a.title + " — " + g.student) + "</title>" + kStyle +
            "</head><body><p><a href='index.html'>← the class</a></p><h1>" +
            scene::xmlEscape(g.student) + (name.empty() ? "" : " — " + scene::xmlEscape(name)) +
            "</h1><p>" + scene::xmlEscape(a.title) + "</p><p><b>Final score " + number(final) +
            " of " + number(max) + "</b> (checker " + number(g.score) + " of " +
            number(g.maxScore) + (g.lateFactor < 1 ? ", late ×" + number(g.lateFactor) : "") +
            ", rubric " + number(book.manualPoints(g.student, a.id)) + " of " +
            number(a.maxManual) + ")</p>";
        if (!g.gradable)
            html += "<p class='not'>Not gradable: " + scene::xmlEscape(g.diagnostics) + "</p>";
        if (options.render && g.gradable && !g.path.empty()) {
            html += "<p>";
            const std::vector<double> moments =
                options.moments ? options.moments(g.path) : std::vector<double>{0};
            for (std::size_t i = 0; i < moments.size(); ++i) {
                const std::string png = pageName(g.student) + "-" + std::to_string(i) + ".png";
                if (options.render(g.path, moments[i], folder / "pictures" / png)) {
                    ++result.pictures;
                    html += "<img src='pictures/" + png + "' width='320' height='240' alt='at " +
                            number(moments[i]) + " s'>";
                } else {
                    ++result.picturesFailed;
                    html +=
                        "<span class='where'>(no picture at " + number(moments[i]) + " s)</span>";
                }
            }
            html += "</p>";
        }
        html += "<table><tr><th>requirement</th><th>points</th><th>why</th></tr>";
        for (const RequirementResult& r : g.requirements) {
            html += "<tr><td class='" + std::string(r.met ? "met" : "not") + "'>" +
                    (r.met ? "✔ " : "✘ ") + scene::xmlEscape(r.id) + "</td><td>" +
                    number(r.points) + "/" + number(r.maxPoints) + "</td><td>" +
                    scene::xmlEscape(r.evidence);
            for (const Location& l : r.locations)
                html += "<br><span class='where'>" +
                        scene::xmlEscape(std::filesystem::path(l.file).filename().string()) + ":" +
                        std::to_string(l.line) + ":" + std::to_string(l.column) + "</span>";
            html += "</td></tr>";
        }
        html += "</table>";
        for (const ManualScore& m : book.manualScores(g.student, a.id))
            html += "<p><b>" + scene::xmlEscape(m.item) + "</b>: " + number(m.points) + " — " +
                    scene::xmlEscape(m.comment) + "</p>";
        html += "</body></html>\n";
        std::ofstream(folder / page, std::ios::binary) << html;
        result.pages.push_back(folder / page);
    }
    std::vector<std::pair<std::string, double>> rates;
    for (const std::string& id : ids)
        rates.push_back({id, grades.empty() ? 0 : double(passed[id]) / double(grades.size())});
    double mean = 0;
    for (double p : percents)
        mean += p;
    const std::string index =
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>" + scene::xmlEscape(a.title) +
        " — the class</title>" + kStyle + "</head><body><h1>" + scene::xmlEscape(a.title) +
        "</h1><p>" + std::to_string(grades.size()) + " students; mean final score " +
        number(grades.empty() ? 0 : std::round(mean / double(grades.size()))) + "% of " +
        number(max) + " points.</p><h2>Score distribution</h2>" + histogramSvg(percents) +
        "<h2>Pass rate per requirement</h2>" + passRateSvg(rates) +
        "<h2>Students</h2><table><tr><th>student</th><th>name</th><th>final</th>"
        "<th>gradable</th></tr>\n" +
        rows + "</table>" + headParagraph(book.head(), options.signedHead) + "</body></html>\n";
    std::ofstream(folder / "index.html", std::ios::binary) << index;
    result.pages.insert(result.pages.begin(), folder / "index.html");
    return result;
}

} // namespace fl::grading
