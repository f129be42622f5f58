#include "batch_jit.h"

#include "scalar_ops.h"

#include "batch_step_run.h"
#include "eval_batch.h"
#include "jit_cache.h"

#include "vector_math.h"

#include <xbyak/xbyak.h>
#include <xbyak/xbyak_util.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>

namespace fl::formula {
namespace {

std::atomic<bool> allowed{true};
std::atomic<bool> allowCalls{true}; // tests turn it off to see a tape left interpreted

// vcmppd predicates (quiet: no exception is ever unmasked here).
constexpr std::uint8_t kEqOQ = 0x00, kUnordQ = 0x03, kNeqUQ = 0x04, kEqUQ = 0x08, kNeqOQ = 0x0C,
                       kLtOQ = 0x11, kLeOQ = 0x12, kGeOQ = 0x1D, kGtOQ = 0x1E;

// Whether the emitter writes this step's code itself (else it calls the
// interpreter's code for it, runBatchStep, once over the block).
bool inline_(const BatchStep& s) {
    if (s.fused == Fused::SinCos) return false; // SLEEF's sincos
    if (s.fused != Fused::None) return true;
    switch (s.op) {
    case Op::Neg:
    case Op::Abs:
    case Op::Square:
    case Op::Sqrt:
    case Op::Floor:
    case Op::Ceil:
    case Op::Sign:
    case Op::Not:
    case Op::PowI:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Min:
    case Op::Max:
    case Op::Less:
    case Op::LessEq:
    case Op::Greater:
    case Op::GreaterEq:
    case Op::Equal:
    case Op::NotEqual:
    case Op::And:
    case Op::Or:
    case Op::Select:
        return true;
    default: // SLEEF's functions, round, hypot, mod, the R-functions, noise
        return false;
    }
}

// Whether the JIT makes code for this step (else the whole tape stays with
// the interpreter). Steps it does not write itself run through the
// interpreter's code once per block: called per 4 points from inside the
// loop, with every live value stored around each call, SLEEF's functions
// made the watermelon's colour 1.4x slower than the interpreter; once per
// block they cost what the interpreter's do, and the arithmetic between
// them runs in registers.
bool compiles(const BatchStep& s) {
    if (s.out < kInputCount) return false; // never write an input's array
    if (s.fused == Fused::SinCos && s.out2 < kInputCount) return false;
    return inline_(s) || allowCalls.load();
}

// The registers a step reads, in the order it reads them.
std::vector<std::int32_t> readsOf(const BatchStep& s) {
    std::vector<std::int32_t> r;
    forEachRead(s, [&r](std::int32_t reg) { r.push_back(reg); });
    return r;
}

// A step the one-point code does not write itself, for its one point: the
// scalar evaluator's operation (ops::apply; a paired sine and cosine from one
// sincos), which gives the interpreter's bits by definition — where
// runBatchStep over one point went through the array routines' set-up.
// Every register it reads is in its row (the code stores them there first).
void runOneStep(const BatchStep& s, double* rows) noexcept {
    const double a = s.constA ? s.ca : rows[s.a];
    if (s.fused == Fused::SinCos) {
        const vmath::SinCos sc = vmath::sinCos(a);
        rows[s.out] = sc.sin;
        rows[s.out2] = sc.cos;
        return;
    }
    const int arity = opArity(s.op);
    const double b = arity < 2 ? 0.0 : s.constB ? s.cb : rows[s.b];
    const double c = arity < 3 ? 0.0 : s.constC ? s.cc : rows[s.c];
    rows[s.out] = ops::apply(s.op, a, b, c, s.imm0, s.imm1);
}

using namespace Xbyak;

class Emitter : public CodeGenerator {
  public:
    // `onePoint`: code for a single point (ScalarEvaluator's): the same
    // steps on the low lane of XMM registers, once, no loop, the inputs
    // arriving in xmm0..xmm6 and every register kept in one row of doubles
    // when not in a vector register (BatchJit::OnePoint); `returnReg` is
    // the value it returns. Its first `hoisted` steps depend on t alone
    // (batch_hoist.h): they run only when t's bits are not those kept in
    // the row after the registers'.
    // Else the loop over groups of 8 points in YMM registers.
    Emitter(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
            std::int32_t registerCount, std::size_t maxSize, bool onePoint, std::int32_t returnReg,
            std::size_t hoisted)
        : CodeGenerator(maxSize), onePoint_(onePoint), S1(vec(11)), S2(vec(12)), R(vec(13)),
          CA(vec(14)), CB(vec(15)), steps_(steps), liveOut_(liveOut),
          where_(std::size_t(registerCount), -1), events_(std::size_t(registerCount)),
          rowGpr_(std::size_t(registerCount), -1), returnReg_(returnReg), hoisted_(hoisted) {
        // One point: code that calls nothing keeps its rows' address in a
        // register a call may clobber (rdi), and so saves none.
        const bool calls = std::any_of(steps_.begin(), steps_.end(),
                                       [](const BatchStep& s) { return !inline_(s); });
        if (onePoint_ && !calls) rowsGpr_ = rdi;
        static_assert(kInputCount <= kSlots);
        if (onePoint_) // the inputs arrive in xmm0..: slots whose rows do not hold them yet
            for (std::int32_t i = 0; i < kInputCount; ++i) {
                slots_[std::size_t(i)] = {i, true, false};
                where_[std::size_t(i)] = i;
            }
        // At most a few constants a step: the pool never moves once r14 (the
        // batch code's) holds its address.
        pool_.reserve(16 * steps_.size() + 16);
        for (std::size_t k = 0; k < steps_.size(); ++k) {
            for (std::int32_t r : readsOf(steps_[k]))
                events_[std::size_t(r)].push_back({k, false});
            events_[std::size_t(steps_[k].out)].push_back({k, true});
            if (steps_[k].fused == Fused::SinCos)
                events_[std::size_t(steps_[k].out2)].push_back({k, true});
        }
        emit();
    }

