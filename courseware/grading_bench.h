#pragma once
// `functionlab bench grading`: a generated class — variants of the
// reference solutions (constants moved, operations made dead, shapes
// hidden), starters, other labs' solutions, broken and hostile files —
// graded as a batch in isolated processes — in parts, as a cluster would
// (grade batch --shard K/N), the parts then merged (grade merge) — then
// measured in-process:
// time per submission (percentiles), the checker's time per requirement,
// and what accuracy costs in time: the solid comparison's depth against the
// checker's time and against its verdicts.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fl::courseware {

struct GradingBenchOptions {
    int submissions = 200;
    int jobs = 2;
    std::uint32_t seed = 1;
    std::filesystem::path work;           // where the class and the gradebook go
    std::string functionlab;              // the executable that grades (grade check)
    std::vector<int> depths{5, 7, 9, 11}; // compared against the default (9)
    int depthSample = 40;                 // submissions the depth sweep grades
    int requirementSample = 200;          // submissions timed per requirement in-process
    int shards = 4;                       // parts the class is graded in, then merged
};

struct GradingBenchResult {
    int submissions = 0;
    int jobs = 0;
    double classSeconds = 0; // the whole batch (every part), isolated processes
    int shards = 0;
    double mergeMs = 0;            // merging the parts' gradebooks into one
    std::size_t mergedEntries = 0; // the merged log's
    std::size_t mergedGrades = 0;  // students graded in the merged gradebook
    int cores = 0;                 // the cores the batch used: its jobs, at most the machine's
    // Submissions graded per second for each core the batch kept busy.
    double perSecondPerCore() const {
        return classSeconds > 0 && cores > 0 ? double(submissions) / classSeconds / cores : 0;
    }
    double p50 = 0, p95 = 0, max = 0; // seconds per submission (child wall time)
    std::size_t graded = 0, notGradable = 0, failed = 0;
    struct RequirementTime {
        std::string id;
        double meanMs = 0, p95Ms = 0;
    };
    std::vector<RequirementTime> requirements; // in-process, one thread
    double viewMeanMs = 0;                     // showing the scene at its moments
    struct DepthRow {
        int maxDepth = 0;
        double seconds = 0;      // the sample, in-process
        int verdictsChanged = 0; // requirement verdicts that differ from depth 9's
        int undecided = 0;       // submissions whose budget ran out
    };
    std::vector<DepthRow> depths;
};

// Writes the class into options.work/class (cleared first).
GradingBenchResult runGradingBench(const GradingBenchOptions& options);

std::string gradingBenchText(const GradingBenchResult& r);
std::string gradingBenchJson(const GradingBenchResult& r);

} // namespace fl::courseware
