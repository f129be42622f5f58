#include "tape_builder.h"

#include "register_pool.h"

#include "scalar_ops.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace fl::formula {

namespace {
// -0.0 and +0.0 differ for division and atan2, so constants keep their exact bits.
std::uint64_t exactBits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}
} // namespace

std::size_t TapeBuilder::KeyHash::operator()(const Key& k) const {
    std::uint64_t h = static_cast<std::uint64_t>(k.op) * 0x9E3779B97F4A7C15ull;
    auto mix = [&h](std::uint64_t v) { h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2); };
    mix(static_cast<std::uint32_t>(k.an));
    mix(static_cast<std::uint32_t>(k.bn));
    mix(static_cast<std::uint32_t>(k.cn));
    mix(k.ac);
    mix(k.bc);
    mix(k.cc);
    mix(k.i0);
    mix(k.i1);
    return static_cast<std::size_t>(h);
}

TapeBuilder::TapeBuilder() = default;

Val TapeBuilder::leaf(std::int32_t reg) {
    if (auto it = leaves_.find(reg); it != leaves_.end()) return {it->second, 0.0};
    Node n{};
    n.op = Op::Add;
    n.isLeaf = true;
    n.leafRegister = reg;
    n.origin = -1;
    nodes_.push_back(n);
    std::int32_t id = static_cast<std::int32_t>(nodes_.size() - 1);
    leaves_[reg] = id;
    return {id, 0.0};
}

Val TapeBuilder::input(Input which) {
    return leaf(static_cast<std::int32_t>(which));
}

Val TapeBuilder::parameter(std::int32_t index) {
    return leaf(kInputCount + index);
}

bool TapeBuilder::isNegOf(Val v, Val& inner) const {
    if (v.isConst() || nodes_[v.node].isLeaf || nodes_[v.node].op != Op::Neg) return false;
    inner = nodes_[v.node].a;
    return true;
}

Val TapeBuilder::power(Val base, Val exponent) {
    if (exponent.isConst()) {
        double e = exponent.c;
        if (e == 1.0) return base;
        if (e == 2.0) return square(base);
        // (not x^0.5 -> sqrt(x): they differ at -inf and -0)
        if (e == std::trunc(e) && std::abs(e) <= 64.0) return emit(Op::PowI, base, {}, {}, e);
    }
    return emit(Op::Pow, base, exponent);
}

Val TapeBuilder::fold(Op op, Val a, Val b, Val c, double imm0, double imm1) {
    int arity = opArity(op);
    bool allConst = a.isConst() && (arity < 2 || b.isConst()) && (arity < 3 || c.isConst());
    if (allConst) {
        double r = ops::apply(op, a.c, b.c, c.c, imm0, imm1);
        bool inputsNaN =
            std::isnan(a.c) || (arity >= 2 && std::isnan(b.c)) || (arity >= 3 && std::isnan(c.c));
        // An operation that is NaN for every point stays on the tape, so that
        // it is reported where it matters (once, if it reaches an output; not at
        // all in a branch that constant folding removes).
        if (std::isnan(r) && !inputsNaN) return Val{-2, 0.0};
        return Val::constant(r);
    }
    return Val{-2, 0.0}; // not folded
}

Val TapeBuilder::resolveConstant(Val v) {
    if (v.isConst()) return v;
    const Node& n = nodes_[static_cast<std::size_t>(v.node)];
    if (n.isLeaf) return v;
    const int arity = opArity(n.op);
    const Op op = n.op;
    const double imm0 = n.imm0, imm1 = n.imm1;
    const std::int32_t origin = n.origin;
    const Val na = n.a, nb = n.b, nc = n.c; // (the recursion may not grow nodes_, but be safe)
    Val a = resolveConstant(na);
    Val b = arity >= 2 ? resolveConstant(nb) : Val::constant(0.0);
    Val c = arity >= 3 ? resolveConstant(nc) : Val::constant(0.0);
    if (!a.isConst() || !b.isConst() || !c.isConst()) return v;
    double r = ops::apply(op, a.c, b.c, c.c, imm0, imm1);
    if (std::isnan(r) && !std::isnan(a.c) && !std::isnan(b.c) && !std::isnan(c.c) && origin >= 0)
        resolvedUndefined_.push_back(origins_[static_cast<std::size_t>(origin)]);
    return Val::constant(r);
}

