#include "batch_fusion.h"

#include <initializer_list>

namespace fl::formula {

namespace {

class Fuser {
  public:
    Fuser(std::vector<BatchStep>& steps, const Tape& tape)
        : steps_(steps), uses_(steps.size(), 0), dead_(steps.size(), 0) {
        countUses(tape);
    }

    void run() {
        for (std::size_t i = 0; i < steps_.size(); ++i)
            squareOfDiff(i);
        for (std::size_t i = 0; i < steps_.size(); ++i)
            squareTerms(i);
        for (std::size_t i = 0; i < steps_.size(); ++i)
            negatedOperand(i);
        for (std::size_t i = 0; i < steps_.size(); ++i)
            minMaxChain(i);
        std::vector<BatchStep> kept;
        kept.reserve(steps_.size());
        for (std::size_t i = 0; i < steps_.size(); ++i)
            if (!dead_[i]) kept.push_back(steps_[i]);
        steps_.swap(kept);
        sinCosPairs(steps_);
    }

  private:
    std::vector<BatchStep>& steps_;
    std::vector<int> uses_;
    std::vector<char> dead_;

    // Reads of each step's result before its register is written again (a
    // final output counts as one more read).
    void countUses(const Tape& tape) {
        std::vector<int> writer(static_cast<std::size_t>(tape.registerCount), -1);
        for (std::size_t i = 0; i < steps_.size(); ++i) {
            const BatchStep& s = steps_[i];
            const int arity = opArity(s.op);
            auto read = [&](bool isConst, std::int32_t reg) {
                if (!isConst && writer[reg] >= 0) ++uses_[writer[reg]];
            };
            read(s.constA, s.a);
            if (arity >= 2) read(s.constB, s.b);
            if (arity >= 3) read(s.constC, s.c);
            writer[s.out] = static_cast<int>(i);
        }
        for (const OutputInfo& o : tape.outputs)
            if (!o.value.isConst() && writer[o.value.reg] >= 0) ++uses_[writer[o.value.reg]];
    }

    // The live step whose result step `at` reads from `reg`, if that result
    // has no other reader; -1 otherwise. (Dead steps still count as writers
    // in writtenBetween, which only makes fusion more cautious.)
    int soleProducer(std::size_t at, std::int32_t reg) const {
        for (std::size_t k = at; k-- > 0;) {
            if (steps_[k].out != reg) continue;
            return (!dead_[k] && uses_[k] == 1) ? static_cast<int>(k) : -1;
        }
        return -1;
    }

    bool writtenBetween(std::size_t from, std::size_t to, std::int32_t reg) const {
        for (std::size_t k = from + 1; k < to; ++k)
            if (steps_[k].out == reg) return true;
        return false;
    }

    // Can step `to` read `reg` (an input of step `from`) in `from`'s place?
    // Unless `inPlace`, the fused step must not write `reg` either: most batch
    // loops assume an output never overlaps an operand.
    bool canReadLater(std::size_t from, std::size_t to, std::int32_t reg,
                      bool inPlace = false) const {
        return !writtenBetween(from, to, reg) && (inPlace || steps_[to].out != reg);
    }

    void squareOfDiff(std::size_t i) {
        BatchStep& s = steps_[i];
        if (s.op != Op::Square || s.fused != Fused::None) return;
        int d = soleProducer(i, s.a);
        if (d < 0) return;
        const BatchStep& diff = steps_[d];
        if (diff.fused != Fused::None) return;
        bool sub = diff.op == Op::Sub && !diff.constA && diff.constB;
        bool add = diff.op == Op::Add && (diff.constA != diff.constB);
        if (!sub && !add) return;
        std::int32_t reg = diff.constA ? diff.b : diff.a;
        double c = diff.constA ? diff.ca : diff.cb;
        if (add) c = -c; // x + c == x - (-c) exactly: IEEE subtraction adds the negation
        if (!canReadLater(static_cast<std::size_t>(d), i, reg)) return;
        s.fused = Fused::SquareOfDiff;
        s.a = reg;
        s.ca = c;
        dead_[d] = 1;
    }

