#include "grading_bench.h"

#include "measure/percentiles.h"

#include "catalogue.h"
#include "grading/batch_grading.h"
#include "grading/checker.h"
#include "grading/gradebook_merge.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <thread>

namespace fl::courseware {
namespace {

std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string number(double v, const char* format = "%.3g") {
    char buf[32];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
    if (const auto at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
}

// One generated submission: its text and what kind of variant it is.
class ClassGenerator {
  public:
    ClassGenerator(std::uint32_t seed, const Assignment& finalLab,
                   const std::vector<std::filesystem::path>& otherSolutions)
        : rng_(seed), solution_(readText(finalLab.solutions.front())),
          starter_(readText(finalLab.starters.front())) {
        for (const auto& p : otherSolutions)
            others_.push_back(readText(p));
    }

    std::string next() {
        const double roll = uniform(0, 1);
        if (roll < 0.40) return moved(solution_);
        if (roll < 0.55) return dead(moved(solution_));
        if (roll < 0.65) return hidden(solution_);
        if (roll < 0.75) return starter_;
        if (roll < 0.85 && !others_.empty())
            return others_[std::size_t(uniform(0, double(others_.size()) - 0.001))];
        if (roll < 0.93)
            return solution_.substr(0, std::size_t(uniform(0.2, 0.9) * solution_.size()));
        return hostile();
    }

  private:
    double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }

    // The same solution with its constants moved: radii, the slab, the knob.
    std::string moved(std::string s) {
        replaceOnce(s, "ball = 0.8^2", "ball = " + number(uniform(0.65, 0.9)) + "^2");
        replaceOnce(s, "slab = 0.6 ", "slab = " + number(uniform(0.4, 0.65)) + " ");
        replaceOnce(s, "hole = 0.3^2", "hole = " + number(uniform(0.15, 0.35)) + "^2");
        replaceOnce(s, "(y - 0.75)", "(y - " + number(uniform(0.65, 0.85)) + ")");
        return s;
    }
    // An intersection with a slab wider than the ball: dead.
    std::string dead(std::string s) {
        replaceOnce(s, "slab = ", "slab = 4 + 0*");
        return s;
    }
    // Everything behind a Switch that shows nothing.
    std::string hidden(std::string s) {
        replaceOnce(s, "<Scene>", "<Scene><Switch whichChoice='-1'>");
        replaceOnce(s, "</Scene>", "</Switch></Scene>");
        return s;
    }
    std::string hostile() {
        std::string body = "u0 = 0.001 - x*x - y*y - z*z;";
        for (int i = 1; i < 300; ++i)
            body += " u" + std::to_string(i) + " = u" + std::to_string(i - 1) +
                    " | (0.001 - (x - " + number(i / 300.0, "%.4f") + ")^2 - y*y - z*z);";
        return "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\nFShape { geometry "
               "FGeometry { type \"explicit\" definition \"" +
               body + " return u299;\" } }\n";
    }

    std::mt19937 rng_;
    std::string solution_, starter_;
    std::vector<std::string> others_;
};

} // namespace

GradingBenchResult runGradingBench(const GradingBenchOptions& options) {
    GradingBenchResult result;
    result.submissions = options.submissions;
    result.jobs = options.jobs;
    result.cores =
        std::max(1, std::min<int>(options.jobs, int(std::thread::hardware_concurrency())));
    const AssignmentLoad lab = findAssignment("implicit-fantasies");
    if (!lab.assignment) throw std::runtime_error("implicit-fantasies is not there");
    std::vector<std::filesystem::path> others;
    for (const AssignmentLoad& a : listAssignments())
        if (a.assignment && a.assignment->id != "implicit-fantasies")
            others.insert(others.end(), a.assignment->solutions.begin(),
                          a.assignment->solutions.end());

    const auto folder = options.work / "class";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    ClassGenerator generate(options.seed, *lab.assignment, others);
    std::vector<std::filesystem::path> files;
    for (int i = 0; i < options.submissions; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "s%03d.x3d", i);
        const std::string text = generate.next();
        std::ofstream(folder / name, std::ios::binary) << text;
        files.push_back(folder / name);
    }

