#pragma once
// The batch evaluator's steps compiled to AVX2 machine code at load time
// (issue 31 §1): loops over the block, 8 points an iteration (two groups
// of 4, independent work the processor overlaps), every step's value in a
// YMM register while it is live (spilled to its workspace row only under
// register pressure), so a formula runs as the loop a person would write
// by hand. Each operation is the interpreter's, bit for bit: the same IEEE
// operations in the same order (no FMA contraction), min and max with its
// NaN rule, comparisons giving exactly 0 or 1 (batch_jit_test.cpp).
//
// Steps it does not write itself (SLEEF's sin, exp, pow ..., hypot, mod,
// round, the R-functions, noise) run through the interpreter's own code
// for them (runBatchStep), once over the block between the loops: the
// same code, the same bits. A CPU without AVX2, a system that refuses
// executable memory and FUNCTIONLAB_NO_JIT=1 leave tapes to the
// interpreter. Made with xbyak (header-only, Debian's libxbyak-dev):
// docs/design-notes.md says why.
#include "batch_step.h"
#include "tape.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace fl::formula {

class BatchJit {
  public:
    // The compiled steps, or null when the interpreter must run them (see
    // above). `liveOut`: per register, whether evaluate() reads it after the
    // block (a tape output). Code is made once per set of steps and shared
    // (a cache of the last 256): a mesher's threads, each with its own
    // evaluator of one formula, share one copy.
    static std::shared_ptr<const BatchJit> compile(const std::vector<BatchStep>& steps,
                                                   const std::vector<char>& liveOut,
                                                   std::int32_t registerCount);
    // The same steps for one point a call (ScalarEvaluator's code): on the
    // low lane of XMM registers, straight through, as a plain function
    // (onePoint()) that returns register `returnReg` (-1: nothing) and
    // leaves every output in its row. Its first `hoisted` steps depend on t
    // alone (batch_hoist.h): it runs them only when t's bits differ from
    // those it keeps in rows[registerCount]. Cached beside the batch code.
    static std::shared_ptr<const BatchJit>
    compileOnePoint(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                    std::int32_t registerCount, std::int32_t returnReg, std::size_t hoisted);
    ~BatchJit();

    // Runs whole groups of 8 of the n points (base as runBlock takes it, then
    // its scratch rows): all, or a block's where it spills or calls; says how many.
    std::size_t run(double* const* base, std::size_t n) const;
    // Code from compileOnePoint: the point's coordinates (Input's order)
    // arrive in registers, and rows (registerCount + 1 doubles, the
    // caller's: each evaluator its own) keep every register the code stores
    // — the outputs, but for the one returned — and t's last bits. A call
    // costs what a call through a pointer costs: the ScalarEvaluator calls
    // it from its inline evaluate().
    using OnePoint = double (*)(double x, double y, double z, double t, double u, double v,
                                double w, double* rows);
    OnePoint onePoint() const;

    std::size_t codeBytes() const;

    // Whether compile() may make code at all: AVX2 on this CPU, not turned
    // off by FUNCTIONLAB_NO_JIT=1 or by setAllowed(false) (tests compare
    // both ways in one process).
    static bool available();
    static void setAllowed(bool allowed);
    // Whether tapes with steps it does not write itself are compiled (the
    // default) or left to the interpreter whole (tests turn it off to see
    // such a tape interpreted).
    static void setCallsAllowed(bool allowed);

  private:
    struct Code;
    static std::shared_ptr<const BatchJit> make(const std::vector<BatchStep>& steps,
                                                const std::vector<char>& liveOut,
                                                std::int32_t registerCount, bool onePoint,
                                                std::int32_t returnReg, std::size_t hoisted);
    explicit BatchJit(std::unique_ptr<Code> code);
    std::unique_ptr<Code> code_;
};

} // namespace fl::formula