    // A squared term that step i may absorb from register `reg`.
    bool takeTerm(std::size_t i, std::int32_t reg, double sign, BatchStep& into) {
        int q = soleProducer(i, reg);
        if (q < 0) return false;
        const BatchStep& sq = steps_[q];
        if (sq.op != Op::Square || (sq.fused != Fused::None && sq.fused != Fused::SquareOfDiff))
            return false;
        if (!canReadLater(static_cast<std::size_t>(q), i, sq.a)) return false;
        into.termReg[into.terms] = sq.a;
        into.termOffset[into.terms] = sq.fused == Fused::SquareOfDiff ? sq.ca : 0.0;
        into.termSign[into.terms] = sign;
        ++into.terms;
        dead_[q] = 1;
        return true;
    }

    void squareTerms(std::size_t i) {
        BatchStep& s = steps_[i];
        if (dead_[i] || s.fused != Fused::None || (s.op != Op::Add && s.op != Op::Sub)) return;
        const double sign = s.op == Op::Add ? 1.0 : -1.0;
        BatchStep f = s;
        f.terms = 0;
        // A + q or A - q: q, the right operand, becomes a term; for Add the
        // left one may be the square instead (q + A = A + q exactly).
        if (!s.constB && takeTerm(i, s.b, sign, f)) {
            // A stays operand a
        } else if (s.op == Op::Add && !s.constA && takeTerm(i, s.a, 1.0, f)) {
            f.constA = s.constB;
            f.a = s.b;
            f.ca = s.cb;
        } else {
            return;
        }
        f.fused = Fused::SquareTerms;
        f.constB = true;
        // A itself a chain of terms (or one square) with no other reader: absorb it
        if (!f.constA) {
            int j = soleProducer(i, f.a);
            if (j >= 0 && steps_[j].fused == Fused::SquareTerms && steps_[j].terms + f.terms <= 3) {
                const BatchStep& inner = steps_[j];
                bool movable =
                    inner.constA || canReadLater(static_cast<std::size_t>(j), i, inner.a);
                for (int k = 0; k < inner.terms; ++k)
                    movable =
                        movable && canReadLater(static_cast<std::size_t>(j), i, inner.termReg[k]);
                if (movable) {
                    BatchStep merged = inner;
                    merged.op = s.op;
                    merged.out = s.out;
                    for (int k = 0; k < f.terms; ++k) {
                        merged.termReg[merged.terms] = f.termReg[k];
                        merged.termOffset[merged.terms] = f.termOffset[k];
                        merged.termSign[merged.terms] = f.termSign[k];
                        ++merged.terms;
                    }
                    dead_[j] = 1;
                    f = merged;
                }
            } else if (f.terms < 3) {
                // A = square(...) alone: 0 + t^2 == t^2 exactly (a square is never -0)
                BatchStep lead = f;
                lead.terms = 0;
                if (takeTerm(i, f.a, 1.0, lead)) {
                    for (int k = 0; k < f.terms; ++k) {
                        lead.termReg[lead.terms] = f.termReg[k];
                        lead.termOffset[lead.terms] = f.termOffset[k];
                        lead.termSign[lead.terms] = f.termSign[k];
                        ++lead.terms;
                    }
                    lead.constA = true;
                    lead.ca = 0.0;
                    f = lead;
                }
            }
        }
        s = f;
    }

    // The operands of a plain or negated-operand min/max step as chain links;
    // false when one is a constant (chains hold registers only).
    static bool chainLinks(const BatchStep& s, std::int32_t reg[2], double sign[2]) {
        if (s.constA || s.constB) return false;
        reg[0] = s.a;
        reg[1] = s.b;
        sign[0] = s.negA ? -1.0 : 1.0;
        sign[1] = s.negB ? -1.0 : 1.0;
        return true;
    }

