// Fitting polygon meshes with PDE patches (pde fit): named hard cases — a
// sphere and a cylinder as meshes, a torus (no cap anywhere), a mesh with a
// hole, two parts, the bunny's ears (branches), the fandisk's sharp edges —
// each measured the way any tool would (the model written, read back,
// meshed, and compared by exact distances both ways); bad meshes refused
// with where and why; more radii never miss more.
#include "mesh/mesh_topology.h"
#include "mesh/obj_reader.h"
#include "mesh/surface_distance.h"
#include "pde/fit_measure.h"
#include "pde/mesh_fit.h"
#include "pde/pde_file.h"
#include "pde/pde_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

using namespace fl;
using fl::mesh::Mesh;

namespace {

constexpr double kPi = std::numbers::pi;

// A welded UV sphere: one vertex at each pole, no seam.
Mesh sphere(int rings = 48, int segments = 96, double r = 1) {
    Mesh m;
    m.positions.push_back({0, 0, float(r)});
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double t = kPi * i / rings, p = 2 * kPi * j / segments;
            m.positions.push_back({float(r * std::sin(t) * std::cos(p)),
                                   float(r * std::sin(t) * std::sin(p)), float(r * std::cos(t))});
        }
    m.positions.push_back({0, 0, float(-r)});
    const auto south = std::uint32_t(m.positions.size() - 1);
    auto at = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back({at(rings - 1, j), south, at(rings - 1, j + 1)});
    return m;
}

// A grid of rows x columns over (s, t) in [0,1] x [0,1), closed round t
// when `wrap`, its points from `f`.
template <typename F>
Mesh grid(int rows, int columns, bool wrapRows, F&& f) {
    Mesh m;
    const int ringCount = wrapRows ? rows : rows + 1;
    for (int i = 0; i < ringCount; ++i)
        for (int j = 0; j < columns; ++j) {
            const auto p = f(double(i) / rows, double(j) / columns);
            m.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
        }
    auto at = [&](int i, int j) {
        return std::uint32_t((i % ringCount) * columns + (j % columns));
    };
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return m;
}

Mesh cylinder() { // open at both ends
    return grid(24, 96, false, [](double s, double t) {
        return std::array<double, 3>{0.5 * std::cos(2 * kPi * t), 0.5 * std::sin(2 * kPi * t),
                                     2 * s - 1};
    });
}

Mesh torus() {
    return grid(64, 32, true, [](double s, double t) {
        const double a = 2 * kPi * s, b = 2 * kPi * t;
        return std::array<double, 3>{(1 + 0.35 * std::cos(b)) * std::cos(a),
                                     (1 + 0.35 * std::cos(b)) * std::sin(a), 0.35 * std::sin(b)};
    });
}

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

TEST(PdeMeshFit, ASphereAndACylinderAreRecoveredWithFewPatches) {
    for (const auto& [name, m] :
         {std::pair{"sphere", sphere()}, std::pair{"cylinder", cylinder()}}) {
        pde::MeshFitOptions o;
        o.radii = 8; // the radii search is the bunny's test
        const Measured s = fitAndMeasure(m, o);
        EXPECT_LE(s.patches, 16u) << name;
        EXPECT_LT(s.rms, 2e-3) << name;
        EXPECT_LT(s.hausdorff, 0.03) << name;
    }
}

TEST(PdeMeshFit, NeighbouringPatchesMeetWithoutACrack) {
    // A closed mesh gives a closed model: every edge of the meshed patches
    // has two triangles, the shared border points being one vertex each.
    pde::MeshFitOptions o;
    o.patches = 12;
    o.radii = 6;
    std::string why;
    const auto fit = pde::fitMesh(sphere(24, 48), o, &why);
    ASSERT_TRUE(fit) << why;
    const pde::ReadResult back = pde::readModel(pde::encodeBinary(fit->model), "s.pde");
    ASSERT_TRUE(back.ok()) << back.error;
    const mesh::Topology t = mesh::analyseTopology(pde::meshModel(*back.model, {8, 16}));
    EXPECT_EQ(t.boundaryEdges, 0u);
    EXPECT_EQ(t.nonManifoldEdges, 0u);
    EXPECT_EQ(t.misorientedEdges, 0u);
    EXPECT_GT(t.signedVolume, 0); // facing out, as the mesh did
    // Without the borders the same patches leave cracks (the check can fail).
    pde::Model bare = *back.model;
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
