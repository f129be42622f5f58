// Node kinds as a type (scene/node_kind.h): one per catalogue entry, in the
// catalogue's order, so a kind and its type name never disagree; PROTO
// instances and unknown types are Unknown.
#include "scene/node_catalogue.h"
#include "scene/node_kind.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl::scene;

TEST(NodeKind, EveryCatalogueEntryHasItsKind) {
    for (const NodeSpec& spec : nodeCatalogue()) {
        const NodeKind kind = kindOf(&spec);
        EXPECT_NE(kind, NodeKind::Unknown) << spec.name;
        EXPECT_EQ(nameOf(kind), spec.name);
        EXPECT_EQ(kindOf(findNodeSpec(spec.name)), kind);
    }
    // A copy of a spec outside the catalogue is found by its name.
    const NodeSpec copy = *findNodeSpec("Transform");
    EXPECT_EQ(kindOf(&copy), NodeKind::Transform);
    EXPECT_EQ(kindOf(nullptr), NodeKind::Unknown);
    EXPECT_EQ(nameOf(NodeKind::Unknown), "");
}

TEST(NodeKind, NodesOfAReadSceneKnowWhatTheyAre) {
    const ReadResult r = readSceneBytes("#X3D V3.3 utf8\nPROFILE Immersive\n"
                                        "PROTO Ball [ ] { Shape { geometry Sphere { } } }\n"
                                        "Transform { children [ Ball { } FShape { } ] }\n",
                                        "a.x3dv");
    ASSERT_TRUE(r.ok());
    const Node* transform = r.scene->roots.at(0);
    EXPECT_EQ(transform->kind(), NodeKind::Transform);
    const auto& children = transform->field("children")->value.nodes;
    ASSERT_EQ(children.size(), 2u);
    EXPECT_EQ(children[0]->kind(), NodeKind::Unknown); // a PROTO instance
    EXPECT_EQ(children[1]->kind(), NodeKind::FShape);
}
