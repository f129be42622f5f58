// Fitting polygon meshes with PDE patches (pde fit): named hard cases — a
// sphere and a cylinder as meshes, a torus (no cap anywhere), a mesh with a
// hole, two parts, the bunny's ears (branches), the fandisk's sharp edges —
// each measured the way any tool would (the model written, read back,
// meshed, and compared by exact distances both ways); bad meshes refused
// with where and why; more radii never miss more.
#include "field/vec3.h"
#include "mesh/mesh_topology.h"
#include "mesh/obj_reader.h"
#include "mesh/surface_distance.h"
#include "pde/fit_measure.h"
#include "pde/mesh_fit.h"
#include "pde/pde_file.h"
#include "pde/pde_mesh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <numbers>

using namespace fl;
using fl::mesh::Mesh;
using namespace fl::pde::test;

namespace {

struct Measured {
    std::size_t patches = 0, bytes = 0;
    double rms = 0, hausdorff = 0; // fractions of the diagonal
};

Measured fitAndMeasure(const Mesh& m, pde::MeshFitOptions o = {}) {
    std::string why;
    const auto fit = pde::fitMesh(m, o, &why);
    EXPECT_TRUE(fit) << why;
    if (!fit) return {};
    pde::MeasureOptions mo;
    mo.samples = 20000;
    const auto measured = pde::measureFit(m, fit->model, mo, &why);
    EXPECT_TRUE(measured) << why;
    if (!measured) return {};
    return {fit->model.patches.size(), measured->bytes.size(), measured->rms(),
            measured->hausdorff()};
}

std::optional<Mesh> shared(const char* name) {
    const std::filesystem::path p = std::filesystem::path(FUNCTIONLAB_MESHES_DIR) / name;
    if (!std::filesystem::exists(p)) return std::nullopt;
    mesh::ObjReadResult r = mesh::readObjFile(p.string());
    EXPECT_TRUE(r.ok()) << r.error;
    return r.mesh;
}

} // namespace

// The area-weighted RMS of `distance` over a mesh's triangles (three
// points each), a fraction of `diagonal`.
template <typename F>
double rmsOver(const Mesh& m, F&& distance, double diagonal) {
    double sum = 0, area = 0;
    for (const auto& t : m.triangles) {
        std::array<field::Vec3, 3> p{};
        for (std::size_t k = 0; k < 3; ++k)
            p[k] = {m.positions[t[k]][0], m.positions[t[k]][1], m.positions[t[k]][2]};
        const double a =
            0.5 * field::length(field::cross(field::minus(p[1], p[0]), field::minus(p[2], p[0])));
        for (const auto& w :
             {std::array{4.0, 1.0, 1.0}, std::array{1.0, 4.0, 1.0}, std::array{1.0, 1.0, 4.0}}) {
            field::Vec3 x{};
            for (std::size_t k = 0; k < 3; ++k)
                x = field::plus(x, field::scaled(p[k], w[k] / 6));
            const double d = distance(x);
            sum += a / 3 * d * d;
            area += a / 3;
        }
    }
    return std::sqrt(sum / area) / diagonal;
}

TEST(PdeMeshFit, ASphereAndACylinderAreRecoveredToATenThousandthOfTheDiagonal) {
    // Issue 30 §5: recovered to 1e-4 of the diagonal with few radii. The
    // recovered shape is the sphere (the cylinder), so it is measured
    // against it, on the model meshed finely; against the mesh it stands
    // for, it may not be farther than the mesh's own facets are from the
    // shape (the sphere's: 1.8e-4 of the diagonal) and 1e-4 more. Both are
    // the paper's layout: caps at the ends and tubes between (one tube for
    // the cylinder, open at both ends), with 16-bit coefficients.
    struct Case {
        const char* name;
        Mesh mesh;
        std::function<double(const std::array<double, 3>&)> distance;
        double error;
    };
    const Case cases[] = {
        {"sphere", sphere(),
         [](const std::array<double, 3>& x) { return std::hypot(x[0], x[1], x[2]) - 1; }, 5e-5},
        {"cylinder", cylinder(),
         [](const std::array<double, 3>& x) { return std::hypot(x[0], x[1]) - 0.5; }, 1e-4},
    };
    for (const Case& c : cases) {
        pde::MeshFitOptions o;
        o.radii = 8;
        o.error = c.error;
        std::string why;
        const auto fit = pde::fitMesh(c.mesh, o, &why);
        ASSERT_TRUE(fit) << why;
        EXPECT_TRUE(fit->reached) << c.name;
        EXPECT_LE(fit->model.patches.size(), 8u) << c.name;
        EXPECT_LE(fit->model.maxRadii(), 8u) << c.name;
        std::size_t tubes = 0;
        for (const pde::Patch& p : fit->model.patches)
            tubes += p.cap ? 0 : 1;
        EXPECT_GE(tubes, 1u) << c.name;
        pde::MeasureOptions mo;
        mo.samples = 20000;
        mo.grid = {64, 256};
        mo.encode.bits = 16;
        const auto measured = pde::measureFit(c.mesh, fit->model, mo, &why);
        ASSERT_TRUE(measured) << why;
        const double recovered = rmsOver(measured->rebuilt, c.distance, measured->diagonal);
        const double facets = rmsOver(c.mesh, c.distance, measured->diagonal);
        EXPECT_LT(recovered, 1e-4) << c.name;
        EXPECT_LT(measured->rms(), facets + 1e-4) << c.name;
        EXPECT_LT(measured->hausdorff(), 2e-3) << c.name;
        std::cout << c.name << ": " << fit->model.patches.size() << " patches (" << tubes
                  << " tubes), " << measured->bytes.size() << " bytes, RMS from the shape "
                  << recovered << ", from the mesh " << measured->rms() << " (its facets " << facets
                  << "), Hausdorff " << measured->hausdorff() << "\n";
    }
}

