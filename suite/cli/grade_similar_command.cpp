// `functionlab grade similar --db GRADEBOOK --assignment ID [--threshold S]
// [--json]`: pairs of submissions whose models are the same up to renaming,
// the order of commutative operations, constants and placement, with what
// the starter scene already has subtracted (grading/similarity.h).
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "grading/checker.h"
#include "grading/gradebook.h"
#include "grading/similarity.h"

#include "scene/scene_reader.h"

#include <cstdio>
#include <iostream>

namespace fl::cli {

const CommandSpec& gradeSimilarSpec() {
    static const CommandSpec spec{
        .name = "grade similar",
        .summary = "pairs of submissions with the same model, the starter subtracted",
        .synopsis = {"grade similar --db GRADEBOOK.sqlite --assignment ID|DIR [--threshold S] "
                     "[--json]"},
        .description =
            "Compares each student's newest submission in the gradebook with every other:\n"
            "the sub-expressions of the shown function shapes, with names, constants and\n"
            "placement forgotten and commutative operations in any order, minus what the\n"
            "assignment's starter scene has. Prints the pairs whose similarity (shared over\n"
            "all, from 0 to 1) reaches the threshold, most similar first. A pair is a place\n"
            "to look, not a verdict.\n",
        .options = {gradebookOption("the gradebook grade batch wrote"),
                    assignmentOption(),
                    {.name = "threshold",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "the least similarity reported",
                     .defaultValue = "0.8",
                     .min = 0,
                     .max = 1},
                    {.name = "json",
                     .help = "print one JSON array of {\"first\", \"second\", \"similarity\", "
                             "\"shared\"}"}},
        .exitStatus = "0 compared (pairs or none), 1 the gradebook or the assignment could not be "
                      "read, 2 usage error",
    };
    return spec;
}

int gradeSimilarCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeSimilarSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("db") || !a->given("assignment"))
        return usageError(gradeSimilarSpec(), "--db and --assignment are required", std::cerr);
    const auto assignment = assignmentOrExplain(a->text("assignment"), std::cerr);
    if (!assignment) return kExitDiagnostic;
    if (!gradebookExists("grade similar", a->text("db"), std::cerr)) return kExitDiagnostic;
    try {
        grading::Gradebook book(a->text("db"));
        grading::ModelFingerprint starter;
        for (const auto& s : assignment->starters)
            if (auto r = scene::readSceneFile(s); r.ok()) {
                const auto f = grading::modelFingerprint(*r.scene);
                starter.insert(f.begin(), f.end());
            }
        std::vector<grading::Fingerprinted> models;
        for (const grading::GradeRecord& g : book.latestGrades(assignment->id)) {
            if (!g.gradable || g.path.empty()) continue;
            const scene::ReadResult r = scene::readSceneFile(grading::sceneFileOf(g.path));
            if (!r.ok()) continue;
            models.push_back(
                {g.student, grading::without(grading::modelFingerprint(*r.scene), starter)});
        }
        const auto pairs = grading::similarPairs(models, a->number("threshold", 0.8));
        if (a->flag("json")) {
            std::string out = "[";
            for (std::size_t i = 0; i < pairs.size(); ++i) {
                if (i) out += ",";
                out += "{\"first\":" + jsonString(pairs[i].first);
                out += ",\"second\":" + jsonString(pairs[i].second);
                out += ",\"similarity\":" + jsonNumber(pairs[i].similarity);
                out += ",\"shared\":" + std::to_string(pairs[i].shared) + "}";
            }
            std::cout << out << "]\n";
        } else {
            for (const auto& p : pairs) {
                char line[64];
                std::snprintf(line, sizeof line, "%.2f", p.similarity);
                std::cout << line << "  " << p.first << "  " << p.second << "  (" << p.shared
                          << " shared sub-expressions)\n";
            }
            std::cout << pairs.size() << " pair(s) of " << models.size()
                      << " submissions at or above " << a->number("threshold", 0.8) << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "functionlab grade similar: " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