    // Whether the code touches no row but its inputs' and outputs' (no
    // spill, no call to the interpreter's code, which works in the block's
    // rows): it may then run over any number of points in one call, where
    // the inputs and outputs are whole arrays, not a block's rows.
    bool streams() const { return streams_; }

  private:
    static constexpr int kSlots = 11; // ymm0..ymm10 hold values; ymm11..ymm15 are scratch
    const bool onePoint_;
    // Vector register i: all four lanes, or (one point) an XMM, whose low
    // lane is the point's (the other lane is anything, never computed on).
    Xmm vec(int i) const { return onePoint_ ? Xmm(i) : Xmm(Ymm(i)); }
    const Xmm S1, S2;
    Xmm R; // the step's result: its register becomes the slot's (define)
    const Xmm CA, CB;

    // Arithmetic on every lane, or (one point) on the low lane only: the
    // upper lanes of the point's registers are whatever the caller left
    // there (denormals would be slow), and the scalar forms never read them.
    // (b: a register, or one point's constant in memory: withConstant)
    void fadd(const Xmm& d, const Xmm& a, const Xbyak::Operand& b) {
        onePoint_ ? vaddsd(d, a, b) : vaddpd(d, a, b);
    }
    void fsub(const Xmm& d, const Xmm& a, const Xbyak::Operand& b) {
        onePoint_ ? vsubsd(d, a, b) : vsubpd(d, a, b);
    }
    void fmul(const Xmm& d, const Xmm& a, const Xbyak::Operand& b) {
        onePoint_ ? vmulsd(d, a, b) : vmulpd(d, a, b);
    }
    void fdiv(const Xmm& d, const Xmm& a, const Xbyak::Operand& b) {
        onePoint_ ? vdivsd(d, a, b) : vdivpd(d, a, b);
    }
    void fmin(const Xmm& d, const Xmm& a, const Xmm& b) {
        onePoint_ ? vminsd(d, a, b) : vminpd(d, a, b);
    }
    void fmax(const Xmm& d, const Xmm& a, const Xmm& b) {
        onePoint_ ? vmaxsd(d, a, b) : vmaxpd(d, a, b);
    }
    void fsqrt(const Xmm& d, const Xmm& a) { onePoint_ ? vsqrtsd(d, a, a) : vsqrtpd(d, a); }
    void fround(const Xmm& d, const Xmm& a, std::uint8_t mode) {
        onePoint_ ? vroundsd(d, a, a, mode) : vroundpd(d, a, mode);
    }
    void fcmp(const Xmm& d, const Xmm& a, const Xmm& b, std::uint8_t predicate) {
        onePoint_ ? vcmpsd(d, a, b, predicate) : vcmppd(d, a, b, predicate);
    }

    struct Event {
        std::size_t step;
        bool write;
    };
    struct Slot {
        std::int32_t reg = -1;
        bool dirty = false;
        bool pinned = false;
    };