Val TapeBuilder::emit(Op op, Val a, Val b, Val c, double imm0, double imm1) {
    Val folded = fold(op, a, b, c, imm0, imm1);
    if (folded.node != -2) return folded;

    // Identities that hold for every double, NaN and infinities included.
    switch (op) {
    case Op::Add: { // only -0 is an exact additive identity (+0 + -0 = +0)
        if (a.isConst(0.0) && std::signbit(a.c)) return b;
        if (b.isConst(0.0) && std::signbit(b.c)) return a;
        // IEEE defines a - b as a + (-b): the negation is free to drop
        Val inner;
        if (isNegOf(b, inner)) return emit(Op::Sub, a, inner);
        if (isNegOf(a, inner)) return emit(Op::Sub, b, inner);
        break;
    }
    case Op::Sub: { // a - (+0) = a for every a, -0 included
        if (b.isConst(0.0) && !std::signbit(b.c)) return a;
        Val inner;
        if (isNegOf(b, inner)) return emit(Op::Add, a, inner);
        break;
    }
    case Op::Mul:
        if (a.isConst(1.0)) return b;
        if (b.isConst(1.0)) return a;
        if (a.isConst(-1.0)) return emit(Op::Neg, b);
        if (b.isConst(-1.0)) return emit(Op::Neg, a);
        if (!a.isConst() && a.node == b.node) return emit(Op::Square, a);
        break;
    case Op::Div:
        if (b.isConst(1.0)) return a;
        break;
    case Op::Neg: {
        Val inner;
        if (isNegOf(a, inner)) return inner;
        break;
    }
    case Op::Min:
    case Op::Max:
        if (!a.isConst() && !b.isConst() && a.node == b.node) return a;
        break;
    case Op::Select:
        if (a.isConst()) return ops::truth(a.c) ? b : c;
        if (!b.isConst() && !c.isConst() && b.node == c.node) return b;
        if (b.isConst() && c.isConst() && exactBits(b.c) == exactBits(c.c)) return b;
        break;
    case Op::PowI:
        if (imm0 == 1.0) return a;
        if (imm0 == 2.0) return emit(Op::Square, a);
        break;
    default:
        break;
    }

    if (opIsCommutative(op)) {
        auto rank = [](Val v) {
            return v.isConst() ? std::make_pair(1, 0) : std::make_pair(0, v.node);
        };
        if (rank(b) < rank(a)) std::swap(a, b);
    }
    int arity = opArity(op);
    if (arity < 2) b = {};
    if (arity < 3) c = {};
    Key key{op,
            a.node,
            b.node,
            c.node,
            a.isConst() ? exactBits(a.c) : 0,
            b.isConst() ? exactBits(b.c) : 0,
            c.isConst() ? exactBits(c.c) : 0,
            exactBits(imm0),
            exactBits(imm1)};
    if (auto it = cse_.find(key); it != cse_.end()) return {it->second, 0.0};

    Node n{op, a, b, c, imm0, imm1, static_cast<std::int32_t>(origins_.size()), false, -1};
    origins_.push_back(origin_);
    nodes_.push_back(n);
    std::int32_t id = static_cast<std::int32_t>(nodes_.size() - 1);
    cse_.emplace(key, id);
    return {id, 0.0};
}

