#include "batch_grading.h"

#include "grading/check_report_json.h"
#include "scene/scene_writer.h"
#include "submission_hash.h"

#include <QDateTime>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <mutex>
#include <thread>

namespace fl::grading {
namespace {

std::string modifiedUtc(const std::filesystem::path& p) {
    std::error_code ec;
    const auto t = std::filesystem::last_write_time(p, ec);
    if (ec) return utcNow();
    // libstdc++ 12 has no clock_cast; file_clock and system_clock differ by a
    // fixed offset, measured now.
    const auto system = std::chrono::system_clock::now() +
                        std::chrono::duration_cast<std::chrono::system_clock::duration>(
                            t - std::filesystem::file_time_type::clock::now());
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(system.time_since_epoch()).count();
    return QDateTime::fromSecsSinceEpoch(seconds, Qt::UTC).toString(Qt::ISODate).toStdString();
}

double hoursBetween(const std::string& dueUtc, const std::string& submittedUtc) {
    if (dueUtc.empty()) return 0;
    const QDateTime due = QDateTime::fromString(QString::fromStdString(dueUtc), Qt::ISODate);
    const QDateTime at = QDateTime::fromString(QString::fromStdString(submittedUtc), Qt::ISODate);
    if (!due.isValid() || !at.isValid()) return 0;
    return std::max<double>(0, double(due.secsTo(at)) / 3600.0);
}

// Why a child did not give a verdict, for a student and an instructor.
std::string failureOf(const platform::ChildResult& r, const platform::IsolationLimits& limits) {
    if (!r.startError.empty()) return r.startError;
    if (r.timedOut)
        return "the checker ran out of time (" + std::to_string(int(limits.wallSeconds)) + " s)";
    if (r.signal == SIGXCPU)
        return "the checker used up its CPU time (" + std::to_string(int(limits.cpuSeconds)) +
               " s)";
    if (r.outputCut) return "the checker printed more than allowed";
    if (r.signal != 0)
        return "the checker stopped on signal " + std::to_string(r.signal) +
               (r.signal == SIGKILL || r.signal == SIGSEGV || r.signal == SIGABRT
                    ? " (out of memory, or a fault)"
                    : "");
    if (r.exitCode == 2) return "usage error: " + r.err.substr(0, 200);
    return {};
}

} // namespace

std::vector<BatchSubmission> findSubmissions(const std::filesystem::path& folder,
                                             std::vector<std::string>& skipped) {
    std::vector<BatchSubmission> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = e.path().filename().string();
        const bool plain =
            !name.empty() && name[0] != '.' && std::none_of(name.begin(), name.end(), [](char c) {
                return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
            });
        if (!plain) {
            skipped.push_back(name + ": not a plain name");
            continue;
        }
        std::string student = name;
        if (e.is_regular_file(ec)) {
            // alice.x3d, alice.x3dv.gz, bob.wrl: the student is the name before the first dot.
            student = name.substr(0, name.find('.'));
            if (!scene::isSceneFileName(name)) {
                skipped.push_back(name + ": not a scene file");
                continue;
            }
        } else if (!e.is_directory(ec)) {
            skipped.push_back(name + ": neither a file nor a folder");
            continue;
        }
        out.push_back({student, e.path()});
    }
    std::sort(out.begin(), out.end(),
              [](const BatchSubmission& a, const BatchSubmission& b) { return a.path < b.path; });
    // Two submissions for one student (alice.x3d and alice/): both graded,
    // the later in name order counts as newest; say so.
    for (std::size_t i = 1; i < out.size(); ++i)
        if (out[i].student == out[i - 1].student)
            skipped.push_back(out[i].student + ": more than one submission; each is graded");
    return out;
}

bool gradeFromCheckJson(const std::string& json, GradeRecord& g) {
    const std::optional<CheckReportDocument> d = readCheckReportJson(json);
    if (!d) return false;
    g.gradable = d->report.gradable;
    g.score = d->report.score;
    g.maxScore = d->report.maxScore;
    g.requirements = d->report.requirements;
    std::string diagnostics;
    for (const scene::SceneDiagnostic& diagnostic : d->report.diagnostics)
        diagnostics += scene::formatSceneDiagnostic(diagnostic) + "\n";
    g.diagnostics = diagnostics;
    return true;
}

BatchSummary gradeBatch(Gradebook& book, const AssignmentRecord& assignment,
                        const std::vector<BatchSubmission>& submissions,
                        const BatchOptions& options) {
    BatchSummary summary;
    book.registerAssignment(assignment);
    // Hash and skip first (cheap, in order); the rest goes to the workers.
    struct Job {
        const BatchSubmission* submission;
        std::string hash;
    };
    std::vector<Job> jobs;
    std::size_t done = 0;
    for (const BatchSubmission& s : submissions) {
        const std::optional<std::string> hash = submissionHash(s.path);
        if (!hash) {
            ++summary.failed;
            summary.problems.push_back(s.student + ": cannot be read (or too large)");
            if (options.progress) options.progress(++done, submissions.size(), s, "unreadable");
            continue;
        }
        if (book.hasGrade(s.student, assignment.id, *hash, options.checkerVersion,
                          assignment.rubricHash)) {
            ++summary.skipped;
            if (options.progress) options.progress(++done, submissions.size(), s, "unchanged");
            continue;
        }
        jobs.push_back({&s, *hash});
    }
    std::mutex lock; // the gradebook, the summary and the progress
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < jobs.size(); i = next++) {
            const Job& job = jobs[i];
            const auto started = std::chrono::steady_clock::now();
            const platform::ChildResult r =
                platform::runIsolated(options.command(*job.submission), options.limits);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            GradeRecord g;
            g.student = job.submission->student;
            g.assignment = assignment.id;
            g.contentHash = job.hash;
            g.path = job.submission->path.string();
            g.submittedAt = modifiedUtc(job.submission->path);
            g.hoursLate = hoursBetween(options.dueUtc, g.submittedAt);
            g.lateFactor = options.lateFactor ? options.lateFactor(g.hoursLate) : 1.0;
            g.checkerVersion = options.checkerVersion;
            g.rubricHash = assignment.rubricHash;
            g.gradedAt = utcNow();
            g.maxScore = assignment.maxAutomatic;
            g.isolation = std::string(platform::isolationName(r.isolation));
            std::string failure = failureOf(r, options.limits);
            if (failure.empty() && !gradeFromCheckJson(r.out, g))
                failure = "the checker gave no verdict (exit " + std::to_string(r.exitCode) + ")";
            std::lock_guard guard(lock);
            summary.secondsPerSubmission.push_back(seconds);
            std::string outcome;
            if (!failure.empty()) {
                // Recorded as not gradable: the student sees why; a run
                // again does not retry the same bytes.
                g.gradable = false;
                g.score = 0;
                g.diagnostics = failure;
                ++summary.failed;
                summary.problems.push_back(g.student + ": " + failure);
                outcome = failure;
            } else if (!g.gradable) {
                ++summary.notGradable;
                outcome = "not gradable";
            } else {
                ++summary.graded;
                char score[64];
                std::snprintf(score, sizeof score, "%g/%g", g.score, g.maxScore);
                outcome = score;
            }
            book.recordGrade(g);
            if (options.progress)
                options.progress(++done, submissions.size(), *job.submission, outcome);
        }
    };
    std::vector<std::thread> threads;
    for (int k = 0; k < std::max(1, options.jobs); ++k)
        threads.emplace_back(worker);
    for (std::thread& t : threads)
        t.join();
    return summary;
}

} // namespace fl::grading