    const std::vector<BatchStep>& steps_;
    const std::vector<char> liveOut_; // a copy: the emitter outlives compile()'s arguments
    std::vector<int> where_;          // register -> slot, or -1 (in its row)
    std::vector<std::vector<Event>> events_;
    std::array<Slot, kSlots> slots_{};
    // The vector register each slot names, and R's: a step's result is not
    // copied into its slot, the slot takes R's register and R the slot's
    // old one (nothing is live in it). Slots 0..6 start as xmm0..xmm6, where
    // one point's inputs arrive.
    std::array<int, kSlots> phys_ = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    int rPhys_ = 13;
    Xmm slotReg(int slot) const { return vec(phys_[std::size_t(slot)]); }
    std::size_t step_ = 0;
    int lane_ = 0;            // the first point of the group being emitted (0 or 4)
    std::vector<int> rowGpr_; // register -> the general register holding its row, or -1
    bool streams_ = true;     // no call, no spill: see streams()
    const std::int32_t returnReg_;
    const std::size_t hoisted_;
    int returnSlot_ = -1; // one point: the slot holding returnReg_ at the end, if any
    // One point: where the registers' rows are (callee-saved where the code
    // calls out); its constants follow its code (poolLabel_), read relative
    // to the instruction.
    Reg64 rowsGpr_ = r13;
    Label poolLabel_;
    // The constants, read with one load each (vbroadcastsd from memory: no
    // shuffle port, unlike a move from a general register).
    std::vector<double> pool_;
    std::unordered_map<std::uint64_t, std::size_t> poolIndex_; // by the constant's bits

    // The step at or after `from` that next reads the value `reg` holds
    // before step `from` runs, or SIZE_MAX when none does; `neededAtEnd`
    // whether the block's caller reads it (an output never written again).
    std::size_t nextRead(std::int32_t reg, std::size_t from, bool* neededAtEnd = nullptr) const {
        for (const Event& e : events_[std::size_t(reg)]) {
            if (e.step < from) continue;
            if (!e.write) return e.step; // a step reading and writing reads first
            if (neededAtEnd) *neededAtEnd = false;
            return std::numeric_limits<std::size_t>::max();
        }
        if (neededAtEnd) *neededAtEnd = liveOut_[std::size_t(reg)] != 0;
        return std::numeric_limits<std::size_t>::max();
    }
    bool needed(std::int32_t reg, std::size_t from) const {
        bool atEnd = false;
        return nextRead(reg, from, &atEnd) != std::numeric_limits<std::size_t>::max() || atEnd;
    }

