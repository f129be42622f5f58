#include "nonfinite_report.h"

#include "scalar_ops.h"

#include <cmath>
#include <sstream>

namespace fl::formula {

namespace {

struct Trace {
    double value = 0.0;
    int operandWriter[3] = {-1, -1,
                            -1}; // instruction that produced each operand, -1: input/constant
    double operand[3] = {0.0, 0.0, 0.0};
};

} // namespace

std::optional<Diagnostic> explainNonFinite(const Tape& tape, const std::vector<double>& params,
                                           const Point& p) {
    for (int i = 0; i < kInputCount; ++i)
        if (tape.usesInput[i] && !std::isfinite(p[i]))
            return std::nullopt; // not the formula's doing
    std::vector<double> r(static_cast<std::size_t>(tape.registerCount), 0.0);
    std::vector<int> writer(static_cast<std::size_t>(tape.registerCount), -1);
    for (int i = 0; i < kInputCount; ++i)
        r[i] = p[i];
    for (std::size_t i = 0; i < params.size() && i < tape.params.size(); ++i)
        r[kInputCount + i] = params[i];

    // Forward: values, and who produced each operand.
    std::vector<Trace> trace(tape.code.size());
    for (std::size_t k = 0; k < tape.code.size(); ++k) {
        const Instruction& ins = tape.code[k];
        const Operand* ops3[3] = {&ins.a, &ins.b, &ins.c};
        const int arity = opArity(ins.op);
        Trace& t = trace[k];
        for (int j = 0; j < arity; ++j) {
            t.operand[j] = ops3[j]->isConst() ? ops3[j]->value : r[ops3[j]->reg];
            t.operandWriter[j] = ops3[j]->isConst() ? -1 : writer[ops3[j]->reg];
        }
        t.value = ops::apply(ins.op, t.operand[0], t.operand[1], t.operand[2], ins.imm0, ins.imm1);
        r[ins.out] = t.value;
        writer[ins.out] = static_cast<int>(k);
    }

    // The first non-finite output, then backwards along non-finite operands
    // (for a select, only the branch it took) to the operation that turned
    // finite operands into a non-finite result.
    int at = -1;
    bool constantOutput = false;
    for (const OutputInfo& o : tape.outputs) {
        double v = o.value.isConst() ? o.value.value : r[o.value.reg];
        if (std::isfinite(v)) continue;
        if (o.value.isConst())
            constantOutput = true;
        else
            at = writer[o.value.reg];
        break;
    }
    if (at < 0 && !constantOutput) return std::nullopt;
    // Which operand to follow: one that is non-finite the same way as the
    // result (NaN for NaN, infinite for infinite) first, then any non-finite one.
    bool fromConstant = false; // the walk ended at a non-finite constant or parameter
    while (at >= 0) {
        const Instruction& ins = tape.code[static_cast<std::size_t>(at)];
        const Trace& t = trace[static_cast<std::size_t>(at)];
        const int arity = opArity(ins.op);
        int pick = -1;
        for (int pass = 0; pass < 2 && pick < 0; ++pass) {
            for (int j = 0; j < arity && pick < 0; ++j) {
                if (ins.op == Op::Select && j != (ops::truth(t.operand[0]) ? 1 : 2)) continue;
                if (std::isfinite(t.operand[j])) continue;
                if (pass == 0 && std::isnan(t.operand[j]) != std::isnan(t.value)) continue;
                pick = j;
            }
        }
        if (pick < 0) break; // finite operands, non-finite result: this operation did it
        if (t.operandWriter[pick] < 0) {
            fromConstant = true;
            break;
        }
        at = t.operandWriter[pick];
    }

    Diagnostic d;
    d.severity = Severity::Warning;
    std::ostringstream os;
    os.precision(6);
    if (at >= 0 && fromConstant) {
        const Instruction& ins = tape.code[static_cast<std::size_t>(at)];
        if (ins.origin >= 0 && ins.origin < static_cast<std::int32_t>(tape.origins.size()))
            d.range = tape.origins[static_cast<std::size_t>(ins.origin)];
        os << "a constant or parameter here is not finite ("
           << trace[static_cast<std::size_t>(at)].value << ")";
        d.suggestion = "check constants such as 1/0 and parameter values";
    } else if (at >= 0) {
        const Instruction& ins = tape.code[static_cast<std::size_t>(at)];
        const double v = trace[static_cast<std::size_t>(at)].value;
        if (ins.origin >= 0 && ins.origin < static_cast<std::int32_t>(tape.origins.size()))
            d.range = tape.origins[static_cast<std::size_t>(ins.origin)];
        os << (std::isnan(v) ? "undefined value (NaN)" : "infinite value") << " from '"
           << opSourceName(ins.op) << "'";
        d.suggestion = std::isnan(v) ? "keep arguments inside the function's domain (log and sqrt "
                                       "need non-negative input, asin and acos [-1, 1]; 0/0 is "
                                       "undefined)"
                                     : "avoid dividing by zero, log(0) and very large exponents";
    } else {
        os << "the definition is not finite";
        d.suggestion = "check the constants of the formula";
    }
    const char* sep = " at ";
    for (int i = 0; i < kInputCount; ++i) {
        if (!tape.usesInput[i]) continue;
        os << sep << kInputNames[i] << " = " << p[i];
        sep = ", ";
    }
    d.message = os.str();
    return d;
}

} // namespace fl::formula
