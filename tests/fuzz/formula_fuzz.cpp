// libFuzzer target: lexer + parser + checker + compiler + all four evaluators.
// Beyond "no crash, no hang, no unbounded allocation" it checks two laws on
// whatever compiles: batch == scalar, and interval contains scalar.
#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"
#include "formula/nonfinite_report.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

using namespace fl::formula;

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

    ScalarEvaluator scalar(tape);
    BatchEvaluator batch(tape);
    IntervalEvaluator interval(tape);
    GradientEvaluator gradient(tape);
    const std::size_t outs = tape.outputs.size();

    static const double coords[] = {0.0, 0.5, -1.25, 3.0, 1e-9};
    Point points[5];
    for (int i = 0; i < 5; ++i)
        for (int k = 0; k < kInputCount; ++k)
            points[i][k] = coords[(i + k) % 5];

    std::vector<double> scalarOut(outs), batchOut(outs * 5), column[kInputCount];
    for (int k = 0; k < kInputCount; ++k) {
        column[k].resize(5);
        for (int i = 0; i < 5; ++i)
            column[k][i] = points[i][k];
    }
    BatchInputs in;
    for (int k = 0; k < kInputCount; ++k)
        in.arrays[k] = k == 3 ? nullptr : column[k].data();
    in.uniform[3] = points[0][3];
    for (int i = 0; i < 5; ++i)
        points[i][3] = points[0][3]; // t is uniform in the batch
    std::vector<double*> outPtrs(outs);
    for (std::size_t o = 0; o < outs; ++o)
        outPtrs[o] = batchOut.data() + o * 5;
    batch.evaluate(in, 5, outPtrs.data());

    std::vector<Dual> grads(outs);
    std::vector<Interval> ranges(outs);
    Box box;
    for (int k = 0; k < kInputCount; ++k)
        box[k] = Interval::of(-1.25, 3.0);
    box[3] = Interval::point(points[0][3]);
    interval.evaluateAll(box, ranges.data());
    for (int i = 0; i < 5; ++i) {
        scalar.evaluateAll(points[i], scalarOut.data());
        gradient.evaluateAll(points[i], grads.data());
        (void)explainNonFinite(tape, {}, points[i]);
        for (std::size_t o = 0; o < outs; ++o) {
            double s = scalarOut[o], b = batchOut[o * 5 + i];
            bool same = std::bit_cast<std::uint64_t>(s) == std::bit_cast<std::uint64_t>(b) ||
                        (std::isnan(s) && std::isnan(b));
            if (!same) {
                std::fprintf(stderr, "batch %.17g != scalar %.17g\n", b, s);
                std::abort();
            }
            if (!ranges[o].contains(s)) {
                std::fprintf(stderr, "interval [%.17g, %.17g] nan=%d misses %.17g\n", ranges[o].lo,
                             ranges[o].hi, ranges[o].nan, s);
                std::abort();
            }
        }
    }
    return 0;
}