    // The lanes of register `reg` in this iteration: through the general
    // register that holds its row during the loop (loadRows), else through
    // rax, loaded from the row table. Reading or writing the row of a value
    // that is neither an input nor an output (a spill) ties the code to the
    // block's rows.
    Address lanes(std::int32_t reg) {
        if (onePoint_) return ptr[rowsGpr_ + reg * 8];
        if (reg >= kInputCount && !liveOut_[std::size_t(reg)]) streams_ = false;
        if (const int g = rowGpr_[std::size_t(reg)]; g >= 0)
            return ptr[Reg64(g) + rbx * 8 + lane_ * 8];
        mov(rax, ptr[r12 + reg * 8]);
        return ptr[rax + rbx * 8 + lane_ * 8];
    }
    // Before the loop over steps [first, end): the rows it reads inputs from
    // and writes outputs to, each in a general register of its own while
    // registers last (a call clobbers them, so each loop loads its own).
    // An iteration then makes no load but its values' and constants'.
    void loadRows(std::size_t first, std::size_t end) {
        static constexpr int kFree[] = {
            Xbyak::Operand::RCX, Xbyak::Operand::RDX, Xbyak::Operand::RSI,
            Xbyak::Operand::RDI, Xbyak::Operand::R8,  Xbyak::Operand::R9,
            Xbyak::Operand::R10, Xbyak::Operand::R11, Xbyak::Operand::RBP};
        std::size_t used = 0;
        auto hold = [&](std::int32_t reg) {
            if (rowGpr_[std::size_t(reg)] >= 0 || used == std::size(kFree)) return;
            rowGpr_[std::size_t(reg)] = kFree[used++];
            mov(Reg64(rowGpr_[std::size_t(reg)]), ptr[r12 + reg * 8]);
        };
        for (std::size_t k = first; k < end; ++k) {
            for (std::int32_t r : readsOf(steps_[k]))
                if (r < kInputCount) hold(r);
            if (liveOut_[std::size_t(steps_[k].out)]) hold(steps_[k].out);
        }
    }
    void store(int slot) {
        if (onePoint_)
            vmovsd(lanes(slots_[std::size_t(slot)].reg), slotReg(slot));
        else
            vmovupd(lanes(slots_[std::size_t(slot)].reg), slotReg(slot));
        slots_[std::size_t(slot)].dirty = false;
    }
    void release(int slot) {
        Slot& s = slots_[std::size_t(slot)];
        if (s.reg >= 0) where_[std::size_t(s.reg)] = -1;
        s = Slot{};
    }
    // A free slot: an empty one, else the one whose value is read last
    // (stored first when it is still needed).
    int freeSlot() {
        int best = -1;
        std::size_t bestUse = 0;
        for (int i = 0; i < kSlots; ++i) {
            const Slot& s = slots_[std::size_t(i)];
            if (s.reg < 0) return i;
            if (s.pinned) continue;
            bool atEnd = false;
            std::size_t use = nextRead(s.reg, step_, &atEnd);
            if (use == std::numeric_limits<std::size_t>::max() && !atEnd) {
                release(i); // dead: dropped, never stored
                return i;
            }
            if (best < 0 || use > bestUse) best = i, bestUse = use;
        }
        if (slots_[std::size_t(best)].dirty) store(best);
        release(best);
        return best;
    }
    // The register's value in a vector register, pinned for the current step.
    Xmm in(std::int32_t reg) {
        int slot = where_[std::size_t(reg)];
        if (slot < 0) {
            slot = freeSlot();
            if (onePoint_)
                vmovsd(slotReg(slot), lanes(reg));
            else
                vmovupd(slotReg(slot), lanes(reg));
            slots_[std::size_t(slot)] = {reg, false, true};
            where_[std::size_t(reg)] = slot;
        }
        slots_[std::size_t(slot)].pinned = true;
        return slotReg(slot);
    }
    // R, the step's result, becomes register `reg`'s value.
    void define(std::int32_t reg) {
        int slot = where_[std::size_t(reg)];
        if (slot < 0) {
            slot = freeSlot();
            where_[std::size_t(reg)] = slot;
        }
        slots_[std::size_t(slot)] = {reg, true, false};
        std::swap(phys_[std::size_t(slot)], rPhys_);
        R = vec(rPhys_);
    }
    // The constant's byte offset in the pool (added the first time).
    int pooled(double v) {
        auto [at, added] = poolIndex_.emplace(std::bit_cast<std::uint64_t>(v), pool_.size());
        if (added) {
            if (pool_.size() == pool_.capacity()) throw Xbyak::Error(ERR_CODE_IS_TOO_BIG);
            pool_.push_back(v);
        }
        return int(at->second * sizeof(double));
    }
    // One point: the constant where it lies, after the code.
    Address poolAddress(double v) { return ptr[rip + poolLabel_ + pooled(v)]; }
    void broadcast(const Xmm& y, double v) {
        if (onePoint_)
            vmovsd(y, poolAddress(v));
        else
            vbroadcastsd(Ymm(y.getIdx()), ptr[r14 + pooled(v)]);
    }
    // use(the constant v as an operand): one point, straight from the pool
    // (a scalar form reads 8 bytes); else broadcast into `scratch`.
    template <class Use>
    void withConstant(double v, const Xmm& scratch, Use use) {
        if (onePoint_) {
            use(poolAddress(v));
        } else {
            broadcast(scratch, v);
            use(scratch);
        }
    }
    Xmm operandA(const BatchStep& s) {
        if (!s.constA) return in(s.a);
        broadcast(CA, s.ca);
        return CA;
    }
    Xmm operandB(const BatchStep& s) {
        if (!s.constB) return in(s.b);
        broadcast(CB, s.cb);
        return CB;
    }

    // dst = min or max (x, y) with the language's rule: x when x < y (x > y)
    // or x is NaN, else y. The processor's minsd/maxsd (x, y) is that but
    // for a NaN x, where it gives y (as it does at a tie and for a NaN y):
    // x is blended back in there. Uses S1 and S2.
    void minMax(bool isMin, const Xmm& dst, const Xmm& x, const Xmm& y) {
        fcmp(S2, x, x, kUnordQ);
        isMin ? fmin(S1, x, y) : fmax(S1, x, y);
        vblendvpd(dst, S1, x, S2);
    }
    // R = 1.0 where mask, else 0.0.
    void oneWhere(const Xmm& mask) {
        broadcast(S2, 1.0);
        vandpd(R, mask, S2);
    }
    // mask = truth(x): non-zero and not NaN.
    void truth(const Xmm& mask, const Xmm& x) {
        vxorpd(S2, S2, S2);
        fcmp(mask, x, S2, kNeqOQ);
    }
    void negate(const Xmm& dst, const Xmm& x) {
        broadcast(S2, -0.0);
        vxorpd(dst, x, S2);
    }

