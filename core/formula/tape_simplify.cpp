#include "tape_simplify.h"

#include "register_pool.h"

#include <algorithm>
#include <limits>

namespace fl::formula {

bool hasChoices(const Tape& tape) {
    return std::any_of(tape.code.begin(), tape.code.end(), [](const Instruction& ins) {
        return ins.op == Op::Min || ins.op == Op::Max || ins.op == Op::Select;
    });
}

Keep decide(Op op, const Interval& a, const Interval& b) {
    // Keeping one operand is exact only where the other is never NaN (a NaN
    // from either side would be the result) and the kept one is strictly
    // below (min) or above (max) it at every point. An empty interval (NaN
    // everywhere) has nan set, so it is never the one dropped.
    switch (op) {
    case Op::Min:
        if (!b.nan && a.hi < b.lo) return Keep::A;
        if (!a.nan && b.hi < a.lo) return Keep::B;
        return Keep::All;
    case Op::Max:
        if (!b.nan && a.lo > b.hi) return Keep::A;
        if (!a.nan && b.lo > a.hi) return Keep::B;
        return Keep::All;
    case Op::Select:
        // A condition is true where it is non-zero and not NaN (ops::truth).
        if (!a.nan && (a.lo > 0 || a.hi < 0)) return Keep::B;
        if (a.empty() || (a.lo == 0 && a.hi == 0)) return Keep::C; // only zeros and NaN
        return Keep::All;
    default:
        return Keep::All;
    }
}

namespace {

// A value while simplifying: a fixed register (input or parameter), the
// result of a kept instruction, or a constant.
struct Value {
    enum Kind : std::uint8_t { Fixed, Node, Constant } kind = Constant;
    std::int32_t index = 0; // the fixed register, or the node
    double constant = 0;
};

struct Node {
    const Instruction* ins = nullptr;
    std::int32_t index = 0; // in the tape simplified
    Value a, b, c;
};

} // namespace

Tape simplifyTape(const Tape& tape, const std::vector<Keep>& keep,
                  std::vector<std::int32_t>* source) {
    const std::int32_t fixed = kInputCount + std::int32_t(tape.params.size());
    // Forward: what each register holds, as a value of the simplified tape.
    std::vector<Value> holds(std::size_t(tape.registerCount));
    for (std::int32_t r = 0; r < fixed; ++r)
        holds[std::size_t(r)] = {Value::Fixed, r, 0};
    auto valueOf = [&](const Operand& o) {
        return o.isConst() ? Value{Value::Constant, 0, o.value} : holds[std::size_t(o.reg)];
    };
    std::vector<Node> nodes;
    nodes.reserve(tape.code.size());
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        const Instruction& ins = tape.code[i];
        const Keep k = i < keep.size() ? keep[i] : Keep::All;
        Value& out = holds[std::size_t(ins.out)];
        if (k != Keep::All) {
            out = valueOf(k == Keep::A ? ins.a : k == Keep::B ? ins.b : ins.c);
            continue;
        }
        const int arity = opArity(ins.op);
        Node n{&ins, std::int32_t(i), valueOf(ins.a), arity >= 2 ? valueOf(ins.b) : Value{},
               arity >= 3 ? valueOf(ins.c) : Value{}};
        out = {Value::Node, std::int32_t(nodes.size()), 0};
        nodes.push_back(n);
    }
    std::vector<Value> outputs;
    for (const OutputInfo& o : tape.outputs)
        outputs.push_back(valueOf(o.value));

    // Backward: which nodes the outputs need, and each one's last reader.
    constexpr std::int32_t kForever = std::numeric_limits<std::int32_t>::max();
    const std::int32_t count = std::int32_t(nodes.size());
    if (source) source->clear();
    std::vector<char> live(std::size_t(count), 0);
    std::vector<std::int32_t> lastUse(std::size_t(count), -1);
    for (const Value& v : outputs)
        if (v.kind == Value::Node) {
            live[std::size_t(v.index)] = 1;
            lastUse[std::size_t(v.index)] = kForever;
        }
    for (std::int32_t id = count - 1; id >= 0; --id) {
        if (!live[std::size_t(id)]) continue;
        const Node& n = nodes[std::size_t(id)];
        for (const Value* v : {&n.a, &n.b, &n.c})
            if (v->kind == Value::Node) {
                live[std::size_t(v->index)] = 1;
                lastUse[std::size_t(v->index)] = std::max(lastUse[std::size_t(v->index)], id);
            }
    }

    // Registers by liveness, as the tape builder assigns them.
    Tape out;
    out.params = tape.params;
    out.origins = tape.origins;
    std::vector<std::int32_t> regOf(std::size_t(count), -1);
    RegisterPool registers(fixed);
    auto operand = [&](const Value& v) {
        switch (v.kind) {
        case Value::Fixed:
            if (v.index < kInputCount) out.usesInput[std::size_t(v.index)] = true;
            return Operand::ofReg(v.index);
        case Value::Node:
            return Operand::ofReg(regOf[std::size_t(v.index)]);
        default:
            return Operand::constant(v.constant);
        }
    };
    for (std::int32_t id = 0; id < count; ++id) {
        if (!live[std::size_t(id)]) continue;
        const Node& n = nodes[std::size_t(id)];
        const std::int32_t reg = registers.take();
        regOf[std::size_t(id)] = reg;
        Instruction ins = *n.ins;
        ins.out = reg;
        const int arity = opArity(ins.op);
        ins.a = operand(n.a);
        ins.b = arity >= 2 ? operand(n.b) : Operand{};
        ins.c = arity >= 3 ? operand(n.c) : Operand{};
        out.code.push_back(ins);
        if (source) source->push_back(n.index);
        std::array<std::int32_t, 3> dying{-1, -1, -1}; // the operands that die here
        const Value* operands[3] = {&n.a, &n.b, &n.c};
        for (int k = 0; k < arity; ++k) {
            const Value* v = operands[k];
            if (v->kind == Value::Node && lastUse[std::size_t(v->index)] == id)
                dying[std::size_t(k)] = regOf[std::size_t(v->index)];
        }
        registers.release(dying);
    }
    out.registerCount = registers.count();
    for (std::size_t i = 0; i < tape.outputs.size(); ++i)
        out.outputs.push_back({tape.outputs[i].name, operand(outputs[i])});
    return out;
}

} // namespace fl::formula
