#include "gradient_jit.h"

#include "batch_hoist.h"
#include "batch_jit.h"
#include "jit_cache.h"
#include "vector_math.h"

#include <xbyak/xbyak.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace fl::formula {
namespace {

// vcmppd / vcmpsd predicates (quiet).
constexpr std::uint8_t kEqOQ = 0x00, kUnordQ = 0x03, kNeqOQ = 0x0C, kLtOQ = 0x11, kGtOQ = 0x1E;

// The largest |n| of x^n written inline (its loop has log2 |n| steps; the
// compiler only makes PowI for small integer exponents anyway).
constexpr double kInlinePowI = 64.0;

// What walkTape does for one instruction, for the instructions the code
// does not write itself: the interpreter's own operations on the duals in
// memory (the code keeps every register's dual there), the same bits by
// definition.
void runOneInstruction(const Instruction* ins, Dual* regs) noexcept {
    auto get = [regs](const Operand& o) { return o.isConst() ? Dual{o.value, {}} : regs[o.reg]; };
    switch (opArity(ins->op)) {
    case 1:
        regs[ins->out] = ad::unary(ins->op, get(ins->a), ins->imm0);
        break;
    case 2:
        regs[ins->out] = ad::binary(ins->op, get(ins->a), get(ins->b), ins->imm0, ins->imm1);
        break;
    default:
        regs[ins->out] = ad::ternary(ins->op, get(ins->a), get(ins->b), get(ins->c));
        break;
    }
}

// A sine and a cosine of one register side by side (the tape builder puts
// them so): one sincos gives both values and both slopes (sin' = cos, cos'
// = -sin), as ad::unary gives each from its own.
bool sinCosPair(const Instruction& first, const Instruction& second) {
    const bool sine = first.op == Op::SinOfPair;
    return (sine || first.op == Op::CosOfPair) &&
           second.op == (sine ? Op::CosOfPair : Op::SinOfPair) && !first.a.isConst() &&
           !second.a.isConst() && second.a.reg == first.a.reg && first.out != first.a.reg &&
           second.out != first.a.reg && second.out != first.out;
}

void runSinCosPair(const Instruction* first, Dual* regs) noexcept {
    const Instruction* second = first + 1;
    const Dual a = regs[first->a.reg];
    const vmath::SinCos sc = vmath::sinCos(a.v);
    const bool sine = first->op == Op::SinOfPair;
    regs[sine ? first->out : second->out] = ad::chain(sc.sin, sc.cos, a);
    regs[sine ? second->out : first->out] = ad::chain(sc.cos, -sc.sin, a);
}

bool writtenInline(const Instruction& ins) {
    switch (ins.op) {
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Neg:
    case Op::Abs:
    case Op::Square:
    case Op::Sqrt:
    case Op::Min:
    case Op::Max:
    case Op::Select:
        return true;
    case Op::PowI:
        return std::abs(ins.imm0) <= kInlinePowI;
    default:
        return false;
    }
}

// The tape's instructions with those whose values depend on t alone first,
// each renamed to a register of its own past the tape's (batch_hoist.h's
// rule, the same code): the code runs them only when t's bits differ from
// the last call's.
struct Hoisted {
    std::vector<Instruction> code;
    std::size_t hoisted = 0;
    std::int32_t registerCount = 0;
};

Hoisted hoistTimeOnly(const Tape& tape) {
    Hoisted h;
    h.code = tape.code;
    h.registerCount = tape.registerCount;
    std::vector<char> output(std::size_t(tape.registerCount), 0);
    for (const OutputInfo& o : tape.outputs)
        if (!o.value.isConst()) output[std::size_t(o.value.reg)] = 1;
    h.hoisted = hoistTimeOnlySteps(
        h.code, output, h.registerCount,
        [](Instruction& ins, auto&& f) {
            Operand* operands[3] = {&ins.a, &ins.b, &ins.c};
            for (int k = 0; k < opArity(ins.op); ++k)
                if (!operands[k]->isConst()) f(operands[k]->reg);
        },
        [](Instruction& ins, auto&& f) { f(ins.out); });
    return h;
}

using namespace Xbyak;

// The code: rbx holds the duals' address (32 bytes each); a register's dual
// is written to memory as soon as it is made (so an instruction called out
// for, and the caller, find every one there) and kept in one of eight YMM
// registers while it is used again soon (loads are what a chain waits on;
// stores are not). A call clobbers every vector register.
class Emitter : public CodeGenerator {
  public:
    // The first `hoisted` instructions depend on t alone: they run only when
    // t's bits differ from those kept in the value of dual `moment`.
    Emitter(const std::vector<Instruction>& code, std::size_t hoisted, std::int32_t moment,
            std::array<Input, 3> wrt, const std::array<bool, kInputCount>& inputs,
            std::size_t maxSize)
        : CodeGenerator(maxSize, Xbyak::AutoGrow), code_(code) {
        push(rbx); // the stack is now 16-byte aligned for calls
        mov(rbx, rsi);
        // The inputs' duals: the value, and slope 1 along each wrt input.
        // (The point is read here only: rdi is a call's first argument.)
        for (int i = 0; i < kInputCount; ++i) {
            if (!inputs[std::size_t(i)]) continue;
            std::array<double, 4> unit{};
            for (int k = 0; k < 3; ++k)
                if (int(wrt[std::size_t(k)]) == i) unit[std::size_t(k) + 1] = 1.0;
            vmovsd(Xmm(kT1), ptr[rdi + 8 * i]); // lanes 1..3 cleared
            vorpd(Ymm(kT1), Ymm(kT1), pool(unit));
            vmovupd(ptr[rbx + 32 * i], Ymm(kT1));
        }
        if (hoisted > 0) {
            Label same;
            mov(rax, ptr[rdi + 8 * int(Input::T)]);
            cmp(rax, ptr[rbx + 32 * moment]);
            je(same, T_NEAR);
            mov(ptr[rbx + 32 * moment], rax);
            instructions(0, hoisted);
            L(same);
            forgetAll(); // the two ways here leave different duals in registers
        }
        instructions(hoisted, code_.size());
        vzeroupper();
        pop(rbx);
        ret();
        align(32);
        L(poolLabel_);
        for (const auto& entry : poolOrder_)
            for (double v : entry)
                dq(std::bit_cast<std::uint64_t>(v));
    }

