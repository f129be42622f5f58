// The mesher on shapes whose answer is known: closed, manifold, outward,
// on the surface, sharp where min/max make edges, the same for any number of
// threads, and honest about budget, cancellation and progress.
#include "mesh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace fl::mesh;
using namespace fl::mesh::support;

namespace {

void expectWatertight(const Mesh& mesh) {
    const Topology t = analyseTopology(mesh);
    EXPECT_TRUE(t.closed()) << t.boundaryEdges << " boundary edges";
    EXPECT_TRUE(t.manifold()) << t.nonManifoldEdges << " non-manifold edges";
    EXPECT_TRUE(t.consistentlyOriented()) << t.misorientedEdges << " misoriented edges";
    EXPECT_EQ(t.degenerateTriangles, 0u);
    EXPECT_GT(t.signedVolume, 0); // faces outward
}

} // namespace

TEST(DualContouring, SphereIsClosedOutwardAndOnTheSurface) {
    const ImplicitField f = field("0.8^2 - x*x - y*y - z*z");
    MeshOptions o;
    o.resolution = 40;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    expectWatertight(r.mesh);
    const Topology t = analyseTopology(r.mesh);
    EXPECT_EQ(t.eulerCharacteristic, 2); // a sphere
    const double exact = 4.0 / 3.0 * std::numbers::pi * 0.512;
    EXPECT_NEAR(t.signedVolume, exact, 0.01 * exact);
    EXPECT_LT(maxSurfaceError(f, r.mesh), 1e-3);
    // Normals are unit and point away from the centre.
    for (std::size_t i = 0; i < r.mesh.vertexCount(); ++i) {
        const Vec3f& p = r.mesh.positions[i];
        const Vec3f& n = r.mesh.normals[i];
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-5);
        EXPECT_GT(p[0] * n[0] + p[1] * n[1] + p[2] * n[2], 0);
    }
}

TEST(DualContouring, MinMaxCubeKeepsItsEdgesAndCornersSharp) {
    // A cube of half-size 0.5 as the intersection of six half-spaces; the
    // grid does not line up with its faces.
    const ImplicitField f = field("min(min(0.5 - abs(x), 0.5 - abs(y)), 0.5 - abs(z))");
    MeshOptions o;
    o.resolution = 23;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok());
    expectWatertight(r.mesh);
    float extreme = 0;
    for (const Vec3f& p : r.mesh.positions) {
        for (float c : p)
            EXPECT_LE(std::abs(c), 0.5f + 1e-4f);
        extreme = std::max(extreme, std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]));
    }
    EXPECT_NEAR(extreme, 1.5f, 1e-3f); // the corners are there, not rounded off
    EXPECT_NEAR(analyseTopology(r.mesh).signedVolume, 1.0, 1e-3);
}

