// The standard shapes an FShape without geometry lends to (scene/
// effects_plan.h: lendingShapes, lentPhysics): every Shape below its group,
// once, however often a subtree is USE'd, and the walk bounded by the scene's
// size — a group USE'd twice at each of 20 levels has 2^20 paths but 21 groups
// (the reader refuses more than 4 million nodes unfolded, so 20 is near the most).
#include "scene/effects_plan.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <string>

using namespace fl::scene;

namespace {

const std::string kLender =
    "FShape { physics FPhysics { surface FSurface { friction FFriction { definition \"0.5\" } } } "
    "}\n";

const Node* named(const Scene& scene, const std::string& def) {
    const Node* found = nullptr;
    scene.forEachNode([&](const Node& n) {
        if (!found && n.defName == def) found = &n;
    });
    return found;
}

} // namespace

TEST(Lending, ASharedSubtreeIsLentToOnceHoweverOftenItIsUsed) {
    // Level 0 holds the Shape; level k USEs level k-1 twice.
    std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\nGroup { children [\n" + kLender +
                       "DEF L0 Group { children [ DEF BOX Shape { geometry Box { } } ] }\n";
    for (int k = 1; k <= 20; ++k)
        text += "DEF L" + std::to_string(k) + " Group { children [ USE L" + std::to_string(k - 1) +
                " USE L" + std::to_string(k - 1) + " ] }\n";
    text += "] }\n";
    const ReadResult r = readSceneBytes(text, "deep.x3dv");
    ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics.front().message);
    const auto lent = lendingShapes(*r.scene);
    const Node* box = named(*r.scene, "BOX");
    ASSERT_NE(box, nullptr);
    ASSERT_EQ(lent.count(box), 1u);
    EXPECT_EQ(lent.at(box).size(), 1u);                 // one lender, listed once
    const EffectsPlan plan = makeEffectsPlan(*r.scene); // the entries point into it
    const auto physics = lentPhysics(*r.scene, plan);
    ASSERT_EQ(physics.count(box), 1u);
    EXPECT_FALSE(physics.at(box)->tangible.empty());
}

TEST(Lending, ShapesOutsideTheLendersGroupBorrowNothing) {
    const ReadResult r = readSceneBytes(
        "#X3D V3.3 utf8\nPROFILE Immersive\nGroup { children [\n" + kLender +
            "DEF IN Shape { geometry Sphere { } } ] }\nDEF OUT Shape { geometry Box { } }\n",
        "apart.x3dv");
    ASSERT_TRUE(r.ok());
    const auto lent = lendingShapes(*r.scene);
    EXPECT_EQ(lent.count(named(*r.scene, "IN")), 1u);
    EXPECT_EQ(lent.count(named(*r.scene, "OUT")), 0u);
}
