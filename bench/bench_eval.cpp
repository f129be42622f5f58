// Google Benchmark: each formula with FunctionLab's batch evaluator, the
// hand-written C++ and muParser, over the same 64^3 grid.
#include "eval_formulas.h"
#include "muparser_peer.h"

#include "formula/compiler.h"
#include "formula/eval_batch.h"

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

int registerAll() {
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
