#pragma once
// The evaluator benchmark's formulas, each in three forms: FunctionLab source,
// hand-written C++ over arrays, and a muParser expression. Shared by the
// Google Benchmark binary and `functionlab bench eval`.
#include <cstddef>
#include <string>
#include <vector>

namespace fl::bench {

using NativeFn = void (*)(const double* x, const double* y, const double* z, double t, double* out,
                          std::size_t n);

struct EvalFormula {
    std::string name;
    std::string source;   // FunctionLab
    std::string muparser; // the same formula in muParser's syntax
    NativeFn native;      // the same formula written by hand in C++
};

const std::vector<EvalFormula>& evalFormulas();

// The benchmark grid: side^3 points over [-1.2, 1.2]^3, laid out x fastest.
struct Grid {
    std::vector<double> x, y, z;
    double t = 0.3;
    std::size_t size() const { return x.size(); }
};
Grid makeGrid(std::size_t side);

} // namespace fl::bench
