// Every definition of every example scene (geometry, colour, force,
// parametric, transforms) gives the same bits compiled to machine code and
// interpreted (issue 31 §1: the interpreter is the reference), over a grid
// of points, at several moments, through block tails.
#include "formula/batch_jit.h"
#include "formula/eval_batch.h"
#include "formula/eval_scalar.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <vector>

namespace fl::scene {
namespace {

struct Outputs {
    std::vector<std::vector<double>> values;
    bool compiled = false;
    std::size_t passes = 0; // steps left after folding what is uniform
};

Outputs evaluate(const formula::Tape& tape, bool jit, const formula::BatchInputs& in,
                 std::size_t n) {
    formula::BatchJit::setAllowed(jit);
    formula::BatchEvaluator e(tape);
    Outputs o;
    o.values.assign(tape.outputs.size(), std::vector<double>(n));
    std::vector<double*> outs;
    for (auto& v : o.values)
        outs.push_back(v.data());
    e.evaluate(in, n, outs.data());
    o.compiled = e.jitActive();
    o.passes = e.passesPerBlock();
    formula::BatchJit::setAllowed(true);
    return o;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

// Every compiled definition of every example scene, with its scene (for
// messages that say where it is).
template <class Visit>
void forEachExampleDefinition(Visit visit) {
    for (const auto& entry : std::filesystem::directory_iterator(FUNCTIONLAB_EXAMPLES_DIR)) {
        if (entry.path().extension() != ".x3d") continue;
        ReadResult r = readSceneFile(entry.path().string());
        ASSERT_TRUE(r.ok()) << entry.path();
        for (const CompiledDefinition& d : r.scene->definitions)
            if (d.tape) visit(*r.scene, d);
    }
}

TEST(ExampleFormulas, CompiledAndInterpretedAgreeBitForBit) {
    if (!formula::BatchJit::available()) GTEST_SKIP() << "no JIT on this machine";
    // 11^3 points over a box larger than any example's, plus u v w.
    const int side = 11;
    const std::size_t n = std::size_t(side) * side * side;
    std::vector<double> c[6];
    for (auto& v : c)
        v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double p[3] = {-1.6 + 3.2 * double(i % side) / (side - 1),
                             -1.6 + 3.2 * double(i / side % side) / (side - 1),
                             -1.6 + 3.2 * double(i / side / side) / (side - 1)};
        for (int a = 0; a < 3; ++a) {
            c[a][i] = p[a];
            c[3 + a][i] = 0.5 + 0.5 * std::sin(3.0 * p[a] + a); // u v w in [0, 1]
        }
    }
    int definitions = 0, varying = 0, compiled = 0;
    forEachExampleDefinition([&](const Scene& scene, const CompiledDefinition& d) {
        for (const double t : {0.0, 0.37, 2.5}) {
            formula::BatchInputs in;
            for (int k = 0; k < 3; ++k) {
                in.set(formula::Input(k), c[k].data());
                in.set(formula::Input(int(formula::Input::U) + k), c[3 + k].data());
            }
            in.set(formula::Input::T, t);
            const Outputs a = evaluate(*d.tape, true, in, n);
            const Outputs b = evaluate(*d.tape, false, in, n);
            ASSERT_FALSE(b.compiled);
            if (t == 0.0) {
                ++definitions;
                varying += a.passes > 0 ? 1 : 0;
                compiled += a.compiled ? 1 : 0;
            }
            for (std::size_t k = 0; k < a.values.size(); ++k)
                for (std::size_t i = 0; i < n; ++i)
                    ASSERT_TRUE(sameBits(a.values[k][i], b.values[k][i]))
                        << scene.locationOf(*d.node) << " " << d.field << " output " << k
                        << " at point " << i << " t = " << t << ": compiled " << a.values[k][i]
                        << ", interpreted " << b.values[k][i];
        }
    });
    EXPECT_GE(definitions, 20);
    // Every one with work left after folding t and the constants runs
    // compiled (a definition of t alone, or a constant, folds to one value).
    EXPECT_EQ(compiled, varying);
    std::printf("%d of %d example definitions ran compiled (%d with work left)\n", compiled,
                definitions, varying);
}

// The same for one point a call: the scalar evaluator's machine code
// (BatchEvaluator's one-point code) against its interpreter, every output.
TEST(ExampleFormulas, OnePointAtATimeCompiledAndInterpretedAgreeBitForBit) {
    if (!formula::BatchJit::available()) GTEST_SKIP() << "no JIT on this machine";
    const int side = 7;
    int definitions = 0, compiled = 0;
    forEachExampleDefinition([&](const Scene& scene, const CompiledDefinition& d) {
        ++definitions;
        formula::ScalarEvaluator a(*d.tape, formula::ScalarCode::Compiled);
        formula::ScalarEvaluator b(*d.tape, formula::ScalarCode::Interpreted);
        const std::size_t outputs = d.tape->outputs.size();
        std::vector<double> va(outputs), vb(outputs);
        bool ran = true;
        for (const double t : {0.0, 0.37, 2.5})
            for (int i = 0; i < side * side * side; ++i) {
                formula::Point p{};
                for (int k = 0; k < 3; ++k) {
                    const int c = k == 0 ? i % side : k == 1 ? i / side % side : i / side / side;
                    p[std::size_t(k)] = -1.6 + 3.2 * c / (side - 1);
                    p[std::size_t(4 + k)] = 0.5 + 0.5 * std::sin(3.0 * p[std::size_t(k)] + k);
                }
                p[3] = t;
                a.evaluateAll(p, va.data());
                b.evaluateAll(p, vb.data());
                ran = ran && a.compiledLast();
                for (std::size_t k = 0; k < outputs; ++k)
                    ASSERT_TRUE(sameBits(va[k], vb[k]))
                        << scene.locationOf(*d.node) << " " << d.field << " output " << k
                        << " at point " << i << " t = " << t << ": compiled " << va[k]
                        << ", interpreted " << vb[k];
            }
        compiled += ran ? 1 : 0;
    });
    EXPECT_GE(definitions, 20);
    std::printf("%d of %d example definitions ran one point at a time as machine code\n", compiled,
                definitions);
}

} // namespace
} // namespace fl::scene