    // The interpreter's code for step `s` over the points the batch loops do
    // (r13 of them): one call a block. `s` is the code's own copy of the step.
    // (One point: the scalar evaluator's operation, runOneStep; the code
    // touches no upper lane, so needs no vzeroupper.)
    void emitCall(const BatchStep& s) {
        streams_ = false;
        mov(rdi, reinterpret_cast<std::uint64_t>(&s));
        if (onePoint_) {
            mov(rsi, rowsGpr_);
            mov(rax, reinterpret_cast<std::uint64_t>(&runOneStep));
        } else {
            mov(rsi, r12);
            mov(rdx, r13);
            mov(rcx, r15);
            mov(rax, reinterpret_cast<std::uint64_t>(&runBatchStep));
            vzeroupper();
        }
        call(rax);
    }

    // One step (not a call), its value left in R.
    void step(const BatchStep& s) {
        switch (s.fused) {
        case Fused::SquareOfDiff: {
            const Xmm a = in(s.a);
            withConstant(s.ca, S1, [&](const auto& c) { fsub(R, a, c); });
            fmul(R, R, R);
            return;
        }
        case Fused::SquareTerms: {
            // acc + sign * ((r - offset)^2), with what is exact left out:
            // r - (+0) is r, adding -1 * q is subtracting q, and +0 + q is
            // q (a square is +0 or more, or NaN, which the sum passes on).
            auto square = [&](const Xmm& dst, int t) {
                const Xmm r = in(s.termReg[t]);
                const double offset = s.termOffset[t];
                if (std::bit_cast<std::uint64_t>(offset) == 0) {
                    fmul(dst, r, r);
                } else {
                    withConstant(offset, S1, [&](const auto& c) { fsub(dst, r, c); });
                    fmul(dst, dst, dst);
                }
            };
            int first = 0;
            if (s.constA && std::bit_cast<std::uint64_t>(s.ca) == 0 && s.termSign[0] == 1.0)
                square(R, first++);
            else if (s.constA)
                broadcast(R, s.ca);
            else
                vmovapd(R, in(s.a));
            for (int t = first; t < s.terms; ++t) {
                square(CA, t);
                if (s.termSign[t] == 1.0) {
                    fadd(R, R, CA);
                } else if (s.termSign[t] == -1.0) {
                    fsub(R, R, CA);
                } else {
                    broadcast(S1, s.termSign[t]);
                    fmul(CA, S1, CA);
                    fadd(R, R, CA);
                }
            }
            return;
        }
        case Fused::NegatedOperand: {
            const Xmm a = operandA(s), b = operandB(s);
            if (s.negA) {
                negate(CA, a);
                minMax(s.op == Op::Min, R, CA, b);
            } else {
                negate(CB, b);
                minMax(s.op == Op::Min, R, a, CB);
            }
            return;
        }
        case Fused::MinMaxChain: {
            const bool isMin = s.op == Op::Min;
            // sign * r: r itself for +1, its negation for -1 (both exact).
            auto signed_ = [&](const Xmm& dst, int t) {
                const Xmm r = in(s.chainReg[t]);
                if (s.chainSign[t] == 1.0) {
                    vmovapd(dst, r);
                } else if (s.chainSign[t] == -1.0) {
                    negate(dst, r);
                } else {
                    broadcast(S1, s.chainSign[t]);
                    fmul(dst, S1, r);
                }
            };
            signed_(CA, 0);
            signed_(CB, 1);
            minMax(isMin, R, CA, CB);
            for (int t = 2; t < s.chainCount; ++t) {
                vmovapd(CA, R);
                signed_(CB, t);
                minMax(isMin, R, CA, CB);
            }
            return;
        }
        case Fused::SinCos: // called, never inline
        case Fused::None:
            break;
        }
        switch (s.op) {
        case Op::Neg:
            negate(R, in(s.a));
            return;
        case Op::Abs:
            broadcast(S2, -0.0);
            vandnpd(R, S2, in(s.a));
            return;
        case Op::Square: {
            const Xmm a = in(s.a);
            fmul(R, a, a);
            return;
        }
        case Op::Sqrt:
            fsqrt(R, in(s.a));
            return;
        case Op::Floor:
            fround(R, in(s.a), 0x09);
            return;
        case Op::Ceil:
            fround(R, in(s.a), 0x0A);
            return;
        case Op::Sign: { // a > 0 ? 1 : a < 0 ? -1 : a == 0 ? 0 : a (NaN)
            const Xmm a = in(s.a);
            vxorpd(S2, S2, S2);
            fcmp(S1, a, S2, kGtOQ);
            fcmp(CB, a, S2, kLtOQ);
            broadcast(CA, 1.0);
            vandpd(S1, S1, CA);
            broadcast(CA, -1.0);
            vandpd(CB, CB, CA);
            vorpd(S1, S1, CB);
            fcmp(CB, a, a, kUnordQ);
            vblendvpd(R, S1, a, CB);
            return;
        }
        case Op::Not: { // truth(a) ? 0 : 1
            const Xmm a = in(s.a);
            vxorpd(S2, S2, S2);
            fcmp(S1, a, S2, kEqUQ);
            oneWhere(S1);
            return;
        }
        case Op::PowI: {
            const Xmm a = in(s.a);
            const int k = static_cast<int>(s.imm0);
            if (k == 3) {
                fmul(R, a, a);
                fmul(R, R, a);
            } else if (k == 4) {
                fmul(R, a, a);
                fmul(R, R, R);
            } else if (k == -1) {
                broadcast(S1, 1.0);
                fdiv(R, S1, a);
            } else if (k == -2) {
                fmul(CA, a, a);
                broadcast(S1, 1.0);
                fdiv(R, S1, CA);
            } else { // ops::powi, its steps in its order
                unsigned m = k < 0 ? 0u - static_cast<unsigned>(k) : static_cast<unsigned>(k);
                broadcast(R, 1.0);
                vmovapd(CA, a);
                while (m) {
                    if (m & 1u) fmul(R, R, CA);
                    fmul(CA, CA, CA);
                    m >>= 1;
                }
                if (k < 0) {
                    broadcast(S1, 1.0);
                    fdiv(R, S1, R);
                }
            }
            return;
        }
        case Op::Select: {
            if (s.constA) { // a uniform condition: one operand or the other
                const bool take = s.ca < 0.0 || s.ca > 0.0;
                if (take)
                    vmovapd(R, operandB(s));
                else if (s.constC)
                    broadcast(R, s.cc);
                else
                    vmovapd(R, in(s.c));
                return;
            }
            const Xmm a = in(s.a);
            truth(S1, a);
            const Xmm b = operandB(s);
            Xmm c = CA;
            if (s.constC)
                broadcast(CA, s.cc);
            else
                c = in(s.c);
            vblendvpd(R, c, b, S1);
            return;
        }
        default:
            break;
        }
        // Binary arithmetic: a constant second operand as withConstant gives
        // it (one point: read from memory).
        if (s.op == Op::Add || s.op == Op::Sub || s.op == Op::Mul || s.op == Op::Div) {
            const Xmm a = operandA(s);
            auto arithmetic = [&](const auto& b) {
                s.op == Op::Add   ? fadd(R, a, b)
                : s.op == Op::Sub ? fsub(R, a, b)
                : s.op == Op::Mul ? fmul(R, a, b)
                                  : fdiv(R, a, b);
            };
            if (s.constB)
                withConstant(s.cb, CB, arithmetic);
            else
                arithmetic(in(s.b));
            return;
        }
        // min and max, comparisons, logic
        const Xmm a = operandA(s), b = operandB(s);
        switch (s.op) {
        case Op::Min:
        case Op::Max:
            minMax(s.op == Op::Min, R, a, b);
            break;
        case Op::Less:
        case Op::LessEq:
        case Op::Greater:
        case Op::GreaterEq:
        case Op::Equal:
        case Op::NotEqual: {
            const std::uint8_t p = s.op == Op::Less        ? kLtOQ
                                   : s.op == Op::LessEq    ? kLeOQ
                                   : s.op == Op::Greater   ? kGtOQ
                                   : s.op == Op::GreaterEq ? kGeOQ
                                   : s.op == Op::Equal     ? kEqOQ
                                                           : kNeqUQ;
            fcmp(S1, a, b, p);
            oneWhere(S1);
            break;
        }
        case Op::And:
        case Op::Or:
            truth(S1, a);
            fcmp(R, b, S2, kNeqOQ); // S2 is zero after truth()
            if (s.op == Op::And)
                vandpd(S1, S1, R);
            else
                vorpd(S1, S1, R);
            oneWhere(S1);
            break;
        default:
            break; // compiles() let nothing else through
        }
        return;
    }