  private:
    void instructions(std::size_t first, std::size_t end) {
        for (step_ = first; step_ < end; ++step_) {
            if (step_ + 1 < end && sinCosPair(code_[step_], code_[step_ + 1])) {
                callOut(code_[step_], &runSinCosPair);
                ++step_;
                continue;
            }
            instruction(code_[step_]);
        }
    }

    // ymm0..7 keep duals; the rest are each instruction's scratch.
    static constexpr int kSlots = 8;
    static constexpr int kCA = 8, kCB = 9, kCC = 10, kT1 = 11, kT2 = 12, kT3 = 13, kT4 = 14,
                         kRes = 15;
    const std::vector<Instruction>& code_;
    std::size_t step_ = 0;
    struct Slot {
        std::int32_t reg = -1;
        std::size_t lastUse = 0;
        bool pinned = false; // an operand of the instruction being written
    };
    std::array<Slot, kSlots> slots_{};

    Label poolLabel_;
    std::map<std::array<std::uint64_t, 4>, int> poolIndex_; // 32-byte entries by their bits
    std::vector<std::array<double, 4>> poolOrder_;

    Address pool(const std::array<double, 4>& lanes) {
        std::array<std::uint64_t, 4> bits;
        for (std::size_t i = 0; i < 4; ++i)
            bits[i] = std::bit_cast<std::uint64_t>(lanes[i]);
        auto [at, added] = poolIndex_.emplace(bits, int(poolOrder_.size()));
        if (added) poolOrder_.push_back(lanes);
        return ptr[rip + poolLabel_ + 32 * at->second];
    }
    Address all(double v) { return pool({v, v, v, v}); }
    // (-0, +0, +0, +0): added to a dual it leaves the value as it is and
    // turns a -0 slope into +0 — the zero rule's 0 for a slope that is 0.
    Address zeroRule() { return pool({-0.0, 0.0, 0.0, 0.0}); }

