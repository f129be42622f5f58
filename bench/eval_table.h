#pragma once
// The evaluator comparison behind `functionlab bench eval`: the same formulas
// over the same grid with FunctionLab's batch evaluator, hand-written C++ and
// muParser, in one run; and one point a call, FunctionLab's scalar evaluator
// against the hand-written C++ called per point, and its gradient evaluator
// as machine code against its interpreter. Reports nanoseconds per point
// (best of repeated runs).
#include <cstddef>
#include <string>
#include <vector>

namespace fl::bench {

struct EvalRow {
    std::string formula;
    double functionlab = 0; // ns per point
    double native = 0;
    double muparser = -1;     // < 0: muParser unavailable
    std::string muparserMode; // "bulk" or "per-point", whichever was faster
    double maxDifference = 0; // largest |FunctionLab - native| over the grid (a fairness check)
    bool jit = false;         // FunctionLab ran it as machine code (core/formula/batch_jit.h)
    double jitCompileUs = 0;  // making that code
    // One point a call, as picking, haptics and the grader ask: FunctionLab's
    // scalar evaluator, and the hand-written C++ called for one point.
    double scalar = 0; // ns per point
    double nativeScalar = 0;
    // One point's value and gradient a call (normals, Newton steps, haptic
    // contact): the gradient evaluator as machine code and interpreted.
    double gradient = 0; // ns per point
    double gradientInterpreted = 0;
};

std::vector<EvalRow> runEvalTable(std::size_t side = 64, double secondsPerMeasurement = 0.2);

std::string formatEvalTable(const std::vector<EvalRow>& rows);
std::string evalTableJson(const std::vector<EvalRow>& rows);

} // namespace fl::bench