    // The loop over the points for steps [first, end), none of them a call.
    void emitLoop(std::size_t first, std::size_t end) {
        if (!onePoint_) {
            loadRows(first, end);
            xor_(ebx, ebx);
        }
        Label loop, done;
        if (!onePoint_) {
            L(loop);
            cmp(rbx, r13);
            jae(done, T_NEAR);
        }
        // Two groups of 4 points an iteration, each all steps: independent
        // chains of work the processor overlaps. (One point: once.)
        for (lane_ = 0; lane_ < (onePoint_ ? 1 : 8); lane_ += 4) {
            for (step_ = first; step_ < end; ++step_) {
                const BatchStep& s = steps_[step_];
                step(s);
                for (Slot& slot : slots_)
                    slot.pinned = false;
                define(s.out);
            }
            step_ = end;
            flush(end);
        }
        if (!onePoint_) {
            add(rbx, 8);
            jmp(loop, T_NEAR);
            L(done);
        }
        std::fill(rowGpr_.begin(), rowGpr_.end(), -1);
    }

    // Every value still needed from `end` on to its row; the slots emptied.
    // (One point, after the last step: the returned value stays in its
    // register, returnSlot_, its row not written.)
    void flush(std::size_t end) {
        returnSlot_ = -1;
        for (int i = 0; i < kSlots; ++i) {
            const Slot& slot = slots_[std::size_t(i)];
            const bool returned =
                onePoint_ && slot.reg >= 0 && slot.reg == returnReg_ && end == steps_.size();
            if (returned) returnSlot_ = i;
            if (slot.reg >= 0 && slot.dirty && !returned && needed(slot.reg, end)) store(i);
            release(i);
        }
    }