    // op(inner, c) where inner = op(a, b) [or a longer chain] has no other
    // reader: one pass evaluating the same nesting left to right. Negation is
    // a multiplication by -1, which IEEE makes exact.
    void minMaxChain(std::size_t i) {
        BatchStep& s = steps_[i];
        if (dead_[i] || (s.op != Op::Min && s.op != Op::Max)) return;
        if (s.fused != Fused::None && s.fused != Fused::NegatedOperand) return;
        if (s.constA || s.constB || s.negA) return; // the chain continues through operand a only
        int j = soleProducer(i, s.a);
        if (j < 0) return;
        const BatchStep& inner = steps_[j];
        if (inner.op != s.op) return;
        std::int32_t regs[4];
        double signs[4];
        int count = 0;
        if (inner.fused == Fused::MinMaxChain) {
            count = inner.chainCount;
            for (int k = 0; k < count; ++k) {
                regs[k] = inner.chainReg[k];
                signs[k] = inner.chainSign[k];
            }
        } else if (inner.fused == Fused::None || inner.fused == Fused::NegatedOperand) {
            if (!chainLinks(inner, regs, signs)) return;
            count = 2;
        } else {
            return;
        }
        if (count + 1 > 4) return;
        // the chain loop may write the register of its first operand (it reads
        // that one through the output pointer), but no other
        for (int k = 0; k < count; ++k)
            if (!canReadLater(static_cast<std::size_t>(j), i, regs[k], /*inPlace=*/k == 0)) return;
        if (s.out == s.b) return;
        regs[count] = s.b;
        signs[count] = s.negB ? -1.0 : 1.0;
        ++count;
        s.fused = Fused::MinMaxChain;
        s.chainCount = static_cast<std::uint8_t>(count);
        for (int k = 0; k < count; ++k) {
            s.chainReg[k] = regs[k];
            s.chainSign[k] = signs[k];
        }
        dead_[j] = 1;
    }

    // A paired sin and cos of one register, next to each other (the tape
    // builder emits them so): one step writing both. Last, on the kept steps:
    // the other fusions only ever see single results.
    static void sinCosPairs(std::vector<BatchStep>& steps) {
        std::vector<BatchStep> kept;
        kept.reserve(steps.size());
        for (std::size_t i = 0; i < steps.size(); ++i) {
            BatchStep s = steps[i];
            if (i + 1 < steps.size() && s.fused == Fused::None) {
                const BatchStep& t = steps[i + 1];
                const bool pair = (s.op == Op::SinOfPair && t.op == Op::CosOfPair) ||
                                  (s.op == Op::CosOfPair && t.op == Op::SinOfPair);
                // the first result must not be the second step's operand,
                // and sincos writes two distinct arrays, neither its input
                if (pair && t.fused == Fused::None && !s.constA && !t.constA && s.a == t.a &&
                    s.out != s.a && t.out != s.a && s.out != t.out) {
                    const bool sinFirst = s.op == Op::SinOfPair;
                    s.op = Op::SinOfPair;
                    s.fused = Fused::SinCos;
                    s.out = sinFirst ? steps[i].out : t.out;
                    s.out2 = sinFirst ? t.out : steps[i].out;
                    ++i;
                }
            }
            kept.push_back(s);
        }
        steps.swap(kept);
    }

    void negatedOperand(std::size_t i) {
        BatchStep& s = steps_[i];
        if (dead_[i] || s.fused != Fused::None || (s.op != Op::Min && s.op != Op::Max)) return;
        for (bool second : {true, false}) {
            bool isConst = second ? s.constB : s.constA;
            std::int32_t reg = second ? s.b : s.a;
            if (isConst) continue;
            int n = soleProducer(i, reg);
            if (n < 0 || steps_[n].op != Op::Neg || steps_[n].fused != Fused::None) continue;
            std::int32_t inner = steps_[n].a;
            // (the negated-operand loops handle an output that is the operand itself)
            if (!canReadLater(static_cast<std::size_t>(n), i, inner, /*inPlace=*/true)) continue;
            (second ? s.b : s.a) = inner;
            (second ? s.negB : s.negA) = true;
            s.fused = Fused::NegatedOperand;
            dead_[n] = 1;
            return;
        }
    }
};

} // namespace

void fuseBatchSteps(std::vector<BatchStep>& steps, const Tape& tape) {
    Fuser(steps, tape).run();
}

} // namespace fl::formula
