// A scene is a tree with shared leaves, never a loop (DESIGN §3): every way
// a file can make a node its own ancestor is refused where the USE is written,
// naming the DEF it loops to; a DAG of shared nodes loads; what a scene
// unfolds to (USEs, PROTO instances) is bounded. The property test draws
// random DEF/USE graphs in both encodings: a loop is refused, a DAG loads.
#include "../common/node_graph_text.h"
#include "scene/node_graph.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

using namespace fl::scene;

namespace {

const SceneDiagnostic* firstError(const ReadResult& r) {
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) return &d;
    return nullptr;
}

std::string classic(const std::string& body) {
    return "#X3D V3.3 utf8\nPROFILE Full\n" + body;
}

std::string xml(const std::string& body) {
    return "<X3D profile='Full'><Scene>\n" + body + "\n</Scene></X3D>\n";
}

struct Expected {
    int line, column;
    std::string words; // a piece of the message
};

void expectRefused(const std::string& text, const std::string& name, Expected e) {
    const ReadResult r = readSceneBytes(text, name);
    ASSERT_FALSE(r.ok()) << text;
    const SceneDiagnostic* d = firstError(r);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->file, name);
    EXPECT_EQ(d->pos.line, e.line) << d->message;
    EXPECT_EQ(d->pos.column, e.column) << d->message;
    EXPECT_NE(d->message.find(e.words), std::string::npos) << d->message;
    EXPECT_FALSE(d->suggestion.empty());
}

TEST(NodeLoops, XmlUseOfTheEnclosingNode) {
    // The three lines of issue 26 §1.
    expectRefused(xml("<Transform DEF='A'><Transform USE='A'/></Transform>"), "loop.x3d",
                  {2, 36, "USE A is inside the node it names (DEF A at 2:17)"});
}

TEST(NodeLoops, ClassicUseOfTheEnclosingNode) {
    expectRefused(classic("DEF A Transform { children [ USE A ] }\n"), "loop.x3dv",
                  {3, 34, "USE A is inside the node it names"});
}

TEST(NodeLoops, Vrml97UseOfAnAncestorThroughOtherNodes) {
    expectRefused("#VRML V2.0 utf8\n"
                  "DEF TOP Group { children [\n"
                  "  Transform { children [ Shape { } Transform { children USE TOP } ] }\n"
                  "] }\n",
                  "loop.wrl", {3, 61, "USE TOP is inside the node it names (DEF TOP at 2:5)"});
}

TEST(NodeLoops, ForwardUsesThatCloseALoop) {
    // Neither USE names an open node when it is read: only the whole graph
    // shows the loop.
    expectRefused(classic("DEF A Group { children [ USE B ] }\n"
                          "DEF B Group { children [ USE A ] }\n"),
                  "forward.x3dv",
                  {4, 30, "USE A makes a loop: DEF A (at 3:5) would contain itself"});
    expectRefused(xml("<Group DEF='A'><Group USE='B'/></Group>\n"
                      "<Group DEF='B'><Transform><Group USE='A'/></Transform></Group>"),
                  "forward.x3d", {3, 39, "USE A makes a loop"});
}

TEST(NodeLoops, InsideFunctionCompositionsSwitchAndLod) {
    expectRefused(xml("<FTransform DEF='F' operation='union'>\n"
                      " <FShape><FGeometry definition='sphere(0,0,0,1)'/></FShape>\n"
                      " <FTransform USE='F'/>\n"
                      "</FTransform>"),
                  "ftransform.x3d", {4, 19, "USE F is inside the node it names"});
    expectRefused(classic("DEF S Switch { whichChoice 0 children [ USE S ] }\n"), "switch.x3dv",
                  {3, 45, "USE S"});
    expectRefused(
        "#VRML V2.0 utf8\nDEF S Switch { whichChoice 0 choice [ Group { children USE S } ] }\n",
        "switch.wrl", {2, 60, "USE S"});
    expectRefused(classic("DEF L LOD { range [ 10 ] level [ Shape {} USE L ] }\n"), "lod.x3dv",
                  {3, 47, "USE L"});
}

TEST(NodeLoops, ThroughAProtoInstanceField) {
    // The instance's field is substituted into the PROTO body: the loop runs
    // Group A > P > (expansion) Group > A.
    expectRefused(classic("PROTO P [ inputOutput MFNode kids [] ] { Group { children IS kids } }\n"
                          "DEF A Group { children [ P { kids [ USE A ] } ] }\n"),
                  "proto.x3dv", {4, 41, "USE A is inside the node it names"});
    expectRefused(xml("<ProtoDeclare name='P'><ProtoInterface>"
                      "<field name='kids' type='MFNode' accessType='inputOutput'/>"
                      "</ProtoInterface><ProtoBody><Group><IS>"
                      "<connect nodeField='children' protoField='kids'/></IS></Group>"
                      "</ProtoBody></ProtoDeclare>\n"
                      "<Group DEF='A'><ProtoInstance name='P'><fieldValue name='kids'>"
                      "<Group USE='A'/></fieldValue></ProtoInstance></Group>"),
                  "proto.x3d", {3, 76, "USE A is inside the node it names"});
}