    Ymm slotReg(int slot) const { return Ymm(slot); }
    int slotOf(std::int32_t reg) const {
        for (int i = 0; i < kSlots; ++i)
            if (slots_[std::size_t(i)].reg == reg) return i;
        return -1;
    }
    // An empty slot, else the unpinned one used longest ago (its dual is in
    // memory already: dropping it costs nothing).
    int freeSlot() {
        int best = -1;
        for (int i = 0; i < kSlots; ++i) {
            const Slot& s = slots_[std::size_t(i)];
            if (s.reg < 0) return i;
            if (s.pinned) continue;
            if (best < 0 || s.lastUse < slots_[std::size_t(best)].lastUse) best = i;
        }
        return best;
    }
    // Operand o's dual in a register: its slot, or a constant's (value, 0,
    // 0, 0) in `constant`.
    Ymm operand(const Operand& o, int constant) {
        if (o.isConst()) {
            vmovupd(Ymm(constant), pool({o.value, 0.0, 0.0, 0.0}));
            return Ymm(constant);
        }
        int slot = slotOf(o.reg);
        if (slot < 0) {
            slot = freeSlot();
            vmovupd(slotReg(slot), ptr[rbx + 32 * o.reg]);
            slots_[std::size_t(slot)].reg = o.reg;
        }
        slots_[std::size_t(slot)].lastUse = step_;
        slots_[std::size_t(slot)].pinned = true;
        return slotReg(slot);
    }
    // The result (in kRes) becomes register `reg`'s dual: stored, and kept
    // in a slot (its old one, if it had one).
    void define(std::int32_t reg) {
        vmovupd(ptr[rbx + 32 * reg], Ymm(kRes));
        for (Slot& s : slots_)
            s.pinned = false;
        int slot = slotOf(reg);
        if (slot < 0) slot = freeSlot();
        vmovapd(slotReg(slot), Ymm(kRes));
        slots_[std::size_t(slot)] = {reg, step_, false};
    }
    void forgetAll() { slots_.fill(Slot{}); }

    // dst = f * a's slopes under the zero rule (+0 where a slope or f is 0),
    // f in every lane of `f`; lane 0 is the product too (the caller blends
    // the value in). Uses m1 and m2; `fNonZero` when f is known not to be 0.
    void term(int dst, const Ymm& a, int f, int m1, int m2, bool fNonZero = false) {
        vmulpd(Ymm(dst), a, Ymm(f));
        vcmppd(Ymm(m1), a, all(0.0), kEqOQ);
        if (!fNonZero) {
            vcmppd(Ymm(m2), Ymm(f), all(0.0), kEqOQ);
            vorpd(Ymm(m1), Ymm(m1), Ymm(m2));
        }
        vandnpd(Ymm(dst), Ymm(m1), Ymm(dst));
    }
    // kRes = (value, f' * a's slopes): ad's chain(), with the value in lane 0
    // of kT1 and f' in lane 0 of kT2.
    void chain(const Ymm& a) {
        vbroadcastsd(Ymm(kT2), Xmm(kT2));
        term(kRes, a, kT2, kT3, kT4);
        vblendpd(Ymm(kRes), Ymm(kRes), Ymm(kT1), 1);
    }
    // x^n for |n| small as ops::powi makes it, step by step: dst's lane 0
    // (uses base).
    void powi(int dst, const Xmm& x, int n, int base) {
        unsigned m = n < 0 ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);
        vmovsd(Xmm(dst), all(1.0));
        vmovapd(Xmm(base), x);
        while (m) {
            if (m & 1u) vmulsd(Xmm(dst), Xmm(dst), Xmm(base));
            vmulsd(Xmm(base), Xmm(base), Xmm(base));
            m >>= 1;
        }
        if (n < 0) {
            vmovsd(Xmm(base), all(1.0));
            vdivsd(Xmm(dst), Xmm(base), Xmm(dst));
        }
    }

