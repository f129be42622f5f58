// hoistTimeOnly (batch_hoist.h): which steps lead, and that nothing after
// them can overwrite what they keep between calls.
#include "formula/batch_hoist.h"
#include "formula/tape.h"

#include <gtest/gtest.h>

#include <set>

namespace fl::formula {
namespace {

BatchStep step(Op op, std::int32_t out, std::int32_t a, std::int32_t b) {
    BatchStep s;
    s.op = op;
    s.out = out;
    s.a = a;
    s.b = b;
    return s;
}

constexpr std::int32_t kX = std::int32_t(Input::X), kT = std::int32_t(Input::T);

TEST(HoistTimeOnly, WorkOnTimeAloneLeadsUnderRegistersOfItsOwn) {
    // r8 = t*t; r9 = r8 + x; r8 = sin(r8) (reused register); r10 = r9 * r8
    std::vector<BatchStep> steps = {step(Op::Mul, 8, kT, kT), step(Op::Add, 9, 8, kX),
                                    step(Op::Sin, 8, 8, 0), step(Op::Mul, 10, 9, 8)};
    std::vector<char> liveOut(11, 0);
    liveOut[10] = 1;
    const HoistedSteps h = hoistTimeOnly(steps, liveOut, 11);
    ASSERT_EQ(h.hoisted, 2u);
    EXPECT_EQ(h.registerCount, 13);
    ASSERT_EQ(h.steps.size(), 4u);
    // t*t and sin(t*t) first, each into a new register; the rest read them.
    EXPECT_EQ(h.steps[0].op, Op::Mul);
    EXPECT_EQ(h.steps[0].out, 11);
    EXPECT_EQ(h.steps[1].op, Op::Sin);
    EXPECT_EQ(h.steps[1].a, 11);
    EXPECT_EQ(h.steps[1].out, 12);
    EXPECT_EQ(h.steps[2].op, Op::Add);
    EXPECT_EQ(h.steps[2].a, 11);
    EXPECT_EQ(h.steps[2].out, 9);
    EXPECT_EQ(h.steps[3].a, 9);
    EXPECT_EQ(h.steps[3].b, 12);
    EXPECT_EQ(h.liveOut.size(), 13u);
    // No later step writes a hoisted step's register.
    std::set<std::int32_t> kept = {h.steps[0].out, h.steps[1].out};
    for (std::size_t i = h.hoisted; i < h.steps.size(); ++i)
        EXPECT_EQ(kept.count(h.steps[i].out), 0u);
}

TEST(HoistTimeOnly, BothOutputsOfASineCosinePairAndFusedReadsAreRenamed) {
    // r8, r9 = sincos(t); r10 = 1 + (x - 1)^2 + r8 ... as SquareTerms reading
    // x and r9; r8 reused for x * r9; r11 = min chain of r10, r8, r9.
    BatchStep pair;
    pair.fused = Fused::SinCos;
    pair.op = Op::Sin;
    pair.out = 8;
    pair.out2 = 9;
    pair.a = kT;
    BatchStep terms;
    terms.fused = Fused::SquareTerms;
    terms.op = Op::Add;
    terms.out = 10;
    terms.constA = true;
    terms.ca = 1.0;
    terms.terms = 2;
    terms.termReg[0] = kX;
    terms.termOffset[0] = 1.0;
    terms.termReg[1] = 9;
    BatchStep chain;
    chain.fused = Fused::MinMaxChain;
    chain.op = Op::Min;
    chain.out = 11;
    chain.chainCount = 3;
    chain.chainReg[0] = 10;
    chain.chainReg[1] = 8;
    chain.chainReg[2] = 9;
    std::vector<BatchStep> steps = {pair, terms, step(Op::Mul, 8, kX, 9), chain};
    std::vector<char> liveOut(12, 0);
    liveOut[11] = 1;
    const HoistedSteps h = hoistTimeOnly(steps, liveOut, 12);
    ASSERT_EQ(h.hoisted, 1u);
    EXPECT_EQ(h.registerCount, 14);
    const BatchStep& p = h.steps[0];
    EXPECT_EQ(p.fused, Fused::SinCos);
    EXPECT_EQ(p.out, 12);  // the sines
    EXPECT_EQ(p.out2, 13); // the cosines
    EXPECT_EQ(h.steps[1].termReg[0], kX);
    EXPECT_EQ(h.steps[1].termReg[1], 13); // the cosines, by their new name
    EXPECT_EQ(h.steps[2].b, 13);
    EXPECT_EQ(h.steps[2].out, 8); // x * cos: r8 again, not the sines' register
    EXPECT_EQ(h.steps[3].chainReg[0], 10);
    EXPECT_EQ(h.steps[3].chainReg[1], 8);  // the product
    EXPECT_EQ(h.steps[3].chainReg[2], 13); // the cosines
}

TEST(HoistTimeOnly, OutputsAndWorkOnOtherInputsStay) {
    // r8 = t*t is an output: it stays, and so does r9 = r8 + 1 that reads it.
    BatchStep plusOne = step(Op::Add, 9, 8, 0);
    plusOne.constB = true;
    plusOne.cb = 1.0;
    std::vector<BatchStep> steps = {step(Op::Mul, 8, kT, kT), plusOne, step(Op::Mul, 10, 9, kX)};
    std::vector<char> liveOut(11, 0);
    liveOut[8] = liveOut[10] = 1;
    const HoistedSteps h = hoistTimeOnly(steps, liveOut, 11);
    EXPECT_EQ(h.hoisted, 0u);
    EXPECT_EQ(h.registerCount, 11);
    ASSERT_EQ(h.steps.size(), 3u);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        EXPECT_EQ(h.steps[i].out, steps[i].out);
        EXPECT_EQ(h.steps[i].a, steps[i].a);
    }
}

} // namespace
} // namespace fl::formula
