// `functionlab grade report --db GRADEBOOK --assignment ID -o DIR`: an HTML
// page per student and the class summary (grading/grade_report.h), with
// pictures drawn by `functionlab render` in child processes.
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "grading/checker.h"
#include "grading/grade_report.h"
#include "grading/submission_view.h"
#include "platform/isolated_run.h"

#include "scene/effects_plan.h"
#include "scene/scene_reader.h"

#include <cstdio>
#include <iostream>

namespace fl::cli {
const CommandSpec& gradeReportSpec() {
    static const CommandSpec spec{
        .name = "grade report",
        .summary = "HTML pages: one per student, with pictures, and the class summary",
        .synopsis = {"grade report --db GRADEBOOK.sqlite --assignment ID|DIR -o DIR "
                     "[--no-pictures]"},
        .description =
            "Writes DIR/index.html (the score distribution, the pass rate per requirement,\n"
            "the students) and a page per student: each requirement with its evidence or\n"
            "the reason it is not met and the places, rubric comments, and pictures of\n"
            "the submission drawn off screen by `functionlab render` — at two moments when\n"
            "something in it moves. Text from submissions is escaped. The index says\n"
            "which state of the gradebook it shows: the log's head, signed with the\n"
            "instructor's key when there is one (functionlab grade verify --head).\n",
        .options = {gradebookOption("the gradebook"),
                    assignmentOption(),
                    {.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "DIR",
                     .help = "the folder to write"},
                    {.name = "no-pictures", .help = "leave the pictures out (faster)"},
                    signingKeyOption()},
        .exitStatus = "0 written (a picture that could not be drawn is said on its page), 1 the "
                      "gradebook or the assignment could not be read, 2 usage error",
    };
    return spec;
}

int gradeReportCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeReportSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("db") || !a->given("assignment") || !a->given("output"))
        return usageError(gradeReportSpec(), "--db, --assignment and -o are required", std::cerr);
    const auto assignment = assignmentOrExplain(a->text("assignment"), std::cerr);
    if (!assignment) return kExitDiagnostic;
    if (!gradebookExists("grade report", a->text("db"), std::cerr)) return kExitDiagnostic;
    std::error_code ec;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    grading::ReportOptions o;
    if (!a->flag("no-pictures")) {
        o.render = [&](const std::string& submission, double seconds,
                       const std::filesystem::path& png) {
            // Drawing needs files (the picture, xvfb's) and much address
            // space (the software OpenGL): limits for a renderer, not a checker.
            platform::IsolationLimits l;
            l.wallSeconds = 60;
            l.cpuSeconds = 60;
            l.memoryBytes = std::size_t(16) << 30;
            l.fileBytes = std::size_t(64) << 20;
            l.isolate = false;
            char time[32];
            std::snprintf(time, sizeof time, "%g", seconds);
            const platform::ChildResult r =
                platform::runIsolated({self, "render", grading::sceneFileOf(submission), "-o",
                                       png.string(), "--size", "320x240", "--time", time},
                                      l);
            return r.exitCode == 0 && std::filesystem::is_regular_file(png);
        };
        o.moments = [](const std::string& submission) {
            const scene::ReadResult r = scene::readSceneFile(grading::sceneFileOf(submission));
            if (!r.ok() || scene::makeEffectsPlan(*r.scene).timeVarying == scene::kStatic)
                return std::vector<double>{0};
            const double cycle = grading::longestCycle(*r.scene);
            return std::vector<double>{0, cycle > 0 ? cycle / 4 : 0.5};
        };
    }
    try {
        grading::Gradebook book(a->text("db"));
        std::vector<std::string> ids;
        for (const grading::Requirement& r : assignment->requirements)
            ids.push_back(r.id);
        o.signedHead = signHeadOrSay(book, *a, "grade report", std::cerr);
        const grading::ReportResult r =
            grading::writeReport(book, assignment->record(), ids, a->text("output"), o);
        std::cout << r.pages.size() << " pages, " << r.pictures << " pictures"
                  << (r.picturesFailed ? ", " + std::to_string(r.picturesFailed) + " not drawn"
                                       : std::string{})
                  << " in " << a->text("output") << "\n";
    } catch (const std::exception& e) {
        std::cerr << "functionlab grade report: " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
