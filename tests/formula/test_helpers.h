#pragma once
#include "formula/compiler.h"
#include "formula/eval_scalar.h"

#include <gtest/gtest.h>

#include <string>

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

} // namespace fl::formula::testing
