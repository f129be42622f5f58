// The comparison every round-trip test relies on must say "different" — with
// where — when one thing differs: one bit of a number, one character of a
// string, a broken DEF/USE share, a ROUTE, a field of a PROTO instance, a
// declared field. (Issue 18: a comparison that always answers "same" would
// let every round-trip test pass.)
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

using namespace fl::scene;

namespace {

const char* kScene = R"(#X3D V3.3 utf8
PROFILE Full
PROTO Lamp [ inputOutput SFColor tint 1 1 1 ] {
  Shape { appearance Appearance { material Material { diffuseColor IS tint } } geometry Sphere { } }
}
DEF MOVER Transform {
  translation 1 2 3
  children [
    DEF BALL Shape { geometry Sphere { radius 0.5 } }
    USE BALL
    Lamp { tint 0.2 0.4 0.6 }
    Script { inputOnly SFTime tick url "ecmascript: function tick(t) {}" }
  ]
}
WorldInfo { title "the original title" }
DEF CLOCK TimeSensor { loop TRUE }
DEF PATH PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 0, 1 0 0 ] }
ROUTE CLOCK.fraction_changed TO PATH.set_fraction
ROUTE PATH.value_changed TO MOVER.set_translation
)";

std::unique_ptr<Scene> read() {
    ReadOptions options;
    options.compileFunctions = false;
    ReadResult r = readSceneBytes(kScene, "a.x3dv", options);
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

Node* rootNamed(Scene& s, const std::string& def) {
    for (Node* n : s.roots)
        if (n->defName == def) return n;
    return nullptr;
}

Node* child(Node& parent, std::size_t i) {
    return parent.field("children")->value.nodes.at(i);
}

// `mutate` changes one thing in a copy; sameModel must say "different" and
// name something of `where`.
template <class Mutation>
void expectDifferent(Mutation mutate, const std::string& where) {
    auto a = read(), b = read();
    std::string difference;
    ASSERT_TRUE(sameModel(*a, *b, &difference)) << "two reads differ: " << difference;
    mutate(*b);
    difference.clear();
    EXPECT_FALSE(sameModel(*a, *b, &difference)) << "not seen: " << where;
    EXPECT_NE(difference.find(where), std::string::npos) << "said: " << difference;
}

} // namespace

TEST(SameModel, OneBitOfANumberIsADifference) {
    expectDifferent(
        [](Scene& s) {
            double& x = rootNamed(s, "MOVER")->field("translation")->value.numbers[1];
            x = std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) ^ 1u);
        },
        "translation");
}

TEST(SameModel, OneCharacterOfAStringIsADifference) {
    expectDifferent(
        [](Scene& s) {
            for (Node* n : s.roots)
                if (n->type == "WorldInfo") n->field("title")->value.strings[0][4] = 'O';
        },
        "title");
}

TEST(SameModel, ABrokenDefUseShareIsADifference) {
    expectDifferent(
        [](Scene& s) {
            // The USE becomes a node of its own with the same fields.
            Node* mover = rootNamed(s, "MOVER");
            Node* copy = s.newNode();
            *copy = *child(*mover, 0);
            copy->defName.clear();
            mover->field("children")->value.nodes[1] = copy;
        },
        "USE");
}

TEST(SameModel, ARouteIsPartOfTheModel) {
    expectDifferent([](Scene& s) { s.routes.back().toField = "set_scale"; }, "ROUTE");
    expectDifferent([](Scene& s) { s.routes.pop_back(); }, "ROUTE");
}

TEST(SameModel, AFieldOfAProtoInstanceIsADifference) {
    expectDifferent(
        [](Scene& s) { child(*rootNamed(s, "MOVER"), 2)->field("tint")->value.numbers[2] = 0.7; },
        "tint");
}

TEST(SameModel, ADeclaredFieldIsADifference) {
    expectDifferent(
        [](Scene& s) {
            child(*rootNamed(s, "MOVER"), 3)->declarations[0].access = AccessType::InputOutput;
        },
        "declaration");
}