    // 1. The class as `grade batch --shard K/N` grades it on a cluster:
    // isolated processes, `jobs` at once, each part into its own gradebook
    // (here one part after another), then the parts merged into one.
    auto removeGradebook = [](const std::filesystem::path& db) {
        if (!grading::removeGradebookFiles(db.string()))
            throw std::runtime_error("cannot remove the old " + db.string());
    };
    std::vector<std::string> skipped;
    const auto all = grading::findSubmissions(folder, skipped);
    grading::BatchOptions batch;
    batch.jobs = options.jobs;
    batch.checkerVersion = grading::kCheckerVersion;
    const std::string manifest = lab.assignment->folder.string();
    batch.command = [&](const grading::BatchSubmission& s) {
        return std::vector<std::string>{
            options.functionlab, "grade", "check", "--assignment", manifest,
            s.path.string(),     "--json"};
    };
    const int shards = std::max(1, options.shards);
    result.shards = shards;
    std::vector<std::string> parts;
    std::vector<double> perSubmission;
    for (int k = 0; k < shards; ++k) {
        const auto db = options.work / ("part-" + std::to_string(k) + ".sqlite");
        removeGradebook(db);
        parts.push_back(db.string());
        grading::Gradebook book(db.string());
        std::vector<grading::BatchSubmission> mine;
        for (const auto& s : all)
            if (grading::shardOf(s.student, std::size_t(shards)) == std::size_t(k))
                mine.push_back(s);
        const auto started = std::chrono::steady_clock::now();
        const grading::BatchSummary summary =
            grading::gradeBatch(book, lab.assignment->record(), mine, batch);
        result.classSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        perSubmission.insert(perSubmission.end(), summary.secondsPerSubmission.begin(),
                             summary.secondsPerSubmission.end());
        result.graded += summary.graded;
        result.notGradable += summary.notGradable;
        result.failed += summary.failed;
    }
    result.p50 = measure::percentile(perSubmission, 0.50);
    result.p95 = measure::percentile(perSubmission, 0.95);
    result.max = measure::percentile(perSubmission, 1.0);
    const auto merged = options.work / "gradebook.sqlite";
    removeGradebook(merged);
    std::string why;
    const auto mergeStarted = std::chrono::steady_clock::now();
    const auto summary = grading::mergeGradebooks(parts, merged.string(), &why);
    result.mergeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mergeStarted)
            .count();
    if (!summary) throw std::runtime_error("merging the parts: " + why);
    result.mergedEntries = summary->entries;
    result.mergedGrades = summary->grades;

    // 2. In-process, one thread: the checker's time per requirement.
    std::map<std::string, std::vector<double>> times;
    std::vector<double> views;
    std::vector<grading::CheckReport> reference;
    const std::size_t timed =
        std::min<std::size_t>(files.size(), std::size_t(std::max(1, options.requirementSample)));
    for (std::size_t i = 0; i < timed; ++i) {
        const auto& f = files[i];
        grading::CheckReport r = grading::checkSubmission(f.string(), lab.assignment->requirements);
        if (r.gradable) {
            views.push_back(r.viewMilliseconds);
            for (std::size_t i = 0; i < r.requirements.size(); ++i)
                times[r.requirements[i].id].push_back(r.requirementMilliseconds[i]);
        }
        reference.push_back(std::move(r));
    }
    for (const grading::Requirement& q : lab.assignment->requirements) {
        const auto& t = times[q.id];
        double sum = 0;
        for (double v : t)
            sum += v;
        result.requirements.push_back(
            {q.id, t.empty() ? 0 : sum / double(t.size()), measure::percentile(t, 0.95)});
    }
    double sum = 0;
    for (double v : views)
        sum += v;
    result.viewMeanMs = views.empty() ? 0 : sum / double(views.size());

    // 3. What accuracy costs in time: the comparison's depth.
    const std::size_t sample =
        std::min<std::size_t>(reference.size(), std::size_t(options.depthSample));
    for (int depth : options.depths) {
        GradingBenchResult::DepthRow row;
        row.maxDepth = depth;
        grading::CheckOptions o;
        o.compare.maxDepth = depth;
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < sample; ++i) {
            const grading::CheckReport r =
                grading::checkSubmission(files[i].string(), lab.assignment->requirements, o);
            row.undecided += r.budgetExceeded ? 1 : 0;
            for (std::size_t k = 0;
                 k < r.requirements.size() && k < reference[i].requirements.size(); ++k)
                row.verdictsChanged += r.requirements[k].met != reference[i].requirements[k].met;
        }
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        result.depths.push_back(row);
    }
    return result;
}