TEST(DualContouring, ACreasePassingBesideACellStillGetsItsVertexOnIt) {
    // The watermelon's shape: a ball with a wedge cut out. Its creases run
    // obliquely through the grid, so many cells hold both surfaces of a
    // crease but not the line where they meet; their vertices used to fall
    // back to the crossings' centre, up to half a cell inside the solid
    // (max error 5e-3 of the diagonal at 64, from a few hundred triangles).
    const ImplicitField f = field("min(1 - x^2 - y^2 - z^2, -min(min(z - x, y), z))", 1.1);
    MeshOptions o;
    o.resolution = 64;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    expectWatertight(r.mesh);
    EXPECT_LT(maxSurfaceError(f, r.mesh), 1.5e-3);
    // No triangle folded over at the creases: each faces the way -grad f
    // does at its centre, give or take the turn of the crease itself.
    FieldSampler sampler(f);
    for (const Triangle& t : r.mesh.triangles) {
        const Vec3f& a = r.mesh.positions[t[0]];
        const Vec3f& b = r.mesh.positions[t[1]];
        const Vec3f& c = r.mesh.positions[t[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        const fl::formula::Dual g = sampler.gradient(
            {(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0, (a[2] + b[2] + c[2]) / 3.0});
        const double dot = -(n[0] * g.d[0] + n[1] * g.d[1] + n[2] * g.d[2]);
        const double size = std::hypot(n[0], n[1], n[2]) * std::hypot(g.d[0], g.d[1], g.d[2]);
        EXPECT_GT(dot, -0.5 * size)
            << "folded triangle near " << a[0] << ", " << a[1] << ", " << a[2];
    }
}

TEST(DualContouring, ASmoothPatchsVerticesAreBalancedAboutTheSurface) {
    // The QEF alone puts a convex patch's vertex on its crossings' tangent
    // planes, outside the sphere by up to 2.7 % of a cell at 32, and those
    // vertices were the mesh's largest error (4.9e-4 of the diagonal). Lifted
    // to a quarter of the crossings' curvature term instead, they sit at
    // most half as high, and the flat triangles between them deviate about
    // as much inward as the vertices do outward.
    const ImplicitField f = field("0.8^2 - x*x - y*y - z*z");
    MeshOptions o;
    o.resolution = 32;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    const double cell = 2.0 / 32;
    for (const Vec3f& p : r.mesh.positions) {
        const double height = std::hypot(double(p[0]), double(p[1]), double(p[2])) - 0.8;
        EXPECT_GT(height, -0.002 * cell);
        EXPECT_LT(height, 0.02 * cell);
    }
    EXPECT_LT(maxSurfaceError(f, r.mesh), 3.5e-4);
}

TEST(DualContouring, ASaddlesQuadsAreSplitAlongTheFlatterDiagonal) {
    // z = (x^2 + xy) / 2 curves along one diagonal of the grid's quads and not
    // along the other; split along the shorter diagonal (as the quads were)
    // half of them bowed off it, the largest error 2.1e-4 of the diagonal at
    // 32; split along the flatter one, 1.4e-4.
    const ImplicitField f = field("z - 0.5 * (x*x + x*y)", 1.0, BoxBoundary::Open);
    MeshOptions o;
    o.resolution = 32;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_LT(maxSurfaceError(f, r.mesh), 1.75e-4);
}

TEST(DualContouring, TheBoxClosesTheSolidOrLeavesItOpen) {
    // The half-space z <= 0.3 fills most of the box.
    const ImplicitField closed = field("0.3 - z");
    MeshOptions o;
    o.resolution = 16;
    const MeshResult c = meshImplicit(closed, o);
    ASSERT_TRUE(c.ok());
    expectWatertight(c.mesh);
    EXPECT_NEAR(analyseTopology(c.mesh).signedVolume, 2 * 2 * 1.3, 1e-3); // box below z = 0.3
    const MeshResult open = meshImplicit(field("0.3 - z", 1.0, BoxBoundary::Open), o);
    ASSERT_TRUE(open.ok());
    const Topology t = analyseTopology(open.mesh);
    EXPECT_GT(t.boundaryEdges, 0u); // a sheet with a border where it leaves the box
    EXPECT_TRUE(t.manifold());
    EXPECT_TRUE(t.consistentlyOriented());
    for (const Vec3f& n : open.mesh.normals)
        EXPECT_NEAR(n[2], 1, 1e-6); // facing up, out of the solid
}

TEST(DualContouring, SameOutputWhateverTheNumberOfThreads) {
    const ImplicitField f = field("sin(3*x)*cos(3*y) + sin(3*y)*cos(3*z) + sin(3*z)*cos(3*x)");
    MeshOptions one, two;
    one.resolution = two.resolution = 30;
    one.threads = 1;
    two.threads = 2;
    const MeshResult a = meshImplicit(f, one), b = meshImplicit(f, two);
    ASSERT_TRUE(a.ok());
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    expectWatertight(a.mesh); // a gyroid closed by the box
}

// The warnings too: where many corners tie for the highest value (f = -y^2
// touches zero on the whole plane y = 0) or are undefined, the point a
// warning names must not depend on which thread sampled which block first
// (it did: the simplified-tape test below failed once in a sanitizer run).
TEST(DualContouring, TheWarningsNameTheSamePointWhateverTheThreads) {
    for (const char* src : {"sin(max(x - 10, 0)) - y*y", "-(y*y)", "sqrt(x) + 0.3 - y*y - z*z"}) {
        const ImplicitField f = field(src);
        MeshOptions one;
        one.resolution = 40;
        one.threads = 1;
        const MeshResult reference = meshImplicit(f, one);
        ASSERT_TRUE(reference.ok()) << src;
        ASSERT_FALSE(reference.warnings.empty()) << src;
        for (int threads : {2, 3, 4, 7})
            for (int run = 0; run < 5; ++run) {
                MeshOptions many = one;
                many.threads = threads;
                const MeshResult r = meshImplicit(f, many);
                ASSERT_TRUE(r.ok()) << src;
                EXPECT_EQ(r.warnings, reference.warnings) << src << ", " << threads << " threads";
            }
    }
}

// Each block samples the formula simplified for it (formula/tape_simplify.h):
// the mesh is the full formula's, bit for bit — set operations, a select, an
// undefined region, an open box.
TEST(DualContouring, SimplifiedPerBlockTheMeshIsTheSame) {
    for (const char* src : {"(1-x^2-y^2-z^2) & (-((z-x) & y & z))",
                            "max(max(0.3^2-(x-0.4)^2-y^2-z^2, 0.3^2-(x+0.4)^2-y^2-z^2), "
                            "min(0.2-abs(y), 0.5-abs(x)))",
                            "(x > 0) ? 0.5 - x*x - y*y - z*z : 0.3 - y*y - z*z - 4*x*x",
                            "min(sqrt(x + 0.5) - 0.5, 0.7 - y*y - z*z)",
                            // infinite at the corners x < 0.5: a crossing's first guess
                            // was inf / inf, evaluated off its edge (and the box)
                            "((x < 0.5) ? 1e300*1e300 : -1) + min(z, x + 100)",
                            // sin([0, 0]) is widened on the full tape: the simplified
                            // one must not prune more (the warnings would differ)
                            "sin(max(x - 10, 0)) - y*y"}) {
        for (const BoxBoundary boundary : {BoxBoundary::Closed, BoxBoundary::Open}) {
            ImplicitField f = field(src);
            f.boundary = boundary;
            MeshOptions simplified, full;
            simplified.resolution = full.resolution = 40;
            full.simplifyPerBlock = false;
            const MeshResult a = meshImplicit(f, simplified), b = meshImplicit(f, full);
            ASSERT_TRUE(a.ok()) << src;
            ASSERT_TRUE(b.ok()) << src;
            if (std::string(src).rfind("sin(max", 0) != 0) { // that one has no inside
                EXPECT_GT(a.mesh.triangles.size(), 100u) << src;
            }
            for (const auto& p : a.mesh.positions)
                ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
                    << src;
            for (const auto& n : a.mesh.normals)
                ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]))
                    << src;
            EXPECT_EQ(a.mesh.positions, b.mesh.positions) << src;
            EXPECT_EQ(a.mesh.normals, b.mesh.normals) << src;
            EXPECT_EQ(a.mesh.triangles, b.mesh.triangles) << src;
            EXPECT_EQ(a.warnings, b.warnings) << src;
        }
    }
}