    // The interpreter's code for `ins` (and a sincos pair's second): it reads
    // its operands from memory and writes the results there; the vector
    // registers are gone after the call.
    void callOut(const Instruction& ins, void (*run)(const Instruction*, Dual*) noexcept) {
        vzeroupper();
        mov(rdi, reinterpret_cast<std::uint64_t>(&ins));
        mov(rsi, rbx);
        mov(rax, reinterpret_cast<std::uint64_t>(run));
        call(rax);
        forgetAll();
    }

    void instruction(const Instruction& ins) {
        if (!writtenInline(ins)) {
            callOut(ins, &runOneInstruction);
            return;
        }
        const Ymm a = operand(ins.a, kCA);
        switch (ins.op) {
        case Op::Neg: // (-x, -slopes), then a -0 slope to +0
            vxorpd(Ymm(kRes), a, all(-0.0));
            vaddpd(Ymm(kRes), Ymm(kRes), zeroRule());
            break;
        case Op::Abs: // slope 1, -1, or 0 at 0 and NaN
            vmovsd(Xmm(kT1), all(-0.0));
            vandnpd(Xmm(kT1), Xmm(kT1), Xmm(a.getIdx())); // |x|
            vcmpsd(Xmm(kT2), Xmm(a.getIdx()), all(0.0), kGtOQ);
            vandpd(Xmm(kT2), Xmm(kT2), all(1.0));
            vcmpsd(Xmm(kT3), Xmm(a.getIdx()), all(0.0), kLtOQ);
            vandpd(Xmm(kT3), Xmm(kT3), all(1.0));
            vsubsd(Xmm(kT2), Xmm(kT2), Xmm(kT3)); // 1 - 0, 0 - 1 or 0 - 0 = +0
            chain(a);
            break;
        case Op::Square: // x * x, slope 2x (x + x: the same double)
            vmulsd(Xmm(kT1), Xmm(a.getIdx()), Xmm(a.getIdx()));
            vaddsd(Xmm(kT2), Xmm(a.getIdx()), Xmm(a.getIdx()));
            chain(a);
            break;
        case Op::Sqrt: // slope 0.5 / sqrt(x)
            vsqrtsd(Xmm(kT1), Xmm(a.getIdx()), Xmm(a.getIdx()));
            vmovsd(Xmm(kT2), all(0.5));
            vdivsd(Xmm(kT2), Xmm(kT2), Xmm(kT1));
            chain(a);
            break;
        case Op::PowI: { // slope n * x^(n-1), 0 for n = 0
            const int n = static_cast<int>(ins.imm0);
            powi(kT1, Xmm(a.getIdx()), n, kT3);
            if (n == 0) {
                vxorpd(Xmm(kT2), Xmm(kT2), Xmm(kT2));
            } else {
                powi(kT2, Xmm(a.getIdx()), n - 1, kT3);
                vmulsd(Xmm(kT2), Xmm(kT2), all(double(n)));
            }
            chain(a);
            break;
        }
        default:
            binaryOrSelect(ins, a);
            break;
        }
        define(ins.out);
    }

