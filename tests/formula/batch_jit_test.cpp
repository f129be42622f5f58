// The batch evaluator's JIT (issue 31 §1) against its interpreter: every
// operation it compiles, on the values where semantics bite (±0, ±inf, NaN,
// subnormals, huge and tiny), with array and uniform inputs and blocks that
// are not a multiple of 4, must give the interpreter's bits exactly; random
// formulas of those operations too; the fused steps (squared terms, min/max
// chains, negated operands) as the compiler makes them; a tape with an
// operation the JIT leaves alone runs interpreted; FUNCTIONLAB_NO_JIT's
// switch turns it off. Skipped where the CPU has no AVX2.
#include "formula/batch_jit.h"
#include "formula/eval_batch.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <thread>

namespace fl::formula {
namespace {

using testing::sameBits;

const std::vector<double>& specials() {
    return testing::specialValues();
}

struct Outcome {
    std::vector<double> out;
    bool jit = false;
    std::size_t passes = 0; // steps left after folding what does not vary
};

Outcome evaluate(const Tape& tape, bool allowJit, const std::vector<double>& xs,
                 const std::vector<double>& ys, const std::vector<double>& zs, double t,
                 bool uniformY) {
    BatchJit::setAllowed(allowJit);
    BatchEvaluator e(tape);
    BatchInputs in;
    in.set(Input::X, xs.data());
    if (uniformY)
        in.set(Input::Y, ys[0]);
    else
        in.set(Input::Y, ys.data());
    in.set(Input::Z, zs.data());
    in.set(Input::T, t);
    Outcome r;
    r.out.assign(xs.size(), -123.0);
    e.evaluate(in, xs.size(), r.out.data());
    r.jit = e.jitActive();
    r.passes = e.passesPerBlock();
    BatchJit::setAllowed(true);
    return r;
}

// Both ways over every pair of special values (and z a mix); true when the JIT ran.
bool agreeOnSpecials(const std::string& src, bool uniformY = false,
                     const CompileOptions& options = {}) {
    CompileResult r = compile(src, options);
    EXPECT_TRUE(r.ok()) << src;
    if (!r.ok()) return false;
    std::vector<double> xs, ys, zs;
    for (double a : specials())
        for (double b : specials()) {
            xs.push_back(a);
            ys.push_back(b);
            zs.push_back(a * 0.5 - b);
        }
    // 285 points: a second block of 29, whose last 5 the interpreter does
    xs.resize(285);
    ys.resize(285);
    zs.resize(285);
    const Outcome jit = evaluate(*r.tape, true, xs, ys, zs, 0.25, uniformY);
    const Outcome interpreted = evaluate(*r.tape, false, xs, ys, zs, 0.25, uniformY);
    EXPECT_FALSE(interpreted.jit);
    for (std::size_t i = 0; i < xs.size(); ++i)
        if (!sameBits(jit.out[i], interpreted.out[i])) {
            ADD_FAILURE() << src << " at x=" << xs[i] << " y=" << (uniformY ? ys[0] : ys[i])
                          << ": JIT " << jit.out[i] << ", interpreter " << interpreted.out[i];
            break;
        }
    return jit.jit;
}

class BatchJitTest : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!BatchJit::available()) GTEST_SKIP() << "no AVX2 here (or FUNCTIONLAB_NO_JIT)";
        BatchJit::setCallsAllowed(true); // the default: the code that calls SLEEF too
    }
    void TearDown() override { BatchJit::setCallsAllowed(true); }
};

TEST_F(BatchJitTest, EveryOperationItCompilesGivesTheInterpretersBits) {
    std::vector<std::string> compiled = testing::jitOperationFormulas();
    // more run through the interpreter's code, between compiled loops
    compiled.insert(compiled.end(),
                    {"noise(x, 0.5, z) + y", "atan2(x, z) * hypot(x, y) - sin(x) * mod(z, 1.5)"});
    int ran = 0;
    for (const std::string& src : compiled) {
        ran += agreeOnSpecials(src) ? 1 : 0;
        agreeOnSpecials(src, /*uniformY=*/true);
    }
    // Every one of them is the JIT's (with y an array).
    EXPECT_EQ(ran, int(compiled.size()));
}

TEST_F(BatchJitTest, RFunctionsRunCompiledWithTheInterpretersBits) {
    for (const double m : {0.0, 1.0, 2.0})
        for (const double alpha : {0.0, 0.4, 1.0}) {
            CompileOptions o;
            o.setOperations = {SetOperationMode::Kind::RFunction, m, alpha};
            EXPECT_TRUE(agreeOnSpecials("(x & y) | (z \\ (x - y))", false, o))
                << "m " << m << " alpha " << alpha;
            agreeOnSpecials("(x & y) | z", true, o);
        }
}