std::string gradingBenchText(const GradingBenchResult& r) {
    std::ostringstream out;
    out << "class: " << r.submissions << " submissions graded in isolated processes, " << r.jobs
        << " at a time, in " << r.shards << " parts: " << number(r.classSeconds) << " s ("
        << r.graded << " graded, " << r.notGradable << " not gradable, " << r.failed << " failed); "
        << number(r.perSecondPerCore()) << " submissions per second per core\n";
    out << "merge: " << r.shards << " gradebooks into one in " << number(r.mergeMs) << " ms ("
        << r.mergedEntries << " log entries, " << r.mergedGrades << " students graded)\n";
    out << "per submission (child wall time): p50 " << number(r.p50) << " s, p95 " << number(r.p95)
        << " s, max " << number(r.max) << " s\n\n";
    out << "checker time per requirement (in-process, the gradable ones of the first "
        << std::min(r.submissions, 200) << " submissions):\n";
    out << "  showing the scene at its moments   mean " << number(r.viewMeanMs) << " ms\n";
    for (const auto& q : r.requirements) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-34s mean %8.3g ms   p95 %8.3g ms\n", q.id.c_str(),
                      q.meanMs, q.p95Ms);
        out << line;
    }
    out << "\nwhat accuracy costs in time (solid comparison depth, first submissions):\n";
    out << "  depth   cell (of the box side)   time      verdicts changed vs depth 9   budget "
           "ran out\n";
    for (const auto& d : r.depths) {
        char line[160];
        std::snprintf(line, sizeof line,
                      "  %5d   1/%-21d  %6.3g s   %6d                        %6d\n", d.maxDepth,
                      1 << d.maxDepth, d.seconds, d.verdictsChanged, d.undecided);
        out << line;
    }
    return out.str();
}

std::string gradingBenchJson(const GradingBenchResult& r) {
    std::ostringstream out;
    out << "{\"submissions\":" << r.submissions << ",\"jobs\":" << r.jobs
        << ",\"class_seconds\":" << r.classSeconds << ",\"p50_seconds\":" << r.p50
        << ",\"p95_seconds\":" << r.p95 << ",\"max_seconds\":" << r.max
        << ",\"graded\":" << r.graded << ",\"not_gradable\":" << r.notGradable
        << ",\"failed\":" << r.failed << ",\"shards\":" << r.shards
        << ",\"per_second_per_core\":" << r.perSecondPerCore() << ",\"merge_ms\":" << r.mergeMs
        << ",\"merged_entries\":" << r.mergedEntries << ",\"merged_grades\":" << r.mergedGrades
        << ",\"view_mean_ms\":" << r.viewMeanMs << ",\"requirements\":[";
    for (std::size_t i = 0; i < r.requirements.size(); ++i)
        out << (i ? "," : "") << "{\"id\":\"" << r.requirements[i].id
            << "\",\"mean_ms\":" << r.requirements[i].meanMs
            << ",\"p95_ms\":" << r.requirements[i].p95Ms << "}";
    out << "],\"depths\":[";
    for (std::size_t i = 0; i < r.depths.size(); ++i)
        out << (i ? "," : "") << "{\"max_depth\":" << r.depths[i].maxDepth
            << ",\"seconds\":" << r.depths[i].seconds
            << ",\"verdicts_changed\":" << r.depths[i].verdictsChanged
            << ",\"budget_exceeded\":" << r.depths[i].undecided << "}";
    out << "]}";
    return out.str();
}

} // namespace fl::courseware