namespace {

// A sphere fitted with `patches` patches, as any reader sees the model
// (written and read back).
pde::Model fittedSphere(std::size_t patches) {
    pde::MeshFitOptions o;
    o.patches = patches;
    o.radii = 6;
    std::string why;
    const auto fit = pde::fitMesh(sphere(24, 48), o, &why);
    EXPECT_TRUE(fit) << why;
    if (!fit) return {};
    const pde::ReadResult back = pde::readModel(pde::encodeBinary(fit->model), "s.pde");
    EXPECT_TRUE(back.ok()) << back.error;
    return back.ok() ? *back.model : pde::Model{};
}

// Every edge of the meshed model has two triangles wound alike, facing out.
void expectClosed(const pde::Model& model, pde::MeshOptions grid) {
    const mesh::Topology t = mesh::analyseTopology(pde::meshModel(model, grid));
    EXPECT_EQ(t.boundaryEdges, 0u);
    EXPECT_EQ(t.nonManifoldEdges, 0u);
    EXPECT_EQ(t.misorientedEdges, 0u);
    EXPECT_GT(t.signedVolume, 0); // facing out, as the mesh did
}

} // namespace

TEST(PdeMeshFit, ASpheresBandsMeetWithoutACrackAndFaceOut) {
    // Caps and tubes share their loops: the tubes are pulled onto both.
    const pde::Model model = fittedSphere(4);
    ASSERT_EQ(model.patches.size(), 4u);
    EXPECT_TRUE(model.patches.front().cap);
    EXPECT_FALSE(model.patches[1].cap);
    expectClosed(model, {8, 16});
    expectClosed(model, {5, 37});
    // Without the start borders the tubes' u = 0 ends leave cracks.
    pde::Model bare = model;
    bare.startBorders.clear();
    EXPECT_GT(mesh::analyseTopology(pde::meshModel(bare, {8, 16})).boundaryEdges, 0u);
}

TEST(PdeMeshFit, NeighbouringPatchesMeetWithoutACrack) {
    // A closed mesh gives a closed model: every edge of the meshed patches
    // has two triangles, the shared border points being one vertex each.
    const pde::Model model = fittedSphere(12);
    ASSERT_FALSE(model.patches.empty());
    expectClosed(model, {8, 16});
    // Without the borders the same patches leave cracks (the check can fail).
    pde::Model bare = model;
    bare.borders.clear();
    EXPECT_GT(mesh::analyseTopology(pde::meshModel(bare, {8, 16})).boundaryEdges, 0u);
}

TEST(PdeMeshFit, ATorusHasNoCapAndIsStillCovered) {
    pde::MeshFitOptions o;
    o.radii = 8;
    const Measured t = fitAndMeasure(torus(), o);
    EXPECT_GE(t.patches, 2u); // closed and of genus one: never one disk
    EXPECT_LT(t.rms, 3e-3);
    EXPECT_LT(t.hausdorff, 0.04);
}