TEST(DualContouring, IntervalsSkipEmptySpace) {
    const ImplicitField f = field("0.1^2 - x*x - y*y - z*z"); // a small ball in a big box
    MeshOptions o;
    o.resolution = 128;
    const MeshResult r = meshImplicit(f, o);
    ASSERT_TRUE(r.ok());
    EXPECT_LT(r.stats.activeBlocks * 20, r.stats.blocks);
    EXPECT_LT(r.stats.evaluations.points * 50, std::size_t(129 * 129 * 129));
    expectWatertight(r.mesh);
}

TEST(DualContouring, ResolutionIsContinuous) {
    const ImplicitField f = field("0.8 - sqrt(x*x + y*y + z*z)");
    std::size_t previous = 0;
    for (double res : {10.0, 10.5, 11.0, 14.2, 20.0}) {
        MeshOptions o;
        o.resolution = res;
        const MeshResult r = meshImplicit(f, o);
        ASSERT_TRUE(r.ok());
        EXPECT_GE(r.mesh.triangleCount(), previous) << res;
        previous = r.mesh.triangleCount();
    }
}

TEST(DualContouring, BudgetCancelProgressAndBadInput) {
    const ImplicitField f = field("0.5 - x*x - y*y - z*z");
    MeshOptions o;
    o.resolution = 4000;
    o.memoryBudgetBytes = 1 << 20;
    MeshResult r = meshImplicit(f, o);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("lower the resolution"), std::string::npos) << r.error;

    std::atomic<bool> cancel{true};
    o = {};
    o.cancel = &cancel;
    r = meshImplicit(f, o);
    EXPECT_TRUE(r.cancelled);

    o = {};
    double last = -1;
    bool monotonic = true;
    o.progress = [&](double p) {
        monotonic = monotonic && p >= last;
        last = p;
    };
    r = meshImplicit(f, o);
    EXPECT_TRUE(monotonic);
    EXPECT_DOUBLE_EQ(last, 1.0);

    ImplicitField bad = f;
    bad.box.hi[0] = bad.box.lo[0];
    EXPECT_NE(meshImplicit(bad).error.find("domain box"), std::string::npos);
    o = {};
    o.resolution = std::nan("");
    EXPECT_NE(meshImplicit(f, o).error.find("resolution"), std::string::npos);
}

TEST(DualContouring, TheBudgetCountsWhatTheBlocksReallyHold) {
    // A dense gyroid passes the first, typical estimate (about kB^2 vertices
    // a block) but holds several times that: sampling counts the real bytes
    // and stops with the budget's message instead of running out of memory.
    const ImplicitField f =
        field("sin(30*x)*cos(30*y) + sin(30*y)*cos(30*z) + sin(30*z)*cos(30*x)");
    MeshOptions o;
    o.resolution = 96;
    const MeshResult whole = meshImplicit(f, o);
    ASSERT_TRUE(whole.ok()) << whole.error;
    o.memoryBudgetBytes = std::size_t(whole.stats.activeBlocks) * 9000;
    const MeshResult r = meshImplicit(f, o);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("lower the resolution"), std::string::npos) << r.error;
    EXPECT_GT(r.stats.activeBlocks, 0u); // refused while sampling, not by the first estimate
}
