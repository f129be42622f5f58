#include "tape_compose.h"

namespace fl::formula {

std::vector<Val> inlineTape(TapeBuilder& builder, const Tape& tape,
                            const std::array<Val, kInputCount>& inputs,
                            const std::vector<double>& parameterValues, int sourceTag) {
    std::vector<Val> values;
    for (std::size_t p = 0; p < tape.params.size(); ++p)
        values.push_back(Val::constant(p < parameterValues.size() ? parameterValues[p]
                                                                  : tape.params[p].defaultValue));
    return inlineTape(builder, tape, inputs, values, sourceTag);
}

std::vector<Val> inlineTape(TapeBuilder& builder, const Tape& tape,
                            const std::array<Val, kInputCount>& inputs,
                            const std::vector<Val>& parameterValues, int sourceTag) {
    // What each register of the tape holds, as a value of the builder. The
    // tape reuses registers, so the map follows the instructions in order.
    std::vector<Val> regs(std::size_t(tape.registerCount), Val::constant(0));
    for (int i = 0; i < kInputCount; ++i)
        regs[std::size_t(i)] = inputs[std::size_t(i)];
    for (std::size_t p = 0; p < tape.params.size(); ++p)
        regs[std::size_t(tape.params[p].reg)] = p < parameterValues.size()
                                                    ? parameterValues[p]
                                                    : Val::constant(tape.params[p].defaultValue);
    auto operand = [&](const Operand& o) {
        return o.isConst() ? Val::constant(o.value) : regs[std::size_t(o.reg)];
    };
    const SourceRange before = builder.origin();
    for (const Instruction& in : tape.code) {
        SourceRange where = in.origin >= 0 && std::size_t(in.origin) < tape.origins.size()
                                ? tape.origins[std::size_t(in.origin)]
                                : SourceRange{};
        where.source = sourceTag;
        builder.setOrigin(where);
        regs[std::size_t(in.out)] =
            builder.emit(in.op, operand(in.a), operand(in.b), operand(in.c), in.imm0, in.imm1);
    }
    builder.setOrigin(before);
    std::vector<Val> outputs;
    for (const OutputInfo& o : tape.outputs)
        outputs.push_back(operand(o.value));
    return outputs;
}

} // namespace fl::formula
