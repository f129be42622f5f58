// Google Benchmark: each formula with FunctionLab's batch evaluator, the
// hand-written C++ and muParser, over the same 64^3 grid; and many points'
// gradients three ways (GradientEvaluator::evaluateMany's choice, its row
// loops, the machine code one point a call) over a 32^3 grid.
#include "eval_formulas.h"
#include "muparser_peer.h"

#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"

#include <array>

#include <benchmark/benchmark.h>

namespace {

using namespace fl::bench;

const Grid& grid() {
    static const Grid g = makeGrid(64);
    return g;
}

void runFunctionLab(benchmark::State& state, const EvalFormula* f) {
    auto compiled = fl::formula::compile(f->source);
    fl::formula::BatchEvaluator batch(*compiled.tape);
    fl::formula::BatchInputs in;
    in.set(fl::formula::Input::X, grid().x.data());
    in.set(fl::formula::Input::Y, grid().y.data());
    in.set(fl::formula::Input::Z, grid().z.data());
    in.set(fl::formula::Input::T, grid().t);
    std::vector<double> out(grid().size());
    for (auto _ : state) {
        batch.evaluate(in, out.size(), out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(out.size()));
}

void runNative(benchmark::State& state, const EvalFormula* f) {
    std::vector<double> out(grid().size());
    for (auto _ : state) {
        f->native(grid().x.data(), grid().y.data(), grid().z.data(), grid().t, out.data(),
                  out.size());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(out.size()));
}

void runMuParser(benchmark::State& state, const EvalFormula* f) {
    MuParserPeer peer(f->muparser);
    std::vector<double> out(grid().size());
    for (auto _ : state) {
        peer.evaluateBulk(grid(), out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(out.size()));
}

// Formulas whose gradients take either way in evaluateMany: the first three
// through the machine code (abs, powers, division), the rest in rows.
const std::array<std::pair<const char*, const char*>, 6> kGradientFormulas = {{
    {"box", "max(abs(x), max(abs(y), abs(z))) - 0.8"},
    {"quartic", "x^4 + y^4 + z^4 - 0.5"},
    {"division", "x / (1 + y*y) - z"},
    {"sphere", "1 - x^2 - y^2 - z^2"},
    {"select", "x > 0 ? 1 - x^2 - y^2 - z^2 : 0.5 - x^2 - y^2 - z^2"},
    {"gyroid", "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)"},
}};

enum class GradientWay { Chosen, Rows, OnePointCode };

void runGradients(benchmark::State& state, const char* source, GradientWay way) {
    using namespace fl::formula;
    static const Grid g = makeGrid(32);
    std::vector<Point> points(g.size());
    for (std::size_t i = 0; i < g.size(); ++i)
        points[i] = pointXYZ(g.x[i], g.y[i], g.z[i], g.t);
    auto compiled = compile(source);
    // Interpreted: evaluateMany keeps its rows; compiled from the first point.
    GradientEvaluator e(*compiled.tape, {Input::X, Input::Y, Input::Z},
                        way == GradientWay::Rows ? ScalarCode::Interpreted : ScalarCode::Compiled);
    std::vector<Dual> out(points.size());
    for (auto _ : state) {
        if (way == GradientWay::OnePointCode)
            for (std::size_t i = 0; i < points.size(); ++i)
                out[i] = e.evaluate(points[i]);
        else
            e.evaluateMany(points.data(), points.size(), out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(out.size()));
}

int registerAll() {
    for (const auto& [name, source] : kGradientFormulas) {
        const std::string base = std::string("gradient/") + name;
        benchmark::RegisterBenchmark((base + "/many").c_str(), runGradients, source,
                                     GradientWay::Chosen);
        benchmark::RegisterBenchmark((base + "/rows").c_str(), runGradients, source,
                                     GradientWay::Rows);
        benchmark::RegisterBenchmark((base + "/one-point-code").c_str(), runGradients, source,
                                     GradientWay::OnePointCode);
    }
    for (const EvalFormula& f : evalFormulas()) {
        benchmark::RegisterBenchmark(("eval/" + f.name + "/functionlab").c_str(), runFunctionLab,
                                     &f)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("eval/" + f.name + "/native").c_str(), runNative, &f)
            ->Unit(benchmark::kMillisecond);
        if (MuParserPeer::available())
            benchmark::RegisterBenchmark(("eval/" + f.name + "/muparser").c_str(), runMuParser, &f)
                ->Unit(benchmark::kMillisecond);
    }
    return 0;
}
const int registered = registerAll();

} // namespace

BENCHMARK_MAIN();
