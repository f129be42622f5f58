#pragma once
// Evaluates a tape at one point. The reference semantics: the batch evaluator
// must agree with it bit for bit, the interval evaluator must contain it.
#include "batch_jit.h"
#include "tape.h"

#include <array>
#include <memory>
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
    bool set(std::string_view name, double value);  // false when the tape has no such parameter
    void rebind(const Tape& tape);                  // the same tape's copy (an evaluator's copy)
    void assign(const std::vector<double>& values); // every value, in order (same count)
    const std::vector<double>& values() const { return values_; }
    // Whether `other` holds the same values bit for bit (== would call +0
    // and -0 the same, and NaN not itself): what compiled code folded in.
    bool sameBitsAs(const std::vector<double>& other) const;
    // A new number at every set() and assign(), unique across all
    // ParameterValues (a copy, or an assignment of one to another, carries
    // its values and their number together): equal versions, equal values.
    std::uint64_t version() const { return version_; }

  private:
    const Tape* tape_;
    std::vector<double> values_;
    std::uint64_t version_ = 0;
};

class BatchEvaluator;

// How a ScalarEvaluator runs its tape: interpreted always (the reference), or
// as machine code (BatchEvaluator::evaluateOne, the same bits) once it has
// been asked for kScalarWarmUp points — an evaluator asked for a few points
// never pays for compiling — or from the first point (tests, benchmarks).
// Where no code can be made (no AVX2, FUNCTIONLAB_NO_JIT=1) it interprets.
enum class ScalarCode { Interpreted, AfterWarmUp, Compiled };
inline constexpr unsigned kScalarWarmUp = 256;

class ScalarEvaluator {
  public:
    explicit ScalarEvaluator(const Tape& tape, ScalarCode code = ScalarCode::AfterWarmUp);
    ~ScalarEvaluator();
    // A copy starts interpreted again (its warm-up counted anew); a move
    // takes the code along.
    ScalarEvaluator(const ScalarEvaluator& other);
    ScalarEvaluator(ScalarEvaluator&&) noexcept;
    ScalarEvaluator& operator=(const ScalarEvaluator&) = delete;

    ParameterValues& parameters() { return params_; }

    // The first output. Once compiled, a call is a call of the code (inline:
    // one test of the parameters' version; compiledLast() stays true); else
    // evaluateSlowly's work. (The point goes by value in registers both
    // ways: a caller never stores it.)
    double evaluate(const Point& p) {
        if (direct_ && directVersion_ == params_.version()) [[likely]]
            return direct_(p[0], p[1], p[2], p[3], p[4], p[5], p[6], directRows_);
        return evaluateSlowly(p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
    }
    void evaluateAll(const Point& p, double* outputs); // every output, in tape order
    // Whether the last evaluation ran as machine code.
    bool compiledLast() const { return compiledLast_; }

  private:
    const Tape tape_; // a copy: evaluators never dangle when a CompileResult goes away
    ParameterValues params_;
    std::vector<double> regs_;
    ScalarCode code_;
    unsigned calls_ = 0;
    bool compiledLast_ = false;
    // The machine code's evaluator (made at the warm-up), its parameters
    // kept equal to params_, and whether it could make code for them.
    std::unique_ptr<BatchEvaluator> compiled_;
    std::vector<double> compiledParams_;
    bool prepared_ = false; // compiled_ specialised for compiledParams_ (or no code for them)
    bool noCode_ = false;
    // The code to call straight from evaluate(), its rows and the
    // parameters' version it was checked against (null while there is none
    // or the first output is a constant).
    BatchJit::OnePoint direct_ = nullptr;
    double* directRows_ = nullptr;
    std::uint64_t directVersion_ = 0;
    double evaluateSlowly(double x, double y, double z, double t, double u, double v, double w);
    void run(const Point& p);
    bool runCompiled(const Point& p, double* outputs, std::size_t count);
};

} // namespace fl::formula
