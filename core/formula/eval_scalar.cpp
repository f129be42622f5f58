#include "eval_scalar.h"

#include "scalar_ops.h"

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

ScalarEvaluator::ScalarEvaluator(const Tape& tape)
    : tape_(tape), params_(tape), regs_(static_cast<std::size_t>(tape.registerCount), 0.0) {}

void ScalarEvaluator::run(const Point& p) {
    double* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = p[i];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = pv[i];
    auto get = [r](const Operand& o) { return o.isConst() ? o.value : r[o.reg]; };
    for (const Instruction& ins : tape_.code) {
        switch (opArity(ins.op)) {
        case 1:
            r[ins.out] = ops::unary(ins.op, get(ins.a), ins.imm0);
            break;
        case 2:
            r[ins.out] = ops::binary(ins.op, get(ins.a), get(ins.b), ins.imm0, ins.imm1);
            break;
        default:
            r[ins.out] = ops::ternary(ins.op, get(ins.a), get(ins.b), get(ins.c));
            break;
        }
    }
}

double ScalarEvaluator::evaluate(const Point& p) {
    run(p);
    if (tape_.outputs.empty()) return 0.0;
    const Operand& o = tape_.outputs[0].value;
    return o.isConst() ? o.value : regs_[o.reg];
}

void ScalarEvaluator::evaluateAll(const Point& p, double* outputs) {
    run(p);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i) {
        const Operand& o = tape_.outputs[i].value;
        outputs[i] = o.isConst() ? o.value : regs_[o.reg];
    }
}

} // namespace fl::formula
