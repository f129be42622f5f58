// `functionlab grade batch --assignment ID DIR --db GRADEBOOK.sqlite [--jobs N]
// [--roster CSV] [--shard K/N] [--json]`: a class's submissions (or the K-th
// of N parts of them), each checked by `functionlab grade check` in its own
// isolated child process.
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "courseware/catalogue.h"
#include "grading/batch_grading.h"
#include "grading/checker.h"
#include "grading/gradebook_merge.h"

#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace fl::cli {
namespace {

// "K/N" with 0 <= K < N, or nothing (with why).
std::optional<std::pair<std::size_t, std::size_t>> parseShard(const std::string& text,
                                                              std::string& why) {
    const auto slash = text.find('/');
    auto whole = [](const std::string& s, std::size_t& v) {
        if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
            return false;
        v = std::size_t(std::stoul(s));
        return true;
    };
    std::size_t k = 0, n = 0;
    if (slash == std::string::npos || !whole(text.substr(0, slash), k) ||
        !whole(text.substr(slash + 1), n) || n == 0) {
        why = "--shard needs K/N with whole numbers, N at least 1 (e.g. 0/4), not '" + text + "'";
        return std::nullopt;
    }
    if (k >= n) {
        why = "--shard " + text + ": K counts from 0, so it must be below N (0/" +
              std::to_string(n) + " ... " + std::to_string(n - 1) + "/" + std::to_string(n) + ")";
        return std::nullopt;
    }
    return std::pair{k, n};
}

std::string selfExecutable() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("functionlab") : p.string();
}

} // namespace

const CommandSpec& gradeBatchSpec() {
    static const CommandSpec spec{
        .name = "grade batch",
        .summary = "grade a class's submissions into a SQLite gradebook, isolated and resumable",
        .synopsis = {"grade batch --assignment ID|DIR DIR --db GRADEBOOK.sqlite [--jobs N] "
                     "[--roster CSV] [--shard K/N] [--isolation KIND | --no-isolation] [--json]"},
        .description =
            "Grades every submission in DIR — a scene file or a folder per student; the\n"
            "student's id is the name before its first dot — each by `functionlab grade\n"
            "check` in its own child process with limits (CPU time, memory, output, wall\n"
            "clock) and an isolation: no files written and no network — bubblewrap where it\n"
            "runs, else a syscall filter (seccomp). Without either the batch refuses to run\n"
            "unless --no-isolation. A hostile file costs its own budget, never the batch;\n"
            "the gradebook records which isolation each check ran under. Each result is\n"
            "written to the gradebook as soon as it is in: a killed batch loses no finished\n"
            "result, and a batch run again skips submissions already graded with the same\n"
            "content, checker version and rubric. With --shard K/N only the K-th of N\n"
            "disjoint parts of the class is graded (a student's part is a hash of their id,\n"
            "the same on every machine): run the N parts on N machines, each into its own\n"
            "gradebook, then `grade merge` them.\n",
        .positionals = {{.name = "DIR", .help = "the folder of submissions"}},
        .options = {assignmentOption(),
                    gradebookOption("the gradebook (created when missing)"),
                    {.name = "jobs",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "submissions checked at once",
                     .defaultValue = "2",
                     .min = 1,
                     .max = 64},
                    {.name = "roster",
                     .kind = OptionKind::Path,
                     .valueName = "CSV",
                     .help = "import students first: a CSV whose header names an id column "
                             "(and name, email)"},
                    {.name = "shard",
                     .kind = OptionKind::Text,
                     .valueName = "K/N",
                     .help = "grade only the K-th (from 0) of N disjoint parts of the class, by "
                             "student id (a Slurm array task: $SLURM_ARRAY_TASK_ID/N)"},
                    {.name = "time-limit",
                     .kind = OptionKind::Number,
                     .valueName = "SECONDS",
                     .help = "wall clock per submission (CPU time: half of it)",
                     .defaultValue = "60",
                     .min = 1,
                     .max = 3600},
                    {.name = "isolation",
                     .kind = OptionKind::Choice,
                     .valueName = "KIND",
                     .help = "the isolation to check under (default: the strongest this machine "
                             "gives, bubblewrap before syscall-filter)",
                     .choices = {"bubblewrap", "syscall-filter"}},
                    {.name = "no-isolation",
                     .help = "check with limits only (CPU, memory, output, wall clock): files "
                             "can be written and the network reached; only for submissions you "
                             "trust, on a machine with neither bubblewrap nor seccomp"},
                    signingKeyOption(),
                    {.name = "json",
                     .help = "print one JSON object at the end: {\"graded\", \"skipped\", "
                             "\"not_gradable\", \"failed\", \"shard\" (with --shard: \"K/N\"), "
                             "\"isolation\", \"head\": "
                             "{\"entry\", \"hash\", \"publicKey\", \"signature\"}, "
                             "\"problems\": [...]}"}},
        .notes = "A progress line on a terminal. Results: `functionlab grade export`.\n",
        .exitStatus = "0 the batch ran (whatever the scores), 1 the assignment, the folder or the "
                      "gradebook could not be read, or no isolation is available (see "
                      "--no-isolation), 2 usage error",
    };
    return spec;
}

int gradeBatchCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeBatchSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("assignment") || !a->given("db"))
        return usageError(gradeBatchSpec(), "--assignment and --db are required", std::cerr);
    const auto assignment = assignmentOrExplain(a->text("assignment"), std::cerr);
    if (!assignment) return kExitDiagnostic;
    const std::filesystem::path folder = a->positional("DIR");
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
        std::cerr << "functionlab grade batch: " << folder.string() << " is not a folder\n";
        return kExitDiagnostic;
    }
    std::optional<std::pair<std::size_t, std::size_t>> shard;
    if (a->given("shard")) {
        std::string why;
        shard = parseShard(a->text("shard"), why);
        if (!shard) return usageError(gradeBatchSpec(), why, std::cerr);
    }
    if (a->given("isolation") && a->flag("no-isolation"))
        return usageError(gradeBatchSpec(), "--isolation and --no-isolation exclude each other",
                          std::cerr);
    platform::IsolationLimits limits;
    limits.wallSeconds = a->number("time-limit", 60);
    limits.cpuSeconds = limits.wallSeconds / 2;
    limits.isolate = !a->flag("no-isolation");
    if (a->given("isolation"))
        limits.isolation = a->text("isolation") == "bubblewrap"
                               ? platform::Isolation::Bubblewrap
                               : platform::Isolation::SyscallFilter;
    else if (limits.isolate && platform::bestIsolation() == platform::Isolation::LimitsOnly) {
        std::cerr << "functionlab grade batch: this machine can isolate no check: neither "
                     "bubblewrap nor a seccomp filter works here. Install bubblewrap "
                     "(apt-get install bubblewrap), or run with --no-isolation for submissions "
                     "you trust (files could be written, the network reached).\n";
        return kExitDiagnostic;
    }
    try {
        grading::Gradebook book(a->text("db"));
        if (a->given("roster")) {
            std::ifstream in(a->text("roster"), std::ios::binary);
            if (!in) {
                std::cerr << "functionlab grade batch: cannot read " << a->text("roster") << "\n";
                return kExitDiagnostic;
            }
            std::stringstream text;
            text << in.rdbuf();
            for (const auto& p : book.importRoster(text.str()))
                std::cerr << a->text("roster") << ":" << p.line << ":1: error: " << p.message
                          << "\n";
        }
        std::vector<std::string> skipped;
        auto submissions = grading::findSubmissions(folder, skipped);
        if (shard)
            std::erase_if(submissions, [&](const grading::BatchSubmission& s) {
                return grading::shardOf(s.student, shard->second) != shard->first;
            });
        for (const std::string& s : skipped)
            std::cerr << "functionlab grade batch: " << s << "\n";
        grading::BatchOptions o;
        o.jobs = int(a->integer("jobs", 2));
        o.limits = limits;
        o.checkerVersion = grading::kCheckerVersion;
        o.dueUtc = assignment->due.value_or("");
        o.lateFactor = [&](double hours) { return assignment->late.factor(hours); };
        const std::string self = selfExecutable();
        const std::string manifestFolder = assignment->folder.string();
        o.command = [&](const grading::BatchSubmission& s) {
            return std::vector<std::string>{
                self, "grade", "check", "--assignment", manifestFolder, s.path.string(), "--json"};
        };
        const bool terminal = ::isatty(2);
        o.progress = [&](std::size_t done, std::size_t total, const grading::BatchSubmission& s,
                         const std::string& outcome) {
            if (terminal)
                std::cerr << "\r\033[K[" << done << "/" << total << "] " << s.student << ": "
                          << outcome << std::flush;
        };
        const grading::BatchSummary summary =
            grading::gradeBatch(book, assignment->record(), submissions, o);
        if (terminal) std::cerr << "\n";
        for (const std::string& p : summary.problems)
            std::cerr << "functionlab grade batch: " << p << "\n";
        const auto signedHead = signHeadOrSay(book, *a, "grade batch", std::cerr);
        if (a->flag("json")) {
            std::string out = "{\"graded\":" + std::to_string(summary.graded);
            out += ",\"skipped\":" + std::to_string(summary.skipped);
            out += ",\"not_gradable\":" + std::to_string(summary.notGradable);
            out += ",\"failed\":" + std::to_string(summary.failed);
            if (shard)
                out += ",\"shard\":" + jsonString(std::to_string(shard->first) + "/" +
                                                  std::to_string(shard->second));
            out += ",\"isolation\":" +
                   jsonString(limits.isolate ? std::string(platform::isolationName(
                                                   limits.isolation ? *limits.isolation
                                                                    : platform::bestIsolation()))
                                             : std::string("limits only"));
            out += ",\"head\":" + headJson(book.head(), signedHead);
            out += ",\"problems\":[";
            for (std::size_t i = 0; i < summary.problems.size(); ++i) {
                if (i) out += ",";
                out += jsonString(summary.problems[i]);
            }
            std::cout << out << "]}\n";
        } else {
            std::cout << summary.graded << " graded, " << summary.skipped << " unchanged, "
                      << summary.notGradable << " not gradable, " << summary.failed << " failed\n";
        }
    } catch (const platform::SqliteError& e) {
        std::cerr << "functionlab grade batch: " << a->text("db") << ": " << e.what() << "\n";
        return kExitDiagnostic;
    }
    return kExitOk;
}

} // namespace fl::cli
