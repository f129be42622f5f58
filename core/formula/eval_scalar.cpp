#include "eval_scalar.h"

#include "eval_batch.h"
#include "scalar_ops.h"
#include "tape_walk.h"

#include <atomic>
#include <cstring>

namespace fl::formula {

namespace {
std::uint64_t newParameterVersion() {
    static std::atomic<std::uint64_t> last{0};
    return last.fetch_add(1, std::memory_order_relaxed) + 1;
}
} // namespace

ParameterValues::ParameterValues(const Tape& tape) : tape_(&tape), version_(newParameterVersion()) {
    for (const ParameterInfo& p : tape.params)
        values_.push_back(p.defaultValue);
}

void ParameterValues::rebind(const Tape& tape) {
    tape_ = &tape;
}

void ParameterValues::assign(const std::vector<double>& values) {
    if (values.size() == values_.size()) values_ = values;
    version_ = newParameterVersion();
}

bool ParameterValues::sameBitsAs(const std::vector<double>& other) const {
    // (memcmp of no bytes still wants pointers that are not null: an empty
    // vector's may be.)
    return other.size() == values_.size() &&
           (values_.empty() ||
            std::memcmp(other.data(), values_.data(), values_.size() * sizeof(double)) == 0);
}

bool ParameterValues::set(std::string_view name, double value) {
    for (std::size_t i = 0; i < tape_->params.size(); ++i) {
        if (tape_->params[i].name == name) {
            values_[i] = value;
            version_ = newParameterVersion();
            return true;
        }
    }
    return false;
}

namespace {
struct ScalarDomain {
    using Value = double;
    static double constant(double v) { return v; }
    static double unary(Op op, double a, double imm0) { return ops::unary(op, a, imm0); }
    static double binary(Op op, double a, double b, double imm0, double imm1) {
        return ops::binary(op, a, b, imm0, imm1);
    }
    static double ternary(Op op, double a, double b, double c) { return ops::ternary(op, a, b, c); }
};
} // namespace

ScalarEvaluator::ScalarEvaluator(const Tape& tape, ScalarCode code)
    : tape_(tape), params_(tape_), regs_(static_cast<std::size_t>(tape.registerCount), 0.0),
      code_(code) {}

ScalarEvaluator::~ScalarEvaluator() = default;
// (The parameters name their tape: the copy's, not the one copied from.)
ScalarEvaluator::ScalarEvaluator(const ScalarEvaluator& other)
    : tape_(other.tape_), params_(other.params_), regs_(other.regs_), code_(other.code_) {
    params_.rebind(tape_);
}
ScalarEvaluator::ScalarEvaluator(ScalarEvaluator&& other) noexcept
    : tape_(other.tape_), params_(std::move(other.params_)), regs_(std::move(other.regs_)),
      code_(other.code_), calls_(other.calls_), compiledLast_(other.compiledLast_),
      compiled_(std::move(other.compiled_)), compiledParams_(std::move(other.compiledParams_)),
      prepared_(other.prepared_), noCode_(other.noCode_),
      // (the code and its rows belong to compiled_, which moved whole)
      direct_(other.direct_), directRows_(other.directRows_), directVersion_(other.directVersion_) {
    params_.rebind(tape_);
    other.prepared_ = false; // its code went with the move: made again if it is used
    other.direct_ = nullptr;
}

// The point as machine code, where it can be: after kScalarWarmUp points
// with the same parameters (specialisation folds them in, so new values —
// a slider moving — start the count again rather than compiling at each).
bool ScalarEvaluator::runCompiled(const Point& p, double* outputs, std::size_t count) {
    if (code_ == ScalarCode::Interpreted) return false;
    const std::vector<double>& pv = params_.values();
    if (!params_.sameBitsAs(compiledParams_)) {
        compiledParams_ = pv;
        prepared_ = false;
        direct_ = nullptr;
        calls_ = 0;
    }
    directVersion_ = params_.version(); // the same values as the code's, if any
    if (!prepared_) {
        if (code_ == ScalarCode::AfterWarmUp && calls_ < kScalarWarmUp) {
            ++calls_;
            return false;
        }
        prepared_ = true;
        noCode_ = !BatchJit::available();
        if (noCode_) return false;
        if (!compiled_) compiled_ = std::make_unique<BatchEvaluator>(tape_, false); // no batch code
        compiled_->parameters().assign(pv);
        noCode_ = !compiled_->prepareOne();
        if (!noCode_ && compiled_->onePointReturns() >= 0) {
            direct_ = compiled_->onePointCode();
            directRows_ = compiled_->onePointRows();
        }
    }
    if (noCode_) return false;
    compiled_->evaluateOne(p, outputs, count);
    return true;
}

void ScalarEvaluator::run(const Point& p) {
    double* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = p[i];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = pv[i];
    walkTape<ScalarDomain>(tape_, r);
}

double ScalarEvaluator::evaluateSlowly(double x, double y, double z, double t, double u, double v,
                                       double w) {
    const Point p{x, y, z, t, u, v, w};
    if (tape_.outputs.empty()) return 0.0;
    double out = 0.0;
    compiledLast_ = runCompiled(p, &out, 1);
    if (compiledLast_) return out;
    run(p);
    return tapeOutput<ScalarDomain>(tape_, regs_.data(), 0);
}

void ScalarEvaluator::evaluateAll(const Point& p, double* outputs) {
    compiledLast_ = runCompiled(p, outputs, tape_.outputs.size());
    if (compiledLast_) return;
    run(p);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i)
        outputs[i] = tapeOutput<ScalarDomain>(tape_, regs_.data(), i);
}

} // namespace fl::formula
