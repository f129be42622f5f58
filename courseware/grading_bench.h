#pragma once
// `functionlab bench grading`: a generated class — variants of the
// reference solutions (constants moved, operations made dead, shapes
// hidden), starters, other labs' solutions, broken and hostile files —
// graded as a batch in isolated processes, then measured in-process:
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
};

struct GradingBenchResult {
    int submissions = 0;
    int jobs = 0;
    double classSeconds = 0;          // the whole batch, isolated processes
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
