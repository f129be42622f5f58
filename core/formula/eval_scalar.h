#pragma once
// Evaluates a tape at one point. The reference semantics: the batch evaluator
// must agree with it bit for bit, the interval evaluator must contain it.
#include "tape.h"

#include <array>
#include <string_view>
#include <vector>

namespace fl::formula {

// Coordinates of one point: x y z t u v w, in the order of `Input`.
using Point = std::array<double, kInputCount>;

inline Point pointXYZ(double x, double y, double z, double t = 0.0) {
    return {x, y, z, t, 0.0, 0.0, 0.0};
}

// Parameter values of a tape, starting at their defaults.
class ParameterValues {
  public:
    explicit ParameterValues(const Tape& tape);
    bool set(std::string_view name, double value); // false when the tape has no such parameter
    const std::vector<double>& values() const { return values_; }

  private:
    const Tape* tape_;
    std::vector<double> values_;
};

class ScalarEvaluator {
  public:
    explicit ScalarEvaluator(const Tape& tape);

    ParameterValues& parameters() { return params_; }

    double evaluate(const Point& p);                   // the first output
    void evaluateAll(const Point& p, double* outputs); // every output, in tape order
    // Registers after the last evaluation (for diagnostics: which step went non-finite).
    const std::vector<double>& registers() const { return regs_; }

  private:
    const Tape tape_; // a copy: evaluators never dangle when a CompileResult goes away
    ParameterValues params_;
    std::vector<double> regs_;
    void run(const Point& p);
};

} // namespace fl::formula