    void binaryOrSelect(const Instruction& ins, const Ymm& a) {
        const Ymm b = operand(ins.b, kCB);
        const Xmm x(a.getIdx()), y(b.getIdx());
        switch (ins.op) {
        case Op::Add: // slopes a's + b's, then a -0 sum to +0
            vaddpd(Ymm(kRes), a, b);
            vaddpd(Ymm(kRes), Ymm(kRes), zeroRule());
            return;
        case Op::Sub:
            vsubpd(Ymm(kRes), a, b);
            vaddpd(Ymm(kRes), Ymm(kRes), zeroRule());
            return;
        case Op::Mul: // x * y; slopes y * a's + x * b's
            vmulsd(Xmm(kT1), x, y);
            vbroadcastsd(Ymm(kT2), y);
            term(kRes, a, kT2, kT3, kT4);
            vbroadcastsd(Ymm(kT2), x);
            term(kCC, b, kT2, kT3, kT4);
            vaddpd(Ymm(kRes), Ymm(kRes), Ymm(kCC));
            vblendpd(Ymm(kRes), Ymm(kRes), Ymm(kT1), 1);
            return;
        case Op::Div: // x / y; slopes (1 / y) * a's + (-x / (y * y)) * b's
            vdivsd(Xmm(kT1), x, y);
            vmovsd(Xmm(kT2), all(1.0));
            vdivsd(Xmm(kT2), Xmm(kT2), y);
            vbroadcastsd(Ymm(kT2), Xmm(kT2));
            term(kRes, a, kT2, kT3, kT4);
            vmulsd(Xmm(kT2), y, y);
            vxorpd(Xmm(kT3), x, all(-0.0));
            vdivsd(Xmm(kT2), Xmm(kT3), Xmm(kT2));
            vbroadcastsd(Ymm(kT2), Xmm(kT2));
            term(kCC, b, kT2, kT3, kT4);
            vaddpd(Ymm(kRes), Ymm(kRes), Ymm(kCC));
            vblendpd(Ymm(kRes), Ymm(kRes), Ymm(kT1), 1);
            return;
        case Op::Min:
        case Op::Max: {
            // At a tie (x == y: a kink) y's value and the mean of the slopes.
            vmulpd(Ymm(kRes), a, all(0.5));
            vcmppd(Ymm(kT4), a, all(0.0), kEqOQ);
            vandnpd(Ymm(kRes), Ymm(kT4), Ymm(kRes));
            vmulpd(Ymm(kCC), b, all(0.5));
            vcmppd(Ymm(kT4), b, all(0.0), kEqOQ);
            vandnpd(Ymm(kCC), Ymm(kT4), Ymm(kCC));
            vaddpd(Ymm(kRes), Ymm(kRes), Ymm(kCC));
            vblendpd(Ymm(kRes), Ymm(kRes), b, 1);
            // Else x's whole dual where x < y (x > y) or x is NaN, y's where not.
            vcmpsd(Xmm(kT2), x, y, ins.op == Op::Min ? kLtOQ : kGtOQ);
            vcmpsd(Xmm(kT3), x, x, kUnordQ);
            vorpd(Xmm(kT2), Xmm(kT2), Xmm(kT3));
            vbroadcastsd(Ymm(kT2), Xmm(kT2));
            vblendvpd(Ymm(kT1), b, a, Ymm(kT2));
            vcmpsd(Xmm(kT3), x, y, kEqOQ);
            vbroadcastsd(Ymm(kT3), Xmm(kT3));
            vblendvpd(Ymm(kRes), Ymm(kT1), Ymm(kRes), Ymm(kT3));
            return;
        }
        case Op::Select: { // b's whole dual where x is true (not 0, not NaN), else c's
            const Ymm c = operand(ins.c, kCC);
            vcmpsd(Xmm(kT2), x, all(0.0), kNeqOQ);
            vbroadcastsd(Ymm(kT2), Xmm(kT2));
            vblendvpd(Ymm(kRes), c, b, Ymm(kT2));
            return;
        }
        default:
            return; // not reached: writtenInline() lists what is written here
        }
    }
};

} // namespace

