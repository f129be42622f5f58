#include "eval_scalar.h"

#include "scalar_ops.h"
#include "tape_walk.h"

namespace fl::formula {

ParameterValues::ParameterValues(const Tape& tape) : tape_(&tape) {
    for (const ParameterInfo& p : tape.params)
        values_.push_back(p.defaultValue);
}

bool ParameterValues::set(std::string_view name, double value) {
    for (std::size_t i = 0; i < tape_->params.size(); ++i) {
        if (tape_->params[i].name == name) {
            values_[i] = value;
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

ScalarEvaluator::ScalarEvaluator(const Tape& tape)
    : tape_(tape), params_(tape_), regs_(static_cast<std::size_t>(tape.registerCount), 0.0) {}

void ScalarEvaluator::run(const Point& p) {
    double* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = p[i];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = pv[i];
    walkTape<ScalarDomain>(tape_, r);
}

double ScalarEvaluator::evaluate(const Point& p) {
    run(p);
    return tape_.outputs.empty() ? 0.0 : tapeOutput<ScalarDomain>(tape_, regs_.data(), 0);
}

void ScalarEvaluator::evaluateAll(const Point& p, double* outputs) {
    run(p);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i)
        outputs[i] = tapeOutput<ScalarDomain>(tape_, regs_.data(), i);
}

} // namespace fl::formula
