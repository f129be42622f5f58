// `functionlab bench grading`: a generated class graded as a batch, and what
// the checker's time goes to (bench/grading_bench.h).
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "courseware/grading_bench.h"

#include <filesystem>
#include <iostream>

namespace fl::cli {

const CommandSpec& benchGradingSpec() {
    static const CommandSpec spec{
        .name = "bench grading",
        .summary = "grade a generated class of submissions; time per submission and requirement",
        .synopsis = {"bench grading [--students N] [--jobs N] [--shards N] [--work DIR] [--json]"},
        .description =
            "Generates a class for implicit-fantasies — variants of the reference solution\n"
            "(constants moved, an operation made dead, everything hidden), starters, other\n"
            "labs' solutions, truncated files and hostile formulas — grades it as a cluster\n"
            "would with `grade batch --shard K/N` (isolated processes, --jobs at once, each\n"
            "of --shards parts into its own gradebook, one part after another here) and\n"
            "merges the parts with `grade merge`: submissions per second per core, and the\n"
            "merge's time. Then measures in-process the checker's time per requirement\n"
            "(over the first 200 submissions) and, over the first 40, what the solid\n"
            "comparison's depth costs in time and changes in verdicts.\n",
        .options = {{.name = "students",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "the size of the class: one submission per student",
                     .defaultValue = "200",
                     .min = 1,
                     .max = 100000},
                    {.name = "submissions",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "the same as --students (its older name)",
                     .min = 1,
                     .max = 100000},
                    {.name = "shards",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "the parts the class is graded in, then merged",
                     .defaultValue = "4",
                     .min = 1,
                     .max = 1000},
                    {.name = "jobs",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "submissions graded at once",
                     .defaultValue = "2",
                     .min = 1,
                     .max = 64},
                    {.name = "work",
                     .kind = OptionKind::Path,
                     .valueName = "DIR",
                     .help = "where the class and its gradebook are written (default: a folder "
                             "in the system's temporary directory)"},
                    {.name = "json", .help = "print one JSON object instead of the tables"}},
        .exitStatus = "0 measured, 1 the class could not be written or graded, 2 usage error",
    };
    return spec;
}

int benchGradingCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchGradingSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    courseware::GradingBenchOptions o;
    if (a->given("students") && a->given("submissions"))
        return usageError(benchGradingSpec(), "give --students or --submissions, not both",
                          std::cerr);
    o.submissions =
        int(a->given("submissions") ? a->integer("submissions", 200) : a->integer("students", 200));
    o.shards = int(a->integer("shards", 4));
    o.jobs = int(a->integer("jobs", 2));
    o.work = a->given("work")
                 ? std::filesystem::path(a->text("work"))
                 : std::filesystem::temp_directory_path() / "functionlab-bench-grading";
    std::error_code ec;
    o.functionlab = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    try {
        std::filesystem::create_directories(o.work);
        const courseware::GradingBenchResult r = courseware::runGradingBench(o);
        std::cout << (a->flag("json") ? courseware::gradingBenchJson(r) + "\n"
                                      : courseware::gradingBenchText(r));
    } catch (const std::exception& e) {
        std::cerr << "functionlab bench grading: " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
