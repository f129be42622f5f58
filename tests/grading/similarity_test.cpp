// Similar submissions: the same model up to renaming, constants, placement
// and the order of commutative operations is found; a different model is
// not; what the starter already has does not make two submissions alike.
#include "grading/similarity.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl;
using namespace fl::grading;

namespace {

ModelFingerprint of(const std::string& body) {
    auto r = scene::readSceneBytes(
        "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n" + body, "model.x3dv");
    EXPECT_TRUE(r.ok()) << body;
    return modelFingerprint(*r.scene);
}

const char* kCastle = R"x(FShape { geometry FGeometry { type "explicit" definition [
  "keep = min(min(0.5 - abs(x), 0.6 - abs(y)), 0.5 - abs(z));"
  "door = min(min(0.15 - abs(x), -0.3 - y), z - 0.3);"
  "towers = max(0.04 - (x - 0.6)^2 - z*z, 0.04 - (x + 0.6)^2 - z*z) & (0.8 - abs(y));"
  "(keep \\ door) | towers" ] } })x";

// Renamed, other constants, moved (a Transform), operands swapped.
const char* kCopied = R"x(Transform { translation 3 1 0 children FShape { geometry FGeometry {
  type "explicit" definition [
  "walls = min(0.45 - abs(z), min(0.7 - abs(y), 0.55 - abs(x)));"
  "gate = min(min(-0.2 - y, 0.1 - abs(x)), z - 0.25);"
  "spires = (0.9 - abs(y)) & max(0.05 - (x + 0.5)^2 - z*z, 0.05 - (x - 0.5)^2 - z*z);"
  "spires | (walls \\ gate)" ]
}
}
})x";

const char* kOther = R"x(FShape { geometry FGeometry { type "explicit" definition [
  "r = sqrt(x*x + y*y + z*z);"
  "0.6 - r + 0.1*sin(8*atan2(y, x)) * cos(6*z)" ]
}
})x";

} // namespace

TEST(Similarity, TheSameModelRenamedMovedAndReorderedIsFound) {
    const ModelFingerprint a = of(kCastle), b = of(kCopied), c = of(kOther);
    EXPECT_GT(a.size(), 8u);
    EXPECT_DOUBLE_EQ(similarity(a, b), 1.0);
    EXPECT_LT(similarity(a, c), 0.3);
    const auto pairs = similarPairs({{"ann", a}, {"bob", b}, {"cid", c}}, 0.8);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].first, "ann");
    EXPECT_EQ(pairs[0].second, "bob");
}

TEST(Similarity, TheStarterDoesNotMakeTwoSubmissionsAlike) {
    const char* starter = R"x(FShape { geometry FGeometry { type "explicit"
      definition "0.8^2 - x*x - y*y - z*z" } })x";
    const ModelFingerprint s = of(starter);
    const ModelFingerprint onlyStarter1 = without(of(starter), s);
    const ModelFingerprint onlyStarter2 = without(of(starter), s);
    EXPECT_TRUE(onlyStarter1.empty());
    EXPECT_TRUE(similarPairs({{"a", onlyStarter1}, {"b", onlyStarter2}}, 0.5).empty());
    // The starter kept in both, plus the castle in one: not alike.
    const ModelFingerprint withCastle = without(of(std::string(starter) + kCastle), s);
    EXPECT_TRUE(similarPairs({{"a", onlyStarter1}, {"b", withCastle}}, 0.5).empty());
}

TEST(Similarity, HiddenShapesAreNotPartOfTheModel) {
    const ModelFingerprint hidden =
        of(std::string("Switch { whichChoice -1 choice [ ") + kCastle + " ] }");
    EXPECT_TRUE(hidden.empty());
}
