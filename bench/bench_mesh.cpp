// Google Benchmark: the adaptive mesher against the dense marching-cubes
// baseline on the same shapes and resolutions, one thread each, so the ratio
// is per core (`functionlab bench accuracy` adds the error and uses all cores).
#include "formula/compiler.h"
#include "mesh/dual_contouring.h"
#include "mesh/marching_cubes.h"

#include <benchmark/benchmark.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace fl;

struct MeshShape {
    std::string name, formula;
};

const std::vector<MeshShape>& shapes() {
    static const std::vector<MeshShape> all = {
        {"sphere", "0.8^2 - x*x - y*y - z*z"},
        {"gyroid", "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)"},
        {"csg", "min(min(0.7 - abs(x), min(0.7 - abs(y), 0.7 - abs(z))), 0.9^2 - x*x - y*y - z*z)"},
    };
    return all;
}

field::ImplicitField fieldOf(const MeshShape& shape) {
    auto compiled = formula::compile(shape.formula);
    field::ImplicitField f{std::move(*compiled.tape), {{-1, -1, -1}, {1, 1, 1}}, {}, 0, {}};
    f.boundary = field::BoxBoundary::Open;
    return f;
}

void adaptive(benchmark::State& state, const MeshShape* shape) {
    const field::ImplicitField f = fieldOf(*shape);
    mesh::MeshOptions o;
    o.resolution = double(state.range(0));
    o.threads = 1;
    std::size_t triangles = 0;
    for (auto _ : state)
        triangles = mesh::meshImplicit(f, o).mesh.triangleCount();
    state.counters["triangles"] = double(triangles);
}

void dense(benchmark::State& state, const MeshShape* shape) {
    const field::ImplicitField f = fieldOf(*shape);
    std::size_t triangles = 0;
    for (auto _ : state)
        triangles = mesh::marchingCubes(f, double(state.range(0)), 1).mesh.triangleCount();
    state.counters["triangles"] = double(triangles);
}

int registerAll() {
    for (const MeshShape& s : shapes()) {
        using Run = void (*)(benchmark::State&, const MeshShape*);
        for (auto [name, run] : {std::pair<const char*, Run>{"adaptive", adaptive},
                                 std::pair<const char*, Run>{"dense", dense}})
            benchmark::RegisterBenchmark(("mesh/" + s.name + "/" + name).c_str(), run, &s)
                ->Arg(64)
                ->Arg(128)
                ->Arg(256)
                ->Unit(benchmark::kMillisecond);
    }
    return 0;
}
const int registered = registerAll();

} // namespace

BENCHMARK_MAIN();