TEST(PdeMeshFit, AHoleAndTwoPartsAreFittedPartByPart) {
    Mesh holed = sphere(32, 64);
    // Cut out the faces round the north pole: a hole with a rim.
    std::erase_if(holed.triangles, [&](const mesh::Triangle& t) {
        return holed.positions[t[0]][2] > 0.9f || holed.positions[t[1]][2] > 0.9f ||
               holed.positions[t[2]][2] > 0.9f;
    });
    pde::MeshFitOptions o;
    o.radii = 8;
    const Measured h = fitAndMeasure(holed, o);
    EXPECT_LT(h.rms, 3e-3);
    // Two spheres apart: every patch stays on its own sphere.
    Mesh two = sphere(24, 48);
    const Mesh other = sphere(24, 48);
    const auto offset = std::uint32_t(two.positions.size());
    for (auto p : other.positions)
        two.positions.push_back({p[0] + 3, p[1], p[2]});
    for (auto t : other.triangles)
        two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const Measured t = fitAndMeasure(two, o);
    EXPECT_GE(t.patches, 4u);
    EXPECT_LT(t.rms, 3e-3);
    EXPECT_LT(t.hausdorff, 0.04);
}

TEST(PdeMeshFit, TheBunnyMeetsTheIssuesGoalAndItsEarsAreCovered) {
    const auto bunny = shared("bunny.obj");
    if (!bunny) GTEST_SKIP() << "no ../shared/meshes/bunny.obj";
    const Measured b = fitAndMeasure(*bunny);
    // Issue 30's goal: <= 27 KB at <= 0.5 % RMS and <= 2 % Hausdorff (and aim for 10 KB).
    EXPECT_LE(b.bytes, 27u * 1024);
    EXPECT_LE(b.rms, 0.005);
    EXPECT_LE(b.hausdorff, 0.02);
    std::cout << "bunny: " << b.patches << " patches, " << b.bytes << " bytes, RMS " << b.rms
              << ", Hausdorff " << b.hausdorff << "\n";
}

TEST(PdeMeshFit, TheFandisksSharpEdgesAreFollowed) {
    const auto fandisk = shared("fandisk.obj");
    if (!fandisk) GTEST_SKIP() << "no ../shared/meshes/fandisk.obj";
    const Measured f = fitAndMeasure(*fandisk);
    EXPECT_LT(f.rms, 0.005);
    EXPECT_LT(f.hausdorff, 0.03);
}

TEST(PdeMeshFit, MoreRadiiNeverMissMore) {
    const Mesh m = sphere(24, 48);
    double last = 1e300;
    for (std::size_t radii : {1u, 2u, 4u, 8u}) {
        pde::MeshFitOptions o;
        o.patches = 6;
        o.radii = radii;
        std::string why;
        const auto fit = pde::fitMesh(m, o, &why);
        ASSERT_TRUE(fit) << why;
        EXPECT_LE(fit->rms, last * 1.0001) << radii << " radii";
        last = fit->rms;
    }
}

TEST(PdeMeshFit, MeshesNoPatchCanStandForAreRefusedWithWhereAndWhy) {
    std::string why;
    EXPECT_FALSE(pde::fitMesh(Mesh{}, {}, &why));
    EXPECT_NE(why.find("no faces"), std::string::npos) << why;
    // Three faces on one edge.
    Mesh fin;
    fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const std::vector<std::uint32_t> lines{7, 8, 9};
    EXPECT_FALSE(pde::fitMesh(fin, {}, &why, &lines));
    EXPECT_NE(why.find("line 9"), std::string::npos) << why;
    // Two faces wound against each other across an edge.
    Mesh flipped;
    flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    flipped.triangles = {{0, 1, 2}, {1, 2, 3}};
    EXPECT_FALSE(pde::fitMesh(flipped, {}, &why));
    EXPECT_NE(why.find("wind the same way"), std::string::npos) << why;
    // Nothing but faces without area.
    Mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}};
    flat.triangles = {{0, 1, 1}};
    EXPECT_FALSE(pde::fitMesh(flat, {}, &why));
    // A single triangle is a mesh: one patch.
    Mesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.triangles = {{0, 1, 2}};
    const auto fit = pde::fitMesh(one, {}, &why);
    ASSERT_TRUE(fit) << why;
    EXPECT_EQ(fit->model.patches.size(), 1u);
}

TEST(PdeMeshFit, AFitAskedToStopStopsAndSaysSo) {
    std::atomic<bool> stop{true};
    pde::MeshFitOptions o;
    o.cancel = &stop;
    std::string why;
    EXPECT_FALSE(pde::fitMesh(sphere(12, 24), o, &why));
    EXPECT_EQ(why, "cancelled");
    stop = false;
    EXPECT_TRUE(pde::fitMesh(sphere(12, 24), o, &why)) << why;
}