struct GradientJit::Made {
    std::vector<Instruction> code; // what the code calls out with: never moves
    std::unique_ptr<Emitter> emitter;
    Code run = nullptr;
    std::int32_t moment = -1;
    std::size_t duals = 0;
};

GradientJit::GradientJit(std::unique_ptr<Made> made) : made_(std::move(made)) {}
GradientJit::~GradientJit() = default;

bool GradientJit::writesInline(const Instruction& ins) {
    return writtenInline(ins);
}

GradientJit::Code GradientJit::code() const {
    return made_->run;
}

std::size_t GradientJit::codeBytes() const {
    return made_->emitter->getSize();
}

std::size_t GradientJit::duals() const {
    return made_->duals;
}

void GradientJit::forgetMoment(Dual* regs, double t) const {
    if (made_->moment < 0) return;
    regs[made_->moment].v = std::bit_cast<double>(~std::bit_cast<std::uint64_t>(t));
}

namespace {

JitCache<GradientJit>& cache() {
    static JitCache<GradientJit> c;
    return c;
}

} // namespace

std::shared_ptr<const GradientJit> GradientJit::compile(const Tape& tape,
                                                        std::array<Input, 3> wrt) {
    if (!BatchJit::available()) return nullptr;
    // The code sets the inputs' duals and never the parameters': a tape
    // that wrote either (none does) stays with the interpreter.
    const std::int32_t firstFree = kInputCount + std::int32_t(tape.params.size());
    std::array<bool, kInputCount> inputs = tape.usesInput;
    for (const Instruction& ins : tape.code)
        if (ins.out < firstFree || ins.out >= tape.registerCount) return nullptr;
    for (const OutputInfo& o : tape.outputs) // an output that is an input
        if (!o.value.isConst() && o.value.reg < kInputCount)
            inputs[std::size_t(o.value.reg)] = true;
    // Everything the code depends on: which instructions are hoisted
    // depends on the outputs' registers, their new registers on the count.
    std::string key;
    key.reserve(64 * tape.code.size() + 24 * tape.outputs.size() + 32);
    for (Input i : wrt)
        appendKey(key, i);
    for (bool used : inputs)
        appendKey(key, used);
    appendKey(key, tape.registerCount);
    appendKey(key, tape.params.size());
    for (const OutputInfo& o : tape.outputs)
        appendKey(key, o.value.reg), appendKey(key, o.value.value);
    for (const Instruction& ins : tape.code) {
        appendKey(key, ins.op), appendKey(key, ins.out);
        for (const Operand* o : {&ins.a, &ins.b, &ins.c})
            appendKey(key, o->reg), appendKey(key, o->value);
        appendKey(key, ins.imm0), appendKey(key, ins.imm1);
    }
    if (auto known = cache().find(key)) return known;
    // Each instruction's code is under 200 bytes (a call 30), and it adds at
    // most three 32-byte constants: the buffer starts near the usual size
    // and grows (xbyak's AutoGrow, placed at ready()) where a tape needs more.
    const std::size_t size = 4096 + 128 * tape.code.size();
    std::shared_ptr<const GradientJit> made;
    try {
        auto m = std::make_unique<Made>();
        Hoisted h = hoistTimeOnly(tape);
        m->code = std::move(h.code);
        m->moment = h.hoisted > 0 ? h.registerCount : -1;
        m->duals = std::size_t(h.registerCount) + 1;
        m->emitter =
            std::make_unique<Emitter>(m->code, h.hoisted, h.registerCount, wrt, inputs, size);
        m->emitter->ready();
        m->run = m->emitter->getCode<Code>();
        made = std::shared_ptr<const GradientJit>(new GradientJit(std::move(m)));
    } catch (const std::exception&) { // no executable memory, code too large: interpret
        return nullptr;
    }
    return cache().keep(std::move(key), std::move(made));
}

} // namespace fl::formula
