// The second line behind the reader's refusal of loops (DESIGN §3): a scene
// changed by code so that a node holds itself, with and without a DEF name,
// and with two paths back (exponential as a tree), is walked by the writers,
// the comparison, the effects plan and the mesher without a hang or a crash.
#include "mesh/scene_meshing.h"
#include "scene/effects_plan.h"
#include "scene/node_graph.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace fl;
using namespace fl::scene;

namespace {

const char* kScene = R"X3D(#X3D V3.3 utf8
PROFILE Immersive
COMPONENT FunctionLab:1
Transform { children [
  Group { children [
    FShape { geometry FGeometry { definition "sphere(0, 0, 0, 0.5)" } }
    Shape { geometry Box { size 0.2 0.2 0.2 } }
  ] }
] }
)X3D";

// Makes `holder` hold `held` once more in its children.
void holdAgain(Node& holder, Node* held) {
    Field* children = holder.field("children");
    ASSERT_NE(children, nullptr);
    children->value.nodes.push_back(held);
}

class LoopMadeByCode : public ::testing::TestWithParam<bool> {};

TEST_P(LoopMadeByCode, EveryWalkerStops) {
    ReadResult r = readSceneBytes(kScene, "loop.x3dv");
    ASSERT_TRUE(r.ok());
    Scene& s = *r.scene;
    Node* top = s.roots.front();
    if (GetParam()) top->defName = "TOP"; // the writers meet a DEF'd node again
    Node* group = top->field("children")->value.nodes.front();
    holdAgain(*group, top);
    holdAgain(*group, top); // two ways back: a tree walk doubles at each turn

    std::vector<const Node*> roots(s.roots.begin(), s.roots.end());
    EXPECT_TRUE(examineNodeGraph(roots, {}, Edges::Shown, 1000, 100).loop);

    const std::string xml = writeXml(s);
    const std::string classic = writeClassic(s);
    EXPECT_FALSE(xml.empty());
    EXPECT_FALSE(classic.empty());
    // What was written is a scene the reader refuses or reads, never a crash.
    (void)readSceneBytes(xml, "again.x3d");
    (void)readSceneBytes(classic, "again.x3dv");

    std::string difference;
    (void)sameModel(s, s, &difference);
    (void)makeEffectsPlan(s);

    mesh::SceneMeshOptions o;
    o.useFileResolution = false;
    o.mesh.resolution = 8;
    const mesh::SceneMeshes m = mesh::meshScene(s, o);
    EXPECT_FALSE(m.shapes.empty());
    EXPECT_TRUE(std::any_of(m.notes.begin(), m.notes.end(), [](const std::string& n) {
        return n.find("a node contains itself") != std::string::npos;
    }));
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutDef, LoopMadeByCode, ::testing::Bool());

} // namespace