Tape TapeBuilder::finish(const std::vector<Output>& outputs,
                         std::vector<ParameterInfo> params) const {
    const std::int32_t n = static_cast<std::int32_t>(nodes_.size());
    // Liveness: mark what the outputs need, record each node's last use.
    std::vector<char> live(n, 0);
    std::vector<std::int32_t> stack;
    for (const Output& o : outputs)
        if (!o.value.isConst()) stack.push_back(o.value.node);
    while (!stack.empty()) {
        std::int32_t id = stack.back();
        stack.pop_back();
        if (live[id]) continue;
        live[id] = 1;
        const Node& node = nodes_[id];
        if (node.isLeaf) continue;
        for (const Val* v : {&node.a, &node.b, &node.c})
            if (!v->isConst() && v->node >= 0) stack.push_back(v->node);
    }
    // A sine and a cosine of one value become a pair that one sincos computes
    // (SLEEF's costs 1.3 sines where a sine and a cosine cost 2.1): both take
    // the paired opcodes, whose bits every evaluator gives alike, and the
    // later moves up beside the earlier, so the batch evaluator makes one
    // call of them. (Its operand precedes both, so the order stays valid.)
    std::vector<std::int32_t> partner(n, -1);
    {
        std::unordered_map<std::int32_t, std::int32_t> sineOf, cosineOf; // operand -> node
        for (std::int32_t id = 0; id < n; ++id) {
            const Node& node = nodes_[id];
            if (!live[id] || node.isLeaf || node.a.isConst() || node.a.node < 0) continue;
            if (node.op == Op::Sin || node.op == Op::SinOfPair) sineOf.emplace(node.a.node, id);
            if (node.op == Op::Cos || node.op == Op::CosOfPair) cosineOf.emplace(node.a.node, id);
        }
        for (const auto& [operand, sine] : sineOf)
            if (auto c = cosineOf.find(operand); c != cosineOf.end()) {
                partner[sine] = c->second;
                partner[c->second] = sine;
            }
    }
    auto opOf = [&](std::int32_t id) {
        const Op op = nodes_[id].op;
        if (partner[id] < 0) return op;
        return op == Op::Sin || op == Op::SinOfPair ? Op::SinOfPair : Op::CosOfPair;
    };
    std::vector<std::int32_t> order; // the live nodes in emission order
    std::vector<std::int32_t> position(n, -1);
    for (std::int32_t id = 0; id < n; ++id) {
        if (!live[id] || position[id] >= 0) continue;
        position[id] = static_cast<std::int32_t>(order.size());
        order.push_back(id);
        if (const std::int32_t p = partner[id]; p >= 0 && position[p] < 0) {
            position[p] = static_cast<std::int32_t>(order.size());
            order.push_back(p);
        }
    }

    constexpr std::int32_t kForever = std::numeric_limits<std::int32_t>::max();
    std::vector<std::int32_t> lastUse(n, -1); // a position in `order`
    for (const std::int32_t id : order) {
        const Node& node = nodes_[id];
        if (node.isLeaf) continue;
        for (const Val* v : {&node.a, &node.b, &node.c})
            if (!v->isConst() && v->node >= 0) lastUse[v->node] = position[id];
    }
    for (const Output& o : outputs)
        if (!o.value.isConst()) lastUse[o.value.node] = kForever;

    Tape tape;
    tape.params = std::move(params);
    const std::int32_t firstTemp = kInputCount + static_cast<std::int32_t>(tape.params.size());
    std::vector<std::int32_t> regOf(n, -1);
    RegisterPool registers(firstTemp);
    for (const std::int32_t id : order) {
        const Node& node = nodes_[id];
        if (node.isLeaf) {
            regOf[id] = node.leafRegister;
            if (node.leafRegister < kInputCount) tape.usesInput[node.leafRegister] = true;
            continue;
        }
        const std::int32_t reg = registers.take(); // before the operands' are released
        regOf[id] = reg;
        Instruction ins;
        ins.op = opOf(id);
        ins.out = reg;
        auto operand = [&](const Val& v) {
            return v.isConst() ? Operand::constant(v.c)
                               : Operand::ofReg(v.node >= 0 ? regOf[v.node] : 0);
        };
        int arity = opArity(node.op);
        ins.a = operand(node.a);
        if (arity >= 2) ins.b = operand(node.b);
        if (arity >= 3) ins.c = operand(node.c);
        ins.imm0 = node.imm0;
        ins.imm1 = node.imm1;
        ins.origin = node.origin;
        tape.code.push_back(ins);
        // Release the operands that die here.
        std::array<std::int32_t, 3> dying{-1, -1, -1};
        const Val* operands[3] = {&node.a, &node.b, &node.c};
        for (int k = 0; k < arity; ++k) {
            const Val* v = operands[k];
            if (v->isConst() || v->node < 0) continue;
            if (nodes_[v->node].isLeaf || lastUse[v->node] != position[id]) continue;
            dying[std::size_t(k)] = regOf[v->node];
        }
        registers.release(dying);
        if (lastUse[id] == -1)
            registers.release(reg); // computed but unused (cannot happen when live)
    }
    tape.registerCount = registers.count();
    tape.origins = origins_;
    for (const Output& o : outputs) {
        OutputInfo info;
        info.name = o.name;
        info.value =
            o.value.isConst() ? Operand::constant(o.value.c) : Operand::ofReg(regOf[o.value.node]);
        tape.outputs.push_back(info);
    }
    return tape;
}

std::string Tape::disassemble() const {
    std::ostringstream os;
    os.precision(17);
    auto operand = [&](const Operand& o) {
        std::ostringstream s;
        s.precision(17);
        if (o.isConst())
            s << o.value;
        else if (o.reg < kInputCount)
            s << kInputNames[o.reg];
        else if (o.reg < kInputCount + static_cast<std::int32_t>(params.size()))
            s << params[o.reg - kInputCount].name;
        else
            s << "r" << o.reg;
        return s.str();
    };
    for (const Instruction& ins : code) {
        os << "r" << ins.out << " = " << opName(ins.op) << " " << operand(ins.a);
        if (opArity(ins.op) >= 2) os << ", " << operand(ins.b);
        if (opArity(ins.op) >= 3) os << ", " << operand(ins.c);
        if (ins.op == Op::PowI) os << " ^" << ins.imm0;
        if (ins.op == Op::RIntersect || ins.op == Op::RUnion)
            os << " [m=" << ins.imm0 << ", alpha=" << ins.imm1 << "]";
        os << "\n";
    }
    for (const OutputInfo& o : outputs)
        os << o.name << " <- " << operand(o.value) << "\n";
    return os.str();
}

} // namespace fl::formula
