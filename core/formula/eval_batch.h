#pragma once
// Evaluates a tape over many points per call. Work is cut into blocks of
// kBlock points; each instruction runs as one tight loop over a block (the
// compiler vectorises these), temporaries live in a few reused L1-resident
// registers, inputs are read in place, and everything that does not vary
// across the call (t, parameters, constants and what depends only on them) is
// computed once per call and folded into the loops as immediates.
//
// Threads belong above this class: one evaluator per thread.
#include "batch_jit.h"
#include "batch_step.h"
#include "eval_scalar.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace fl::formula {

// Where each input comes from: an array of n values, or one value for all.
struct BatchInputs {
    std::array<const double*, kInputCount> arrays{};
    std::array<double, kInputCount> uniform{};

    void set(Input i, const double* values) { arrays[static_cast<int>(i)] = values; }
    void set(Input i, double value) {
        arrays[static_cast<int>(i)] = nullptr;
        uniform[static_cast<int>(i)] = value;
    }
};

class BatchEvaluator {
  public:
    static constexpr std::size_t kBlock = 256;
    // Registers are kBlock doubles (2 KiB) plus two cache lines apart, so no
    // two registers a loop reads and writes share their low 12 address bits
    // (4K aliasing stalls loads behind unrelated stores).
    static constexpr std::size_t kStride = kBlock + 16;

    // `compile`: whether to make machine code (batch_jit.h) when it can; a
    // tape evaluated a few times only (one simplified for a mesher block)
    // is cheaper interpreted than compiled.
    explicit BatchEvaluator(const Tape& tape, bool compile = true);
    ~BatchEvaluator();
    BatchEvaluator(const BatchEvaluator&) = delete;
    BatchEvaluator& operator=(const BatchEvaluator&) = delete;

    ParameterValues& parameters() { return params_; }

    // outputs[k] receives n values of the tape's k-th output.
    void evaluate(const BatchInputs& in, std::size_t n, double* const* outputs);
    // Convenience for single-output tapes.
    void evaluate(const BatchInputs& in, std::size_t n, double* output) {
        double* outs[1] = {output};
        evaluate(in, n, outs);
    }

    // One point a call, as machine code (ScalarEvaluator's fast path):
    // prepareOne specialises the tape with every input varying (a new t
    // costs nothing) and the current parameters folded, and compiles it for
    // one point (BatchJit::compileOnePoint) — false where no code can be
    // made (the caller interprets); again after the parameters change.
    // evaluateOne then writes the first `count` outputs at p: the scalar
    // evaluator's bits.
    bool prepareOne();
    void evaluateOne(const Point& p, double* outputs, std::size_t count);
    // The prepared code itself, for a caller that wants no more than a
    // call: onePointCode()(x, y, z, t, u, v, w, onePointRows()) returns the
    // first output where onePointReturns() is not -1 (the output is
    // computed, not a constant or an input: its register).
    BatchJit::OnePoint onePointCode() const { return onePoint_->onePoint(); }
    double* onePointRows() { return oneRows_.data(); }
    std::int32_t onePointReturns() const { return oneReturns_; }
    // How many steps of that code depend on t alone (batch_hoist.h): run
    // once per t.
    std::size_t onePointHoisted() const { return oneHoisted_; }

    // Passes over each block for the last evaluate() (after uniform folding
    // and fusion): what the loops really run, for tests and benchmarks.
    std::size_t passesPerBlock() const { return steps_.size(); }
    // Whether the last evaluate() ran compiled code (batch_jit.h), and its size.
    bool jitActive() const { return jit_ != nullptr; }
    std::size_t jitCodeBytes() const { return jit_ ? jit_->codeBytes() : 0; }
    const BatchJit* jitCode() const { return jit_.get(); } // shared between evaluators
    // What making that code took at the last specialisation (microseconds).
    double jitCompileMicroseconds() const { return jitCompileUs_; }

  private:
    const Tape tape_; // a copy: evaluators never dangle when a CompileResult goes away
    ParameterValues params_;
    std::vector<BatchStep> steps_;     // the tape specialised for the current uniform inputs
    std::vector<double> uniformValue_; // per register, valid where isUniform_
    std::vector<char> isUniform_;
    double* workspace_ = nullptr;      // registerCount * kBlock, 64-byte aligned
    std::array<double*, 3> scratch_{}; // broadcast buffers for ternary operands
    // what the current specialisation was made for
    std::array<bool, kInputCount> specialisedVarying_{};
    std::array<double, kInputCount> specialisedUniform_{};
    std::vector<double> specialisedParams_;
    bool specialised_ = false;
    bool compile_ = true;
    std::shared_ptr<const BatchJit> jit_; // the steps as machine code, when it can be made
    double jitCompileUs_ = 0;             // what making it took (the last specialisation)
    std::vector<double*> tailBase_;       // the rows from the point the JIT stopped at
    std::vector<char> liveOut_;           // per register: an output the steps compute
    // evaluateOne's code, its rows (a double for every register, the ones
    // hoistTimeOnly adds included, then t's last bits), the register it
    // returns (as prepareOne made it: an evaluate() in between specialises
    // anew) and how many steps it runs once per t.
    std::shared_ptr<const BatchJit> onePoint_;
    std::vector<double> oneRows_;
    std::int32_t oneReturns_ = -1;
    std::size_t oneHoisted_ = 0;
    std::int32_t firstOutputComputed() const;
    void makeWorkspace();

    void specialise(const BatchInputs& in);
    void runBlock(double* const* base, std::size_t n);
};

} // namespace fl::formula
