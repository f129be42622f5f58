#pragma once
#include "formula/compiler.h"
#include "formula/eval_scalar.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace fl::formula::testing {

// Compiles (expecting success) and evaluates the first output at a point.
inline double eval(const std::string& src, double x = 0, double y = 0, double z = 0, double t = 0,
                   DefinitionKind kind = DefinitionKind::Generic) {
    CompileOptions o;
    o.kind = kind;
    CompileResult r = compile(src, o);
    EXPECT_TRUE(r.ok()) << src << (r.diagnostics.empty() ? "" : ": " + r.diagnostics[0].message);
    if (!r.ok()) return -12345.0;
    ScalarEvaluator e(*r.tape);
    return e.evaluate(pointXYZ(x, y, z, t));
}

// The first error's message (empty when it compiled).
inline Diagnostic firstError(const std::string& src,
                             DefinitionKind kind = DefinitionKind::Generic) {
    CompileOptions o;
    o.kind = kind;
    CompileResult r = compile(src, o);
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == Severity::Error) return d;
    return {};
}

// The same double, bit for bit, or both NaN (the payload is not specified).
inline bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

// Values where an operation's semantics bite: signed zeros, infinities,
// NaN, subnormals, huge and tiny, and a few plain ones.
inline const std::vector<double>& specialValues() {
    static const std::vector<double> v = {0.0,
                                          -0.0,
                                          1.0,
                                          -1.0,
                                          0.5,
                                          -2.5,
                                          3.0,
                                          7.25,
                                          1e300,
                                          -1e300,
                                          1e-310,
                                          -1e-310,
                                          std::numeric_limits<double>::infinity(),
                                          -std::numeric_limits<double>::infinity(),
                                          std::numeric_limits<double>::quiet_NaN(),
                                          1e-20,
                                          -0.75};
    return v;
}

// Sixteen values made before any is read, then summed: more than the
// registers a JIT keeps values in, so some go to memory and come back.
inline std::string sixteenLiveValues() {
    std::string src;
    for (int i = 1; i <= 16; ++i)
        src += "a" + std::to_string(i) + " = x * " + std::to_string(1 + i / 16.0) + " + y * z; ";
    src += "return a1";
    for (int i = 2; i <= 16; ++i)
        src += (i % 3 ? " + a" : " * sin(a") + std::to_string(18 - i) + (i % 3 ? "" : ")");
    return src + ";";
}

// Formulas with work on t alone (the machine code runs it once per moment:
// batch_hoist.h), and the moments to visit in order: repeated, changed,
// +0 first (the bits of fresh rows), signed zeros, NaN, infinity, tiny.
// The scalar and gradient JIT tests both walk them.
struct TimeCase {
    const char* src;
    bool colour; // a colour script (several outputs)
};
inline const std::vector<TimeCase>& timeOnlyCases() {
    static const std::vector<TimeCase> cases = {
        {"0.25 - x^2 - (y - (abs(sin(pi*t)) - 0.5))^2 - z^2", false},
        {"sin(t) * x + cos(t) * y - (t - 1)^2", false},
        {"min(t, -t) + max(x, t * 2) - atan2(t, 3) * z", false},
        {"a = t * t; b = a + x; c = sin(a) + b * y; return c - a;", false},
        {"r = sin(t); g = x * sin(t) + cos(t); b = t * t;", true},
        {"r = x + y; g = exp(-t) * z; b = (t > 0.5) ? x : sqrt(t);", true}};
    return cases;
}
inline const std::vector<double>& momentsToVisit() {
    static const std::vector<double> moments = {0.0,
                                                0.25,
                                                0.25,
                                                0.5,
                                                -0.0,
                                                0.0,
                                                0.0,
                                                std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::infinity(),
                                                0.25,
                                                1e-310};
    return moments;
}

// One formula for each operation the JIT writes itself (arithmetic, min and
// max, comparisons, logic, powers, select, the fused sums of squares and
// min/max chains), then for each it calls out for (SLEEF's functions,
// hypot, mod, round, noise): the batch and the scalar JIT tests both run
// them all, each adding its own.
inline std::vector<std::string> jitOperationFormulas() {
    return {"x + y", "x - y", "x * y", "x / y", "min(x, y)", "max(x, y)", "-x + y", "abs(x) + y",
            "sqrt(x) + y", "floor(x) + y", "ceil(x) + y", "sign(x) + y", "x^2 + y", "x^3 + y",
            "x^4 + y", "x^5 + y", "x^-1 + y", "x^-2 + y", "x^-3 + y", "x^0 + y", "(x < y) + z",
            "(x <= y) + z", "(x > y) + z", "(x >= y) + z", "(x == y) + z", "(x != y) + z",
            "(x && y) + z", "(x || y) + z", "!x + y", "x ? y : z", "x ? 2 : z", "x ? y : 3",
            "x & y", "x | y", "x \\ y", "min(x, min(y, min(z, x * y)))",
            "max(max(x, -y), max(-z, y))", "1 - x^2 - y^2 - z^2", "(x - 1)^2 + (y + 2)^2 - z",
            "x*x + y*y + z*z - 0.5", "2 - (x - y)^2",
            // called out
            "sin(x) + y", "cos(x) * y", "exp(x) - y", "log(x) + y", "tan(x) + y", "atan(x) + y",
            "pow(x, y)", "atan2(x, y)", "pow(x, 2.5) + y", "atan2(1.5, y) + x", "cbrt(x) + y",
            "tanh(x) + sinh(y)", "hypot(x, y) - z", "x - mod(y, 3) * z", "round(x * 3) + y",
            "noise(x, y, z) * 2 + x", "x * y + sin(x * y) * (x - y) + cos(x + y) * x * y"};
}

} // namespace fl::formula::testing