    // Runs of steps between calls are each one loop over the points; a
    // call runs once over all of them. What a run leaves for a later one
    // (or the caller) goes to its row at the run's end.
    void emitSteps(std::size_t from, std::size_t to) {
        for (std::size_t first = from; first < to;) {
            if (!inline_(steps_[first])) {
                flush(first); // one point: the inputs the call reads, to their rows
                emitCall(steps_[first++]);
                continue;
            }
            std::size_t end = first;
            while (end < to && inline_(steps_[end]))
                ++end;
            emitLoop(first, end);
            first = end;
        }
    }

    void emit() {
        if (onePoint_) {
            emitOnePoint();
            return;
        }
        // double* const* base (rdi), size_t n (rsi); rbx: the point index.
        push(rbx);
        push(rbp);
        push(r12);
        push(r13);
        push(r14);
        push(r15);
        sub(rsp, 8); // 16-byte aligned for calls
        mov(r12, rdi);
        // the interpreter's three scratch rows follow the registers' (runBatchStep)
        lea(r15, ptr[r12 + int(where_.size() * sizeof(double*))]);
        mov(r13, rsi);
        mov(r14, reinterpret_cast<std::uint64_t>(pool_.data()));
        and_(r13, ~7u); // sign-extended: whole groups of 8 points
        emitSteps(0, steps_.size());
        mov(rax, r13); // the points done
        vzeroupper();
        add(rsp, 8);
        pop(r15);
        pop(r14);
        pop(r13);
        pop(r12);
        pop(rbp);
        pop(rbx);
        ret();
    }

