// The mesher prunes empty space with intervals: a shape built from min, abs
// and sin costs evaluations in proportion to its surface, not its box. Loose
// intervals (or none) would sample the whole grid. (Issue 18.)
#include "formula/compiler.h"
#include "mesh/dual_contouring.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace fl;

TEST(IntervalTightness, TheMesherEvaluatesAroundTheSurfaceNotTheBox) {
    // A thin shell made of min, abs and sin: a dense 128^3 grid would take
    // 2.1 million values; pruning by intervals must keep it to the surface.
    const char* shell = "min(0.05 - abs(sqrt(x*x + y*y + z*z) - 0.6), 0.3 + 0.1*sin(8*x))";
    formula::CompileResult r = formula::compile(shell);
    ASSERT_TRUE(r.ok());
    field::ImplicitField field;
    field.tape = *r.tape;
    field.box = {{-1, -1, -1}, {1, 1, 1}};
    mesh::MeshOptions o;
    o.resolution = 128;
    o.threads = 1;
    const mesh::MeshResult m = mesh::meshImplicit(field, o);
    ASSERT_TRUE(m.ok()) << m.error;
    const std::size_t dense = 129ull * 129 * 129;
    const std::size_t used = m.stats.evaluations.points + m.stats.evaluations.gradients;
    std::cout << "shell at 128: " << used << " point values, " << m.stats.evaluations.intervals
              << " intervals (dense: " << dense << ")\n";
    EXPECT_LT(used, dense / 3);
    EXPECT_GT(m.mesh.triangleCount(), 1000u);
}
