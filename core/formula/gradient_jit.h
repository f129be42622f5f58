#pragma once
// The gradient evaluator's one point compiled to AVX2 machine code (issue 31
// §1): each register's dual number — the value and three partial
// derivatives, eval_gradient.h's Dual — is one YMM register (value in lane
// 0), so a step's value and slopes come from a handful of vector
// instructions where the interpreter walked four doubles through
// out-of-line calls (~17 ns a step).
//
// Each operation it writes (add, sub, mul, div, neg, abs, square, sqrt, min,
// max, select) is ad::unary's / ad::binary's arithmetic lane for lane: the
// same IEEE operations in the same order, the zero rule of the derivatives
// (0 times anything is 0) as a compare and a mask, min and max choosing
// whole dual numbers by the language's NaN rule and averaging the slopes at
// a tie. The others (SLEEF's functions, pow, the R-functions, noise …) call
// the interpreter's own code for that one instruction: the same code, the
// same bits (gradient_jit_test.cpp checks every operation both ways). Work
// on t alone runs once per moment, as in the scalar code (batch_hoist.h).
//
// A CPU without AVX2, FUNCTIONLAB_NO_JIT=1 and BatchJit::setAllowed(false)
// leave gradients to the interpreter, as for the other evaluators.
#include "eval_gradient.h"
#include "tape.h"

#include <array>
#include <cstddef>
#include <memory>

namespace fl::formula {

class GradientJit {
  public:
    // The code for the tape's instructions, or null where the interpreter
    // must run them. Made once per tape and `wrt` and shared (a cache of the
    // last 256, like the batch code's): every thread's evaluator of one
    // formula uses one copy.
    static std::shared_ptr<const GradientJit> compile(const Tape& tape, std::array<Input, 3> wrt);
    ~GradientJit();

    // Runs the instructions at point p: `regs` holds duals() dual numbers,
    // the parameters' already set (kInputCount onwards: the code never
    // writes them); the code sets the inputs' (p's values, slope 1 along
    // each wrt input) and every instruction's, as walkTape would. Those that
    // depend on t alone keep their duals past the tape's registers and run
    // only when t differs from the last call's (batch_hoist.h's idea): call
    // forgetMoment before the first call with a set of duals.
    using Code = void (*)(const double* p, Dual* regs);
    // Whether the code writes this instruction itself (else it calls the
    // interpreter's code for it, a call a point).
    static bool writesInline(const Instruction& ins);
    Code code() const;
    std::size_t duals() const;
    // Makes the next call at t run the work on t alone.
    void forgetMoment(Dual* regs, double t) const;
    std::size_t codeBytes() const;

  private:
    struct Made;
    explicit GradientJit(std::unique_ptr<Made> made);
    std::unique_ptr<Made> made_;
};

} // namespace fl::formula
