#include "eval_table.h"

#include "eval_formulas.h"
#include "muparser_peer.h"

#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_scalar.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>

namespace fl::bench {

namespace {

// Best time per point of each engine. The engines take turns, round after
// round, until `seconds` have passed (at least three rounds): a noisy spell on
// this shared machine then hits all of them alike, and the minimum of each
// is its undisturbed speed.
std::vector<double> bestNsPerPoint(const std::vector<std::function<void()>>& engines,
                                   std::size_t points, double seconds) {
    using clock = std::chrono::steady_clock;
    std::vector<double> best(engines.size(), 1e300);
    const auto start = clock::now();
    for (int round = 0;; ++round) {
        for (std::size_t e = 0; e < engines.size(); ++e) {
            const auto t0 = clock::now();
            engines[e]();
            const auto t1 = clock::now();
            best[e] = std::min(best[e], std::chrono::duration<double, std::nano>(t1 - t0).count());
        }
        const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
        if (round >= 2 && elapsed >= seconds) break;
    }
    for (double& b : best)
        b /= static_cast<double>(points);
    return best;
}

// The same double bit for bit, or both NaN (payloads are not specified).
bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

} // namespace

std::vector<EvalRow> runEvalTable(std::size_t side, double seconds) {
    const Grid grid = makeGrid(side);
    const std::size_t n = grid.size();
    std::vector<double> ours(n), native(n), peer(n);
    std::vector<EvalRow> rows;
    for (const EvalFormula& f : evalFormulas()) {
        EvalRow row;
        row.formula = f.name;
        formula::CompileResult compiled = formula::compile(f.source);
        if (!compiled.ok())
            throw std::runtime_error("benchmark formula does not compile: " + f.name);
        formula::BatchEvaluator batch(*compiled.tape);
        formula::BatchInputs in;
        in.set(formula::Input::X, grid.x.data());
        in.set(formula::Input::Y, grid.y.data());
        in.set(formula::Input::Z, grid.z.data());
        in.set(formula::Input::T, grid.t);
        std::vector<std::function<void()>> engines = {
            [&] { batch.evaluate(in, n, ours.data()); },
            [&] {
                f.native(grid.x.data(), grid.y.data(), grid.z.data(), grid.t, native.data(), n);
            },
        };
        // One point a call: the scalar evaluator, and the hand-written
        // formula through its pointer for one point (a call it cannot see
        // through, as a caller of a compiled formula makes).
        formula::ScalarEvaluator scalar(*compiled.tape);
        std::vector<double> scalarOut(n), nativeScalarOut(n);
        const NativeFn nativeFn = f.native;
        engines.push_back([&] {
            for (std::size_t i = 0; i < n; ++i)
                scalarOut[i] =
                    scalar.evaluate(formula::pointXYZ(grid.x[i], grid.y[i], grid.z[i], grid.t));
        });
        engines.push_back([&] {
            volatile NativeFn call = nativeFn; // never inlined into the loop
            for (std::size_t i = 0; i < n; ++i)
                call(&grid.x[i], &grid.y[i], &grid.z[i], grid.t, &nativeScalarOut[i], 1);
        });
        // One point's gradient a call: machine code, and the interpreter.
        using formula::Input;
        formula::GradientEvaluator gradient(*compiled.tape, {Input::X, Input::Y, Input::Z},
                                            formula::ScalarCode::Compiled);
        formula::GradientEvaluator gradientInterpreted(
            *compiled.tape, {Input::X, Input::Y, Input::Z}, formula::ScalarCode::Interpreted);
        // (Timed writing one double a point, as the other engines do: four
        // would add 16 MB of traffic that slows the next engine's turn.)
        std::vector<double> slopes(n), slopesInterpreted(n);
        auto gradients = [&grid, n](formula::GradientEvaluator& e, std::vector<double>& out) {
            return [&grid, n, e = &e, out = out.data()] {
                for (std::size_t i = 0; i < n; ++i) {
                    const formula::Dual d =
                        e->evaluate(formula::pointXYZ(grid.x[i], grid.y[i], grid.z[i], grid.t));
                    out[i] = d.v + d.d[0] + d.d[1] + d.d[2];
                }
            };
        };
        engines.push_back(gradients(gradient, slopes));
        engines.push_back(gradients(gradientInterpreted, slopesInterpreted));
        std::unique_ptr<MuParserPeer> mp;
        if (MuParserPeer::available()) {
            mp = std::make_unique<MuParserPeer>(f.muparser);
            engines.push_back([&] { mp->evaluateBulk(grid, peer.data()); });
            engines.push_back([&] { mp->evaluatePerPoint(grid, peer.data()); });
        }
        batch.evaluate(in, n, ours.data()); // specialised (and compiled) once, before timing
        row.jit = batch.jitActive();
        row.jitCompileUs = batch.jitCompileMicroseconds();
        std::vector<double> ns = bestNsPerPoint(engines, n, seconds);
        row.functionlab = ns[0];
        row.native = ns[1];
        row.scalar = ns[2];
        row.nativeScalar = ns[3];
        row.gradient = ns[4];
        row.gradientInterpreted = ns[5];
        for (std::size_t i = 0; i < n; ++i)
            row.maxDifference = std::max({row.maxDifference, std::abs(ours[i] - native[i]),
                                          std::abs(scalarOut[i] - native[i]),
                                          std::abs(nativeScalarOut[i] - native[i])});
        // The same bits both ways (gradient_jit.h), value and slopes, or NaN.
        for (std::size_t i = 0; i < n; ++i) {
            const formula::Point p = formula::pointXYZ(grid.x[i], grid.y[i], grid.z[i], grid.t);
            const formula::Dual a = gradient.evaluate(p), b = gradientInterpreted.evaluate(p);
            if (!sameBits(a.v, b.v) || !sameBits(a.d[0], b.d[0]) || !sameBits(a.d[1], b.d[1]) ||
                !sameBits(a.d[2], b.d[2]))
                throw std::runtime_error("gradient machine code differs from its interpreter: " +
                                         f.name);
        }
        if (mp) {
            row.muparser = std::min(ns[6], ns[7]);
            row.muparserMode = ns[6] <= ns[7] ? "bulk" : "per-point";
            for (std::size_t i = 0; i < n; ++i)
                row.maxDifference = std::max(row.maxDifference, std::abs(peer[i] - native[i]));
        }
        rows.push_back(row);
    }
    return rows;
}

std::string formatEvalTable(const std::vector<EvalRow>& rows) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-18s %12s %12s %12s %10s %12s %10s %10s %10s %10s %10s %12s %10s\n", "formula",
                  "functionlab", "native", "muparser", "vs native", "vs muparser", "max |diff|",
                  "scalar", "native", "vs native", "gradient", "interpreted", "speed-up");
    out += line;
    std::snprintf(line, sizeof line,
                  "%-18s %12s %12s %12s %10s %12s %10s %10s %10s %10s %10s %12s %10s\n", "",
                  "ns/point", "ns/point", "ns/point", "(x slower)", "(x faster)", "", "ns/call",
                  "ns/call", "(x slower)", "ns/call", "ns/call", "(x)");
    out += line;
    for (const EvalRow& r : rows) {
        char mp[32] = "n/a", speed[32] = "n/a";
        if (r.muparser >= 0) {
            std::snprintf(mp, sizeof mp, "%.2f", r.muparser);
            std::snprintf(speed, sizeof speed, "%.1f", r.muparser / r.functionlab);
        }
        std::snprintf(line, sizeof line,
                      "%-18s %12.2f %12.2f %12s %10.2f %12s %10.1e %10.2f %10.2f %10.2f %10.2f "
                      "%12.2f %10.1f\n",
                      r.formula.c_str(), r.functionlab, r.native, mp, r.functionlab / r.native,
                      speed, r.maxDifference, r.scalar, r.nativeScalar, r.scalar / r.nativeScalar,
                      r.gradient, r.gradientInterpreted, r.gradientInterpreted / r.gradient);
        out += line;
    }
    // How FunctionLab ran each: machine code, and what making it took.
    out += "\nFunctionLab's JIT:";
    for (const EvalRow& r : rows) {
        if (r.jit)
            std::snprintf(line, sizeof line, " %s compiled in %.0f us;", r.formula.c_str(),
                          r.jitCompileUs);
        else
            std::snprintf(line, sizeof line, " %s interpreted;", r.formula.c_str());
        out += line;
    }
    out.back() = '\n';
    return out;
}

std::string evalTableJson(const std::vector<EvalRow>& rows) {
    std::string out = "[";
    char buf[512];
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const EvalRow& r = rows[i];
        char mp[32] = "null";
        if (r.muparser >= 0) std::snprintf(mp, sizeof mp, "%.4f", r.muparser);
        std::snprintf(buf, sizeof buf,
                      "%s\n  {\"formula\": \"%s\", \"ns_per_point\": {\"functionlab\": %.4f, "
                      "\"native\": %.4f, "
                      "\"muparser\": %s}, \"ns_per_call\": {\"scalar\": %.4f, \"native\": %.4f, "
                      "\"gradient\": %.4f, \"gradient_interpreted\": %.4f}, "
                      "\"jit\": %s, \"jit_compile_us\": %.1f}",
                      i ? "," : "", r.formula.c_str(), r.functionlab, r.native, mp, r.scalar,
                      r.nativeScalar, r.gradient, r.gradientInterpreted, r.jit ? "true" : "false",
                      r.jitCompileUs);
        out += buf;
    }
    out += "\n]\n";
    return out;
}

} // namespace fl::bench
