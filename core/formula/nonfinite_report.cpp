#include "nonfinite_report.h"

#include "scalar_ops.h"

#include <cmath>
#include <sstream>

namespace fl::formula {

std::optional<Diagnostic> explainNonFinite(const Tape& tape, const std::vector<double>& params,
                                           const Point& p) {
    for (double c : p)
        if (!std::isfinite(c)) return std::nullopt;
    std::vector<double> r(static_cast<std::size_t>(tape.registerCount), 0.0);
    for (int i = 0; i < kInputCount; ++i)
        r[i] = p[i];
    for (std::size_t i = 0; i < params.size() && i < tape.params.size(); ++i)
        r[kInputCount + i] = params[i];
    auto get = [&r](const Operand& o) { return o.isConst() ? o.value : r[o.reg]; };

    const Instruction* culprit = nullptr;
    double culpritValue = 0.0;
    for (const Instruction& ins : tape.code) {
        const int arity = opArity(ins.op);
        double a = get(ins.a), b = arity >= 2 ? get(ins.b) : 0.0, c = arity >= 3 ? get(ins.c) : 0.0;
        double v = arity == 1   ? ops::unary(ins.op, a, ins.imm0)
                   : arity == 2 ? ops::binary(ins.op, a, b, ins.imm0, ins.imm1)
                                : ops::ternary(ins.op, a, b, c);
        r[ins.out] = v;
        if (!culprit && std::isfinite(a) && std::isfinite(b) && std::isfinite(c) &&
            !std::isfinite(v)) {
            culprit = &ins;
            culpritValue = v;
        }
    }
    bool outputsFinite = true;
    for (const OutputInfo& o : tape.outputs)
        outputsFinite = outputsFinite && std::isfinite(get(o.value));
    if (outputsFinite) return std::nullopt;

    Diagnostic d;
    d.severity = Severity::Warning;
    std::ostringstream os;
    os.precision(6);
    if (culprit) {
        if (culprit->origin >= 0 &&
            culprit->origin < static_cast<std::int32_t>(tape.origins.size()))
            d.range = tape.origins[culprit->origin];
        os << (std::isnan(culpritValue) ? "undefined value (NaN)" : "infinite value") << " from '"
           << opName(culprit->op) << "'";
        d.suggestion = std::isnan(culpritValue)
                           ? "keep arguments inside the function's domain (log and sqrt need "
                             "non-negative input, asin and acos [-1, 1]; 0/0 is undefined)"
                           : "avoid dividing by zero, log(0) and very large exponents";
    } else {
        os << "the definition is not finite";
        d.suggestion = "check the constants of the formula";
    }
    os << " at (x, y, z) = (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    d.message = os.str();
    return d;
}

} // namespace fl::formula
