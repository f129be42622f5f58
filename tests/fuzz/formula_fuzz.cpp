// libFuzzer target: lexer + parser + checker + compiler + all four evaluators.
// Beyond "no crash, no hang, no unbounded allocation" it checks four laws on
// whatever compiles, each aborting when broken: batch == scalar (13 points,
// so the batch JIT runs a group of 8 and the interpreter the tail; calls to
// SLEEF compiled too), interval
// contains scalar, the gradient evaluator's value == scalar, and its
// derivatives match central differences wherever f is smooth there (the
// one-sided differences agree, so kinks such as abs(x) at 0 are not judged).
// And a fifth: the tape simplified for the box of the interval check
// (tape_simplify.h) gives the full tape's bits at every point in it. The
// scalar and gradient evaluators' machine code gives their interpreters'
// bits (values and slopes) at every point.
#include "formula/batch_jit.h"
#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"
#include "formula/nonfinite_report.h"
#include "formula/tape_simplify.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

using namespace fl::formula;

// The same double bit for bit, or both NaN (payloads are not specified).
static bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

// d f_o / d x_k at p against central differences of the scalar evaluator,
// judged only where they can judge: the differences at steps h, 10 h and 0.37 h
// agree (f is smooth there, and its values are not rounding noise, as
// mod(a, 1e-9) of a large a is).
static void checkDerivative(ScalarEvaluator& scalar, const Point& p, int k,
                            const std::vector<Dual>& grads, std::size_t outs) {
    const double h = 1e-6 * (1 + std::abs(p[k]));
    auto central = [&](double step, std::vector<double>& out) {
        std::vector<double> lo(outs), hi(outs);
        Point q = p;
        q[k] = p[k] - step;
        scalar.evaluateAll(q, lo.data());
        q[k] = p[k] + step;
        scalar.evaluateAll(q, hi.data());
        for (std::size_t o = 0; o < outs; ++o)
            out[o] = (hi[o] - lo[o]) / (2 * step);
    };
    std::vector<double> fine(outs), coarse(outs), odd(outs), value(outs);
    central(h, fine);
    central(10 * h, coarse);
    // A third step, not a multiple of the others: mod(-z/7, -1e-9) turns
    // thousands of times within h, and its differences at h and 10 h once
    // agreed to seven digits (-9.87e-6, where d is -1/7) by the phase alone.
    central(0.37 * h, odd);
    scalar.evaluateAll(p, value.data());
    for (std::size_t o = 0; o < outs; ++o) {
        const double d = grads[o].d[std::size_t(k)];
        if (!std::isfinite(d) || !std::isfinite(fine[o]) || !std::isfinite(coarse[o]) ||
            !std::isfinite(value[o]))
            continue;
        const double scale = 1 + std::abs(d) + std::abs(fine[o]);
        // What rounding f's value alone puts into a difference (a change of
        // d * h below f's last digits is not seen at all).
        const double noise = 100 * std::abs(value[o]) * 2.3e-16 / h;
        // Smooth here when the two differences agree — judged by their own
        // size, not by d's: sin(1e15*z) has d near 1e15, which once made two
        // differences of 4.7e5 and 4.4e4 (f turns many times within h)
        // "agree" and then contradict d.
        const double differences = 1 + std::abs(fine[o]) + std::abs(coarse[o]);
        if (std::abs(fine[o] - coarse[o]) > 1e-6 * differences + noise ||
            std::abs(fine[o] - odd[o]) > 1e-6 * differences + 3 * noise)
            continue; // not smooth
        if (std::abs(fine[o] - d) > 1e-3 * scale + noise) {
            std::fprintf(stderr, "d/d%c = %.17g, differences say %.17g (and %.17g at 10 h)\n",
                         "xyz"[k], d, fine[o], coarse[o]);
            std::abort();
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    std::string_view src(reinterpret_cast<const char*>(data), size);
    static const DefinitionKind kinds[] = {DefinitionKind::Generic, DefinitionKind::Implicit,
                                           DefinitionKind::Parametric, DefinitionKind::Colour,
                                           DefinitionKind::Force};
    CompileOptions options;
    options.kind = kinds[size % 5];
    if (size % 7 == 3) {
        options.setOperations.kind = SetOperationMode::Kind::RFunction;
        options.setOperations.m = 1.0;
    }
    CompileResult r = compile(src, options);
    for (const Diagnostic& d : r.diagnostics)
        (void)formatDiagnostic(d, src);
    if (!r.ok()) return 0;
    const Tape& tape = *r.tape;
    (void)tape.disassemble();

    ScalarEvaluator scalar(tape, ScalarCode::Interpreted);  // the reference
    BatchJit::setCallsAllowed(true);                        // the compiled calls are judged too
    ScalarEvaluator scalarCode(tape, ScalarCode::Compiled); // one point a call, as machine code
    BatchEvaluator batch(tape);
    IntervalEvaluator interval(tape);
    GradientEvaluator gradient(tape, {Input::X, Input::Y, Input::Z}, ScalarCode::Interpreted);
    GradientEvaluator gradientCode(tape, {Input::X, Input::Y, Input::Z}, ScalarCode::Compiled);
    const std::size_t outs = tape.outputs.size();

    static const double coords[] = {0.0, 0.5, -1.25, 3.0, 1e-9};
    Point points[5];
    for (int i = 0; i < 5; ++i)
        for (int k = 0; k < kInputCount; ++k)
            points[i][k] = coords[(i + k) % 5];

    constexpr int kBatch = 13; // the 5 points again and again
    std::vector<double> scalarOut(outs), batchOut(outs * kBatch), column[kInputCount];
    for (int k = 0; k < kInputCount; ++k) {
        column[k].resize(kBatch);
        for (int i = 0; i < kBatch; ++i)
            column[k][i] = points[i % 5][k];
    }
    BatchInputs in;
    for (int k = 0; k < kInputCount; ++k)
        in.arrays[k] = k == 3 ? nullptr : column[k].data();
    in.uniform[3] = points[0][3];
    for (int i = 0; i < 5; ++i)
        points[i][3] = points[0][3]; // t is uniform in the batch
    std::vector<double*> outPtrs(outs);
    for (std::size_t o = 0; o < outs; ++o)
        outPtrs[o] = batchOut.data() + o * kBatch;
    batch.evaluate(in, kBatch, outPtrs.data());

    std::vector<Dual> grads(outs), codeGrads(outs);
    // The gradient's machine code against its interpreter at p: every
    // output's value and slopes, bit for bit (or both NaN).
    auto sameGradients = [&](const Point& p) {
        gradientCode.evaluateAll(p, codeGrads.data());
        for (std::size_t o = 0; o < outs; ++o) {
            bool same = sameBits(codeGrads[o].v, grads[o].v);
            for (int k = 0; k < 3; ++k)
                same = same && sameBits(codeGrads[o].d[k], grads[o].d[k]);
            if (!same) {
                std::fprintf(stderr,
                             "gradient machine code (%.17g; %.17g %.17g %.17g) != interpreted "
                             "(%.17g; %.17g %.17g %.17g), output %zu\n",
                             codeGrads[o].v, codeGrads[o].d[0], codeGrads[o].d[1],
                             codeGrads[o].d[2], grads[o].v, grads[o].d[0], grads[o].d[1],
                             grads[o].d[2], o);
                std::abort();
            }
        }
    };
    std::vector<Interval> ranges(outs);
    Box box;
    for (int k = 0; k < kInputCount; ++k)
        box[k] = Interval::of(-1.25, 3.0);
    box[3] = Interval::point(points[0][3]);
    interval.evaluateAll(box, ranges.data());
    std::vector<Keep> keep;
    (void)interval.evaluate(box, keep);
    const Tape simplified = simplifyTape(tape, keep);
    ScalarEvaluator simple(simplified);
    std::vector<double> simpleOut(outs), codeOut(outs);
    // The machine code with t changing, then back (what depends on t alone
    // runs once per t: batch_hoist.h), against the interpreter; the
    // gradient's code likewise.
    for (int i = 0; i < 7; ++i) {
        Point q = points[i % 5];
        q[3] = i == 6 ? -0.0 : coords[(2 * i) % 5];
        scalar.evaluateAll(q, scalarOut.data());
        // (either call may be the first at a new t: they take turns)
        double first = 0.0;
        if (i % 2 && outs) first = scalarCode.evaluate(q);
        scalarCode.evaluateAll(q, codeOut.data());
        gradient.evaluateAll(q, grads.data()); // (its work on t alone too)
        sameGradients(q);
        for (std::size_t o = 0; o < outs; ++o) {
            const double code = o == 0 && i % 2 ? first : codeOut[o];
            if (!sameBits(code, scalarOut[o])) {
                std::fprintf(stderr, "scalar machine code %.17g != interpreted %.17g (t %g)\n",
                             code, scalarOut[o], q[3]);
                std::abort();
            }
        }
    }
    for (int i = 0; i < 5; ++i) {
        scalar.evaluateAll(points[i], scalarOut.data());
        simple.evaluateAll(points[i], simpleOut.data());
        scalarCode.evaluateAll(points[i], codeOut.data());
        for (std::size_t o = 0; o < outs; ++o)
            if (!sameBits(codeOut[o], scalarOut[o])) {
                std::fprintf(stderr, "scalar machine code %.17g != interpreted %.17g (point %d)\n",
                             codeOut[o], scalarOut[o], i);
                std::abort();
            }
        for (std::size_t o = 0; o < outs; ++o)
            if (!sameBits(simpleOut[o], scalarOut[o])) {
                std::fprintf(stderr, "simplified %.17g != full %.17g (point %d)\n", simpleOut[o],
                             scalarOut[o], i);
                std::abort();
            }
        gradient.evaluateAll(points[i], grads.data());
        sameGradients(points[i]);
        (void)explainNonFinite(tape, {}, points[i]);
        for (std::size_t o = 0; o < outs; ++o) {
            const double s = scalarOut[o];
            for (int j = i; j < kBatch; j += 5) {
                const double b = batchOut[o * kBatch + std::size_t(j)];
                if (!sameBits(s, b)) {
                    std::fprintf(stderr, "batch %.17g != scalar %.17g (point %d)\n", b, s, j);
                    std::abort();
                }
            }
            if (!ranges[o].contains(s)) {
                std::fprintf(stderr, "interval [%.17g, %.17g] nan=%d misses %.17g\n", ranges[o].lo,
                             ranges[o].hi, ranges[o].nan, s);
                std::abort();
            }
            const double g = grads[o].v;
            if (!sameBits(g, s)) {
                std::fprintf(stderr, "gradient value %.17g != scalar %.17g\n", g, s);
                std::abort();
            }
        }
        // Derivatives off the round coordinates: at a point where a branch's
        // condition is exactly at its boundary (`if (a) ... ` with a = 0),
        // forward-mode differentiation follows the branch taken, which is
        // right almost everywhere but not there.
        Point off = points[i];
        for (int k = 0; k < 3; ++k)
            off[k] += 0.1234567 * (k + 1);
        gradient.evaluateAll(off, grads.data());
        sameGradients(off);
        for (int k = 0; k < 3; ++k)
            checkDerivative(scalar, off, k, grads, outs);
    }
    return 0;
}
