// `functionlab grade export --db GRADEBOOK --assignment ID --format
// canvas|moodle|gradescope|csv -o OUT`: a class's grades for an LMS.
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "grading/grade_export.h"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace fl::cli {

const CommandSpec& gradeExportSpec() {
    static const CommandSpec spec{
        .name = "grade export",
        .summary = "export a class's grades: Canvas, Moodle, Gradescope results.json, CSV",
        .synopsis = {"grade export --db GRADEBOOK.sqlite --assignment ID|DIR --format "
                     "canvas|moodle|gradescope|csv -o OUT"},
        .description =
            "Writes each student's newest grade for the assignment: the final score is an\n"
            "override if there is one, else the automatic score times the late factor plus\n"
            "the manual rubric points. canvas: Canvas's gradebook import CSV; moodle:\n"
            "Moodle's grade import CSV (username, email, grade, feedback); gradescope: a\n"
            "folder OUT/STUDENT/results.json in the autograder's format, one test per\n"
            "requirement; csv: every figure and requirement. Cells a spreadsheet would run\n"
            "as formulas are escaped. Beside it, OUT.head.json (gradescope: OUT/head.json)\n"
            "holds the gradebook log's head the export was made from, signed with the\n"
            "instructor's key when there is one: functionlab grade verify --head checks\n"
            "later that the gradebook still has it.\n",
        .options = {gradebookOption("the gradebook"),
                    assignmentOption(),
                    {.name = "format",
                     .kind = OptionKind::Choice,
                     .valueName = "FORMAT",
                     .help = "canvas, moodle, gradescope or csv",
                     .choices = {"canvas", "moodle", "gradescope", "csv"}},
                    {.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "OUT",
                     .help = "the file to write (gradescope: the folder)"},
                    signingKeyOption()},
        .exitStatus = "0 written, 1 the gradebook or the assignment could not be read or OUT "
                      "not written, 2 usage error",
    };
    return spec;
}

int gradeExportCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeExportSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("db") || !a->given("assignment") || !a->given("format") || !a->given("output"))
        return usageError(gradeExportSpec(), "--db, --assignment, --format and -o are required",
                          std::cerr);
    const auto assignment = assignmentOrExplain(a->text("assignment"), std::cerr);
    if (!assignment) return kExitDiagnostic;
    const std::string db = a->text("db"), out = a->text("output"), format = a->text("format");
    if (!gradebookExists("grade export", db, std::cerr)) return kExitDiagnostic;
    try {
        grading::Gradebook book(db);
        const grading::AssignmentRecord record = assignment->record();
        std::string headFile = out + ".head.json";
        if (format == "gradescope") {
            grading::exportGradescope(book, record, out);
            headFile = (std::filesystem::path(out) / "head.json").string();
        } else {
            const grading::ExportFormat f = format == "canvas"   ? grading::ExportFormat::Canvas
                                            : format == "moodle" ? grading::ExportFormat::Moodle
                                                                 : grading::ExportFormat::Csv;
            std::ofstream file(out, std::ios::binary);
            file << grading::exportCsvText(book, record, f);
            if (!file) {
                std::cerr << "functionlab grade export: cannot write " << out << "\n";
                return kExitDiagnostic;
            }
        }
        // Which state of the gradebook this export shows, signed: the LMS's
        // file cannot hold it, so it goes beside it.
        const auto signedHead = signHeadOrSay(book, *a, "grade export", std::cerr);
        std::ofstream head(headFile, std::ios::binary);
        head << headJson(book.head(), signedHead) << "\n";
        if (!head) {
            std::cerr << "functionlab grade export: cannot write " << headFile << "\n";
            return kExitDiagnostic;
        }
    } catch (const std::exception& e) {
        std::cerr << "functionlab grade export: " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