TEST(NodeLoops, InsideAProtoBodyEvenWhenNeverInstanced) {
    expectRefused(classic("PROTO P [] { DEF B Group { children [ USE B ] } }\n"), "body.x3dv",
                  {3, 43, "USE B is inside the node it names"});
    expectRefused(classic("PROTO P [] { Group { children [\n"
                          "  DEF B Group { children [ USE C ] }\n"
                          "  DEF C Group { children [ USE B ] } ] } }\n"
                          "P {}\n"),
                  "body.x3dv", {5, 32, "USE B makes a loop"});
}

TEST(NodeLoops, AProtoWhoseDefaultHoldsItselfNeverLoads) {
    // Whether the reader sees P inside its own interface or not, the scene
    // must not load with a loop in it.
    const ReadResult r = readSceneBytes(
        classic("PROTO P [ initializeOnly SFNode n P { } ] { Group { children IS n } }\n"
                "P { }\n"),
        "self.x3dv");
    if (r.ok()) {
        std::vector<const Node*> roots(r.scene->roots.begin(), r.scene->roots.end());
        EXPECT_FALSE(examineNodeGraph(roots, {}, Edges::WithExpansions, 1000, 100).loop);
    }
}

TEST(NodeLoops, AScriptMayNameItselfOrItsGroupInItsOwnFields) {
    // Its declared fields hold references, not children (VRML97 §6.40).
    const ReadResult r = readSceneBytes("#VRML V2.0 utf8\n"
                                        "DEF G Group { children [ DEF S Script {\n"
                                        "  field SFNode self USE S\n"
                                        "  field MFNode both [ USE G, USE S ]\n"
                                        "} ] }\n",
                                        "script.wrl");
    ASSERT_TRUE(r.ok()) << (firstError(r) ? firstError(r)->message : "");
}

TEST(NodeLoops, SharedNodesWithoutALoopLoad) {
    const ReadResult r =
        readSceneBytes(classic("DEF A Group { children Shape { } }\n"
                               "DEF B Transform { children [ USE A USE A ] }\n"
                               "Group { children [ USE B USE A Transform { children USE B } ] }\n"),
                       "dag.x3dv");
    ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
}

TEST(NodeLoops, WhatAScaleOfUsesUnfoldsToIsBounded) {
    // 40 levels, each using the last twice: a 2 KB file of 2^40 nodes.
    std::string text = "DEF L0 Group { }\n";
    for (int i = 1; i <= 40; ++i)
        text += "DEF L" + std::to_string(i) + " Group { children [ USE L" + std::to_string(i - 1) +
                " USE L" + std::to_string(i - 1) + " ] }\n";
    const ReadResult r = readSceneBytes(classic(text), "laughs.x3dv");
    ASSERT_FALSE(r.ok());
    const SceneDiagnostic* d = firstError(r);
    ASSERT_NE(d, nullptr);
    EXPECT_NE(d->message.find("once every USE, PROTO instance and Inline in it is unfolded"),
              std::string::npos)
        << d->message;
    EXPECT_EQ(d->pos.line, 3 + 21); // L21, of 2^22 - 1 nodes, is the first over 4 M
}

TEST(NodeLoops, AChainOfUsesDeeperThanAnyWalkIsRefused) {
    std::string text = "DEF L0 Group { }\n";
    const int levels = int(kMaxWalkDepth) + 10;
    for (int i = 1; i <= levels; ++i)
        text += "DEF L" + std::to_string(i) + " Group { children USE L" + std::to_string(i - 1) +
                " }\n";
    const ReadResult r = readSceneBytes(classic(text), "chain.x3dv");
    ASSERT_FALSE(r.ok());
    const SceneDiagnostic* d = firstError(r);
    ASSERT_NE(d, nullptr);
    EXPECT_NE(d->message.find("nest more than"), std::string::npos) << d->message;
}

// ---- property: random DEF/USE graphs -------------------------------------

TEST(NodeLoops, RandomGraphsLoadExactlyWhenTheyHaveNoLoop) {
    std::mt19937 rng(26);
    int loops = 0, dags = 0;
    for (int round = 0; round < 800; ++round) {
        std::vector<std::uint8_t> bytes(40);
        for (auto& b : bytes)
            b = std::uint8_t(rng());
        // Every other graph a DAG: children only of higher-numbered nodes.
        fl::test::NodeGraphText g = fl::test::NodeGraphText::fromBytes(bytes.data(), bytes.size());
        if (round % 2 == 0)
            for (std::size_t i = 0; i < g.children.size(); ++i)
                std::erase_if(g.children[i], [&](int c) { return std::size_t(c) <= i; });
        const std::string text = g.text();
        const ReadResult r = readSceneBytes(text, g.xml ? "g.x3d" : "g.x3dv");
        if (g.hasLoop()) {
            ++loops;
            ASSERT_FALSE(r.ok()) << text;
            const SceneDiagnostic* d = firstError(r);
            ASSERT_NE(d, nullptr);
            EXPECT_TRUE(d->message.find("makes a loop") != std::string::npos ||
                        d->message.find("inside the node it names") != std::string::npos)
                << d->message << "\n"
                << text;
            EXPECT_GT(d->pos.line, 2) << text;
        } else {
            ++dags;
            ASSERT_TRUE(r.ok()) << text << (firstError(r) ? firstError(r)->message : "");
        }
    }
    EXPECT_GT(loops, 150);
    EXPECT_GT(dags, 300);
}

} // namespace
