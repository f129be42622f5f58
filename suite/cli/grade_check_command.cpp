// `functionlab grade check --assignment ID|DIR SUBMISSION [--json]`: one
// submission against an assignment's automatic requirements. Tools outside
// this repository read its JSON; its fields and exit codes are a contract
// (docs/grading.md).
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "grading/check_report_json.h"
#include "grading/checker.h"

#include <iostream>

namespace fl::cli {
namespace {

void reportText(const grading::CheckReport& r, const courseware::Assignment& a, std::ostream& out,
                std::ostream& err) {
    for (const auto& d : r.diagnostics)
        err << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.gradable) {
        out << "not gradable: the scene could not be read (see above)\n";
        return;
    }
    out << a.title << "\n";
    for (const auto& q : r.requirements) {
        out << (q.met ? "  [x] " : "  [ ] ") << q.id << " (" << jsonNumber(q.points) << "/"
            << jsonNumber(q.maxPoints) << "): " << q.evidence << "\n";
        for (const auto& l : q.locations)
            out << "        " << l.file << ":" << l.line << ":" << l.column << "\n";
    }
    out << "score " << jsonNumber(r.score) << " of " << jsonNumber(r.maxScore)
        << " (automatic; rubric items worth " << jsonNumber(a.manualPoints())
        << " more are graded by your instructor)\n";
}

} // namespace

const CommandSpec& gradeCheckSpec() {
    static const CommandSpec spec{
        .name = "grade check",
        .summary = "check one submission against an assignment's requirements",
        .synopsis = {"grade check --assignment ID|DIR SUBMISSION [--json]"},
        .description = "Reads SUBMISSION (a scene file, gzip forms too, or a folder holding one)\n"
                       "and judges each automatic requirement of the assignment — by analysing\n"
                       "and evaluating the scene as it is shown, so an operation that cannot\n"
                       "change the result does not count — with the evidence for it or the\n"
                       "reason it is not met, located as FILE:LINE:COL.\n",
        .positionals = {{.name = "SUBMISSION", .help = "a scene file or a folder holding one"}},
        .options = {assignmentOption(),
                    {.name = "json",
                     .help =
                         "print exactly one JSON object: {\"assignment\", \"gradable\", \"score\", "
                         "\"max_score\", \"checker_version\", \"requirements\": [{\"id\", \"met\", "
                         "\"points\", \"max_points\", \"evidence\", \"locations\": [{\"file\", "
                         "\"line\", \"column\"}]}], \"manual_max\", \"budget_exceeded\", "
                         "\"diagnostics\": [...]}"}},
        .notes = "score and max_score count the automatic requirements; the rubric items\n"
                 "(manual_max points) are scored in the gradebook. The same submission and\n"
                 "checker version always give the same verdict.\n",
        .exitStatus = "0 graded (whatever the score), 1 not gradable (the assignment or the "
                      "submission could not be read; located diagnostics), 2 usage error",
    };
    return spec;
}

int gradeCheckCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeCheckSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("assignment"))
        return usageError(gradeCheckSpec(), "--assignment ID|DIR is required", std::cerr);
    const std::string id = a->text("assignment");
    const courseware::AssignmentLoad load = courseware::findAssignment(id);
    if (!load.assignment) {
        if (a->flag("json")) {
            grading::CheckReportDocument none;
            none.assignment = id;
            none.report.diagnostics = load.diagnostics;
            std::cout << grading::checkReportJson(none) << "\n";
        } else {
            for (const auto& d : load.diagnostics)
                std::cerr << scene::formatSceneDiagnostic(d) << "\n";
        }
        return kExitDiagnostic;
    }
    const courseware::Assignment& assignment = *load.assignment;
    grading::CheckReport r =
        grading::checkSubmission(a->positional("SUBMISSION"), assignment.requirements);
    if (a->flag("json"))
        std::cout << grading::checkReportJson(
                         {assignment.id, grading::kCheckerVersion, r, assignment.manualPoints()})
                  << "\n";
    else
        reportText(r, assignment, std::cout, std::cerr);
    return r.gradable ? kExitOk : kExitDiagnostic;
}

} // namespace fl::cli