TEST_F(BatchJitTest, StepsRunThroughTheInterpretersCodeCanBeTurnedOff) {
    // Steps the emitter does not write itself run through the interpreter's
    // code (runBatchStep) once a block; turned off, their tapes stay
    // interpreted whole.
    BatchJit::setCallsAllowed(false);
    for (const char* src : {"sin(x) + y", "pow(x, y)", "hypot(x, y)", "x - mod(y, 3)",
                            "noise(x, y, z)", "round(x) + y"})
        EXPECT_FALSE(agreeOnSpecials(src)) << src;
    EXPECT_TRUE(agreeOnSpecials("sqrt(x) + y"));
    BatchJit::setCallsAllowed(true);
    BatchJit::setAllowed(false);
    EXPECT_FALSE(BatchJit::available());
    BatchJit::setAllowed(true);
}

// Random formulas of the operations the JIT compiles, nested deep enough
// to need more registers than the CPU has (values spill and come back).
std::string randomCompiled(std::mt19937_64& rng, int depth) {
    std::uniform_int_distribution<int> pick(0, 99);
    if (depth <= 0 || pick(rng) < 15) {
        static const char* leaves[] = {"x", "y", "z", "t", "0.5", "-1.25", "3"};
        return leaves[pick(rng) % 7];
    }
    const std::string a = randomCompiled(rng, depth - 1);
    const std::string b = randomCompiled(rng, depth - 1);
    switch (pick(rng) % 20) {
    case 0:
        return "(" + a + " + " + b + ")";
    case 1:
        return "(" + a + " - " + b + ")";
    case 2:
        return "(" + a + " * " + b + ")";
    case 3:
        return "(" + a + " / " + b + ")";
    case 4:
        return "min(" + a + ", " + b + ")";
    case 5:
        return "max(" + a + ", " + b + ")";
    case 6:
        return "sqrt(abs(" + a + "))";
    case 7:
        return "(" + a + ")^2";
    case 8:
        return "(" + a + " < " + b + ")";
    case 9:
        return "(" + a + " ? " + b + " : " + randomCompiled(rng, depth - 1) + ")";
    case 10:
        return "sin(" + a + ")";
    case 11:
        return "(" + a + " & " + b + ")";
    case 12:
        return "(" + a + " | " + b + ")";
    case 13:
        return "-(" + a + ")";
    case 14:
        return "floor(" + a + ")";
    case 15:
        return "exp(" + a + " * 0.1)";
    case 16:
        return "(" + a + " && " + b + ")";
    case 17:
        return "pow(abs(" + a + "), 0.5)";
    case 18:
        return "(" + a + ")^3";
    default:
        return "(1 - (" + a + ")^2 - (" + b + ")^2)";
    }
}

TEST_F(BatchJitTest, RandomFormulasOfItsOperationsGiveTheInterpretersBits) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> v(-3, 3);
    int ran = 0, varying = 0;
    for (int i = 0; i < 300; ++i) {
        const std::string src = randomCompiled(rng, 2 + i % 6);
        CompileResult r = compile(src);
        ASSERT_TRUE(r.ok()) << src;
        const std::size_t n = i % 2 ? 1001 : 64;
        std::vector<double> xs(n), ys(n), zs(n);
        for (std::size_t k = 0; k < n; ++k) {
            xs[k] = v(rng);
            ys[k] = k % 17 == 0 ? std::numeric_limits<double>::quiet_NaN() : v(rng);
            zs[k] = k % 13 == 0 ? -0.0 : v(rng);
        }
        const Outcome jit = evaluate(*r.tape, true, xs, ys, zs, 0.7, i % 3 == 0);
        const Outcome interpreted = evaluate(*r.tape, false, xs, ys, zs, 0.7, i % 3 == 0);
        ran += jit.jit ? 1 : 0;
        varying += jit.passes > 0 ? 1 : 0;
        for (std::size_t k = 0; k < n; ++k)
            ASSERT_TRUE(sameBits(jit.out[k], interpreted.out[k]))
                << src << " at " << k << ": JIT " << jit.out[k] << ", interpreter "
                << interpreted.out[k];
    }
    // Every formula with work left after folding (t and constants are
    // uniform: a formula of them alone folds to one value) ran compiled.
    EXPECT_EQ(ran, varying);
    EXPECT_GE(varying, 200);
}

