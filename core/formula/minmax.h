#pragma once
// min and max as the formula language defines them: NaN from either side
// propagates (an undefined operand makes a set operation undefined there).
// For equal operands the second is returned, so min(+0, -0) = -0 but
// min(-0, +0) = +0: the compiler therefore never reorders their operands
// (opIsCommutative excludes them). One compare-or-unordered and one select:
// the batch loops vectorise them to a few instructions.
namespace fl::formula {

inline double minPropagating(double a, double b) {
    return (a < b || a != a) ? a : b;
}
inline double maxPropagating(double a, double b) {
    return (a > b || a != a) ? a : b;
}

} // namespace fl::formula
