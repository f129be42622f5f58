// `functionlab grade merge A.sqlite B.sqlite ... -o COURSE.sqlite`: the
// gradebooks of a class graded in parts (grade batch --shard K/N, on a
// cluster) combined into one, every audit entry kept (grading/gradebook_merge.h).
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "grading/gradebook_merge.h"

#include <chrono>
#include <iostream>

namespace fl::cli {

const CommandSpec& gradeMergeSpec() {
    static const CommandSpec spec{
        .name = "grade merge",
        .summary = "combine the gradebooks of a class graded in parts into one",
        .synopsis = {"grade merge GRADEBOOK... -o COURSE.sqlite [--signing-key FILE] [--json]"},
        .description =
            "Combines gradebooks written by `grade batch --shard K/N` (or any gradebooks of\n"
            "disjoint students) into a new one. Each is verified first. The new log holds\n"
            "every entry of every part — its time, kind and payload — chained anew, then one\n"
            "entry that records each part's file name, entry count, head hash and signed\n"
            "heads. Parts that disagree are refused, never combined: work of the same\n"
            "student on the same assignment in two parts (grades, manual scores or\n"
            "overrides), or a student or an assignment described differently. The new\n"
            "gradebook is written beside COURSE and moved into place when complete.\n",
        .positionals = {{.name = "GRADEBOOK",
                         .help = "a part's gradebook (.sqlite); give every part",
                         .repeats = true}},
        .options = {{.name = "output",
                     .shortName = 'o',
                     .kind = OptionKind::Path,
                     .valueName = "COURSE",
                     .help = "the merged gradebook to write (must not exist)"},
                    signingKeyOption(),
                    {.name = "json",
                     .help = "print one JSON object: {\"sources\", \"entries\", \"students\", "
                             "\"grades\", \"milliseconds\", \"head\": {\"entry\", \"hash\", "
                             "\"publicKey\", \"signature\"}}"}},
        .exitStatus = "0 merged, 1 a part could not be read, does not verify, or disagrees with "
                      "another (nothing written), 2 usage error",
    };
    return spec;
}

int gradeMergeCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeMergeSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("output"))
        return usageError(gradeMergeSpec(), "say where the course goes: -o COURSE.sqlite",
                          std::cerr);
    const std::vector<std::string>& parts = a->positionals();
    for (const std::string& p : parts)
        if (!gradebookExists("grade merge", p, std::cerr)) return kExitDiagnostic;
    const std::string out = a->text("output");
    std::string why;
    const auto started = std::chrono::steady_clock::now();
    const auto merged = grading::mergeGradebooks(parts, out, &why);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    if (!merged) {
        std::cerr << "functionlab grade merge: " << why << "\n";
        return kExitDiagnostic;
    }
    try {
        grading::Gradebook book(out);
        const auto signedHead = signHeadOrSay(book, *a, "grade merge", std::cerr);
        if (a->flag("json")) {
            std::cout << "{\"sources\":" << merged->sources << ",\"entries\":" << merged->entries
                      << ",\"students\":" << merged->students << ",\"grades\":" << merged->grades
                      << ",\"milliseconds\":" << jsonNumber(ms)
                      << ",\"head\":" << headJson(book.head(), signedHead) << "}\n";
        } else {
            std::cout << out << ": " << merged->sources << " gradebooks merged, "
                      << merged->students << " students, " << merged->grades << " graded, "
                      << merged->entries << " log entries\n";
        }
    } catch (const platform::SqliteError& e) {
        std::cerr << "functionlab grade merge: " << out << ": " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