// Code that keeps every value in registers runs over a whole call's arrays
// at once, code that spills (more values live than YMM registers) or calls
// the interpreter's code a block at a time: both over three blocks and a
// tail, each giving the interpreter's bits.
TEST_F(BatchJitTest, LongArraysGiveTheInterpretersBitsWhetherTheCodeSpillsOrNot) {
    std::string spilling;
    for (int i = 1; i <= 16; ++i)
        spilling +=
            "a" + std::to_string(i) + " = x * " + std::to_string(1 + i / 16.0) + " + y * z; ";
    spilling += "return a1";
    for (int i = 2; i <= 16; ++i)
        spilling += (i % 2 ? " + a" : " * a") + std::to_string(18 - i);
    spilling += ";";
    for (const std::string& src :
         {std::string("1 - x^2 - y^2 - z^2"), std::string("min(x, y) - max(z, 0.5) * x"), spilling,
          std::string("sin(x) * y - z")}) {
        CompileResult r = compile(src);
        ASSERT_TRUE(r.ok()) << src;
        const std::size_t n = 3 * 256 + 45;
        std::vector<double> xs(n), ys(n), zs(n);
        for (std::size_t k = 0; k < n; ++k) {
            xs[k] = std::sin(double(k)) * 2;
            ys[k] = k % 29 == 0 ? std::numeric_limits<double>::quiet_NaN() : std::cos(double(k));
            zs[k] = double(k % 7) - 3;
        }
        const Outcome jit = evaluate(*r.tape, true, xs, ys, zs, 0.5, false);
        const Outcome interpreted = evaluate(*r.tape, false, xs, ys, zs, 0.5, false);
        EXPECT_TRUE(jit.jit) << src;
        for (std::size_t k = 0; k < n; ++k)
            ASSERT_TRUE(sameBits(jit.out[k], interpreted.out[k]))
                << src << " at " << k << ": JIT " << jit.out[k] << ", interpreter "
                << interpreted.out[k];
    }
}

TEST_F(BatchJitTest, ParametersAndATimeThatChangesRecompile) {
    CompileResult r = compile("param k = 2 in [0, 5]; k*x^2 + y - t");
    ASSERT_TRUE(r.ok());
    BatchEvaluator e(*r.tape);
    std::vector<double> xs = {1, 2, 3, 4, 5}, ys = {0, 0, 0, 0, 1}, out(5);
    BatchInputs in;
    in.set(Input::X, xs.data());
    in.set(Input::Y, ys.data());
    for (double t : {0.0, 1.0}) {
        for (double k : {2.0, 3.0}) {
            e.parameters().set("k", k);
            in.set(Input::T, t);
            e.evaluate(in, 5, out.data());
            EXPECT_TRUE(e.jitActive());
            for (std::size_t i = 0; i < 5; ++i)
                EXPECT_EQ(out[i], k * xs[i] * xs[i] + ys[i] - t);
        }
    }
}

TEST_F(BatchJitTest, EvaluatorsOfOneFormulaShareOneCompiledCopy) {
    // A mesher's threads each have an evaluator: the code is made once.
    CompileResult r = compile("min(1 - x^2 - y^2 - z^2, x - 0.3)");
    ASSERT_TRUE(r.ok());
    std::vector<double> xs(64, 0.1), ys(64, 0.2), zs(64, 0.3), out(64);
    BatchInputs in;
    in.set(Input::X, xs.data());
    in.set(Input::Y, ys.data());
    in.set(Input::Z, zs.data());
    in.set(Input::T, 0.0);
    const BatchJit* first = nullptr;
    std::vector<std::thread> threads;
    std::vector<const BatchJit*> seen(4, nullptr);
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            BatchEvaluator e(*r.tape);
            std::vector<double> mine(64);
            e.evaluate(in, 64, mine.data());
            seen[std::size_t(k)] = e.jitCode();
        });
    for (std::thread& t : threads)
        t.join();
    BatchEvaluator e(*r.tape);
    e.evaluate(in, 64, out.data());
    first = e.jitCode();
    ASSERT_NE(first, nullptr);
    for (const BatchJit* code : seen)
        EXPECT_EQ(code, first);
    // Another moment (t) that changes nothing compiled shares it too; another
    // formula does not.
    in.set(Input::T, 5.0);
    e.evaluate(in, 64, out.data());
    EXPECT_EQ(e.jitCode(), first);
    CompileResult other = compile("max(1 - x^2 - y^2 - z^2, x - 0.3)");
    BatchEvaluator o(*other.tape);
    o.evaluate(in, 64, out.data());
    EXPECT_NE(o.jitCode(), first);
}

} // namespace
} // namespace fl::formula