    // double (x, y, z, t, u, v, w in xmm0..xmm6, double* rows (rdi)):
    // returnReg_'s value in xmm0, every other output in its row.
    void emitOnePoint() {
        if (rowsGpr_ == r13) { // it calls out: r13 saved, the stack 16-byte aligned
            push(r13);
            mov(r13, rdi);
        }
        if (hoisted_ > 0) {
            // t's bits against the last call's (both paths on from here with
            // every input in its row)
            const Address lastT = ptr[rowsGpr_ + int(where_.size() * sizeof(double))];
            Label same;
            vmovq(rax, Xmm(int(Input::T)));
            flush(0);
            cmp(rax, lastT);
            je(same, T_NEAR);
            mov(lastT, rax);
            emitSteps(0, hoisted_);
            L(same);
        }
        emitSteps(hoisted_, steps_.size());
        if (returnReg_ >= 0) {
            if (returnSlot_ >= 0 && phys_[std::size_t(returnSlot_)] != 0)
                vmovapd(xmm0, slotReg(returnSlot_));
            else if (returnSlot_ < 0)
                vmovsd(xmm0, lanes(returnReg_));
        }
        if (rowsGpr_ == r13) pop(r13);
        ret();
        align(8);
        L(poolLabel_);
        for (double v : pool_)
            dq(std::bit_cast<std::uint64_t>(v));
    }
};

} // namespace

struct BatchJit::Code {
    std::unique_ptr<Emitter> emitter;
    std::vector<BatchStep> steps; // what the code calls runBatchStep with: never moves
    std::size_t (*run)(double* const*, std::size_t) = nullptr;
    OnePoint onePoint = nullptr; // code from compileOnePoint
    bool streams = false;        // Emitter::streams()
};

BatchJit::BatchJit(std::unique_ptr<Code> code) : code_(std::move(code)) {}
BatchJit::~BatchJit() = default;

bool BatchJit::available() {
    static const bool cpu = [] {
        const char* off = std::getenv("FUNCTIONLAB_NO_JIT");
        if (off && *off && std::strcmp(off, "0") != 0) return false;
        const Xbyak::util::Cpu c;
        return c.has(Xbyak::util::Cpu::tAVX2) && c.has(Xbyak::util::Cpu::tFMA) &&
               vmath::avx2Implementation() != nullptr;
    }();
    return cpu && allowed.load();
}

void BatchJit::setAllowed(bool on) {
    allowed = on;
}

void BatchJit::setCallsAllowed(bool on) {
    allowCalls = on;
}

namespace {

// The steps as text that identifies them exactly: every field compile()
// reads, numbers by their bits (the cache's key).
std::string keyOf(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                  std::int32_t registerCount, bool onePoint, std::int32_t returnReg,
                  std::size_t hoisted) {
    std::string key;
    key.reserve(96 * steps.size() + liveOut.size() + 9);
    auto put = [&key](const auto& v) { appendKey(key, v); };
    put(onePoint);
    put(returnReg);
    put(hoisted);
    put(registerCount);
    key.append(liveOut.begin(), liveOut.end());
    for (const BatchStep& s : steps) {
        put(s.op), put(s.fused), put(s.constA), put(s.constB), put(s.constC);
        put(s.out), put(s.out2), put(s.a), put(s.b), put(s.c), put(s.ca), put(s.cb), put(s.cc);
        put(s.imm0), put(s.imm1), put(s.terms), put(s.negA), put(s.negB), put(s.chainCount);
        for (int t = 0; t < 3; ++t)
            put(s.termReg[t]), put(s.termOffset[t]), put(s.termSign[t]);
        for (int t = 0; t < 4; ++t)
            put(s.chainReg[t]), put(s.chainSign[t]);
    }
    return key;
}

JitCache<BatchJit>& cache() {
    static JitCache<BatchJit> c;
    return c;
}

} // namespace

std::shared_ptr<const BatchJit> BatchJit::compile(const std::vector<BatchStep>& steps,
                                                  const std::vector<char>& liveOut,
                                                  std::int32_t registerCount) {
    return make(steps, liveOut, registerCount, false, -1, 0);
}

std::shared_ptr<const BatchJit>
BatchJit::compileOnePoint(const std::vector<BatchStep>& steps, const std::vector<char>& liveOut,
                          std::int32_t registerCount, std::int32_t returnReg, std::size_t hoisted) {
    return make(steps, liveOut, registerCount, true, returnReg, hoisted);
}

std::shared_ptr<const BatchJit> BatchJit::make(const std::vector<BatchStep>& steps,
                                               const std::vector<char>& liveOut,
                                               std::int32_t registerCount, bool onePoint,
                                               std::int32_t returnReg, std::size_t hoisted) {
    if (!available() || steps.empty()) return nullptr;
    for (const BatchStep& s : steps)
        if (!compiles(s)) return nullptr;
    // (Whether calls are allowed is not in the key: a tape it would have to
    // call for is refused above, and the others' code does not depend on it.)
    std::string key = keyOf(steps, liveOut, registerCount, onePoint, returnReg, hoisted);
    if (auto known = cache().find(key)) return known;
    // Each step's code is under 400 bytes (a chain of four with loads).
    const std::size_t size = 4096 + 1024 * steps.size(); // two groups of 4 an iteration
    std::shared_ptr<const BatchJit> made;
    try {
        auto code = std::make_unique<Code>();
        code->steps = steps;
        code->emitter = std::make_unique<Emitter>(code->steps, liveOut, registerCount, size,
                                                  onePoint, returnReg, hoisted);
        code->emitter->ready();
        if (onePoint)
            code->onePoint = code->emitter->getCode<OnePoint>();
        else
            code->run = code->emitter->getCode<std::size_t (*)(double* const*, std::size_t)>();
        code->streams = code->emitter->streams();
        made = std::shared_ptr<const BatchJit>(new BatchJit(std::move(code)));
    } catch (const std::exception&) { // no executable memory, code too large: interpret
        return nullptr;
    }
    return cache().keep(std::move(key), std::move(made));
}

// Code that spills or calls works in the block's rows: one block at most.
// Code that streams takes every whole group of 8 it is given (the caller
// gives more than a block only where its rows are whole arrays).
std::size_t BatchJit::run(double* const* base, std::size_t n) const {
    return code_->run(base, code_->streams ? n : std::min(n, BatchEvaluator::kBlock));
}

BatchJit::OnePoint BatchJit::onePoint() const {
    return code_->onePoint;
}

std::size_t BatchJit::codeBytes() const {
    return code_->emitter->getSize();
}

} // namespace fl::formula
