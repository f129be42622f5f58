// Chat commands: parsed, and turned into scenes that pass the class's checks.
#include "classroom/chat_commands.h"
#include "classroom/scene_policy.h"
#include "classroom/starter_scene.h"

#include "scenes.h"

#include "scene/field_access.h"
#include "scene/scene_reader.h"
#include "scene/source_map.h"

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

ChatCommand command(const std::string& text) {
    const ChatCommandParse p = parseChatCommand(text);
    EXPECT_TRUE(p.command.has_value()) << text << ": " << p.error;
    return p.command.value_or(ChatCommand{});
}

// The formula text of the first `type` node's `definition`.
std::string definitionOf(const std::string& sceneText, const std::string& type) {
    scene::ReadOptions o;
    o.followReferences = false;
    auto r = scene::readSceneBytes(sceneText, "scene", o);
    EXPECT_TRUE(r.ok());
    std::string out;
    if (r.ok())
        r.scene->forEachNode([&](const scene::Node& n) {
            if (out.empty() && n.type == type)
                if (const scene::Field* f = n.field("definition")) out = scene::formulaText(*f);
        });
    return out;
}

std::string applied(const std::string& text, const std::string& scene) {
    std::string why;
    std::string out = applyChatCommand(command(text), scene, why);
    EXPECT_FALSE(out.empty()) << text << ": " << why;
    EXPECT_TRUE(checkClassroomScene(out).ok) << out;
    return out;
}

TEST(ChatCommands, Parse) {
    EXPECT_EQ(command("/help").kind, ChatCommandKind::Help);
    const ChatCommand add = command("/add sphere(1, 0, 0, 0.5) difference");
    EXPECT_EQ(add.kind, ChatCommandKind::Add);
    EXPECT_EQ(add.operation, ShapeOperation::Difference);
    EXPECT_EQ(add.formula, "sphere(1, 0, 0, 0.5)");
    EXPECT_EQ(command("/add box(1,1,1)").operation, ShapeOperation::Union);
    EXPECT_EQ(command("/add box(1,1,1) intersection").operation, ShapeOperation::Intersection);
    EXPECT_EQ(command("/remove sphere(0.5)").operation, ShapeOperation::Difference);
    const ChatCommand paint = command("/paint 1,0.5,0 40% sphere(0, 1, 0, 0.3)");
    EXPECT_EQ(paint.kind, ChatCommandKind::Paint);
    EXPECT_DOUBLE_EQ(paint.colour.g, 0.5);
    EXPECT_DOUBLE_EQ(paint.opacity, 0.4);
    EXPECT_EQ(paint.formula, "sphere(0, 1, 0, 0.3)");
    EXPECT_DOUBLE_EQ(command("/paint red sphere(0.3)").opacity, 1.0);
    EXPECT_EQ(command("/undo").kind, ChatCommandKind::Undo);
    EXPECT_EQ(command("/save end of lesson").label, "end of lesson");
}

TEST(ChatCommands, ParseErrorsSayWhat) {
    EXPECT_NE(parseChatCommand("/fly").error.find("unknown command"), std::string::npos);
    EXPECT_FALSE(parseChatCommand("/add").command);
    EXPECT_FALSE(parseChatCommand("/paint mauve sphere(1)").command);
    EXPECT_FALSE(parseChatCommand("/paint 2,0,0 sphere(1)").command);
    EXPECT_FALSE(parseChatCommand("/paint red 150% sphere(1)").command);
    EXPECT_FALSE(parseChatCommand("/paint red").command);
    EXPECT_FALSE(parseChatCommand("/undo now").command);
}

TEST(ChatCommands, AddCombinesWithTheClassShape) {
    const std::string s =
        applied("/add sphere(1, 0, 0, 0.5) difference", test::classScene("sphere(0, 0, 0, 1)"));
    EXPECT_EQ(definitionOf(s, "FGeometry"), "(sphere(0, 0, 0, 1)) \\ (sphere(1, 0, 0, 0.5))");
    const std::string u = applied("/add box(0.2, 0.2, 2)", s);
    EXPECT_EQ(definitionOf(u, "FGeometry"),
              "((sphere(0, 0, 0, 1)) \\ (sphere(1, 0, 0, 0.5))) | (box(0.2, 0.2, 2))");
}

TEST(ChatCommands, AddToAScriptCombinesItsReturn) {
    const std::string s =
        applied("/add sphere(0.5) intersection", test::classScene("a = sphere(1); return a;"));
    EXPECT_EQ(definitionOf(s, "FGeometry"), "a = sphere(1); return (a) & (sphere(0.5));");
}

TEST(ChatCommands, CommentsInAToolNeverBreakTheNextCommand) {
    // Issue 26 §6: a `;` inside a comment made the class shape look like a
    // script, and every later /add and /remove failed for everyone.
    std::string scene = test::classScene("sphere(0, 0, 0, 1)");
    for (const char* cmd :
         {"/add box(0.5, 0.5, 0.5) /* cut; here */", "/remove sphere(0.2) // ; gone",
          "/add sphere(0.3, 0, 0, 0.1) intersection", "/remove box(0.1, 0.1, 3)"}) {
        const std::string next = applied(cmd, scene);
        ASSERT_FALSE(next.empty()) << cmd;
        EXPECT_TRUE(checkClassroomScene(next).ok) << cmd << "\n" << definitionOf(next, "FGeometry");
        scene = next;
    }
    const std::string def = definitionOf(scene, "FGeometry");
    EXPECT_NE(def.find("/* cut; here */"), std::string::npos) << def; // comments stay
}

TEST(ChatCommands, AReturnInACommentIsNotTheScriptsReturn) {
    const std::string s =
        applied("/add sphere(0.5)", test::classScene("a = sphere(1); return a; // not: return b;"));
    EXPECT_EQ(definitionOf(s, "FGeometry"),
              "a = sphere(1); return (a) | (sphere(0.5)); // not: return b;");
}

TEST(ChatCommands, AddMakesTheClassShapeInAnEmptyScene) {
    const std::string empty = "<X3D profile='Immersive' version='3.3'><Scene>\n<Viewpoint "
                              "position='0 0 5'/>\n</Scene></X3D>";
    const std::string s = applied("/add sphere(0, 0, 0, 1)", empty);
    EXPECT_EQ(definitionOf(s, "FGeometry"), "sphere(0, 0, 0, 1)");
    std::string why;
    EXPECT_TRUE(applyChatCommand(command("/remove sphere(1)"), empty, why).empty());
    EXPECT_FALSE(why.empty());
}

TEST(ChatCommands, PaintBlendsInsideTheTool) {
    const std::string s = applied("/paint red 50% sphere(0, 1, 0, 0.3)", starterScene());
    const std::string material = definitionOf(s, "FMaterial");
    EXPECT_NE(material.find("paint = 0.5 * step(0, sphere(0, 1, 0, 0.3));"), std::string::npos);
    EXPECT_NE(material.find("r = mix(r, 1, paint);"), std::string::npos);
}

TEST(ChatCommands, PaintGivesAStandardMaterialAFunctionOne) {
    const std::string scene = "<X3D profile='Immersive' version='3.3'><Scene><FShape>"
                              "<FGeometry type='implicit' definition='\"sphere(1)\"'/>"
                              "<Appearance><Material diffuseColor='0 0 1'/></Appearance>"
                              "</FShape></Scene></X3D>";
    const std::string s = applied("/paint yellow sphere(0, 1, 0, 0.5)", scene);
    const std::string material = definitionOf(s, "FMaterial");
    EXPECT_NE(material.find("b = 1;"), std::string::npos) << material;
    EXPECT_NE(material.find("mix(r, 1, paint)"), std::string::npos);
}

TEST(ChatCommands, AnInvalidToolFormulaGivesAnInvalidScene) {
    std::string why;
    const std::string s =
        applyChatCommand(command("/add sphere(0, 0, 0"), test::classScene("sphere(1)"), why);
    ASSERT_FALSE(s.empty());
    EXPECT_FALSE(checkClassroomScene(s).ok);
}

TEST(ChatCommands, AMistypedFormulaIsLocatedInWhatWasTyped) {
    // Issue 29 §5: it said "14:181", a place in the class scene.
    const std::string typed = "/add sphere(0, 0, 0, 0.5";
    const auto mistake = formulaMistakeInCommand(command(typed), typed);
    ASSERT_TRUE(mistake);
    EXPECT_EQ(mistake->said().rfind("column ", 0), 0u) << mistake->said();
    const int column = int(mistake->column);
    EXPECT_GE(column, 12); // within (or just past) the formula, never the scene's 181
    EXPECT_LE(column, int(typed.size()) + 1);
    EXPECT_FALSE(
        formulaMistakeInCommand(command("/add sphere(0, 0, 0, 0.5)"), "/add sphere(0, 0, 0, 0.5)"));
    // Columns are characters: an accent before the formula counts once.
    const std::string accented = "/paint red 50% é + (";
    const auto paint = formulaMistakeInCommand(command(accented), accented);
    ASSERT_TRUE(paint);
    EXPECT_LE(paint->column, 21u);
}

TEST(ChatCommands, TheClassScenesCommentsSurviveTenCommands) {
    // Commands change definitions in place: the class's comments, layout
    // and every other value stay as typed (the scene was once rewritten).
    std::string scene = starterScene();
    scene.insert(scene.find("<FShape"), "<!-- the class's notes: keep the stem thin -->\n    ");
    const char* commands[] = {"/add sphere(0.8, 0, 0, 0.5)",
                              "/remove box(0.2, 0.2, 0.2)",
                              "/paint red sphere(0, 1, 0, 0.3)",
                              "/add torus(1, 0.8) union",
                              "/paint 0.1,0.2,0.3 50% sphere(0, 0, 1, 0.2)",
                              "/add cylinder(0.1, 2) union",
                              "/remove sphere(0, 0, 0, 0.1)",
                              "/paint blue sphere(-1, 0, 0, 0.4)",
                              "/add sphere(0, -0.8, 0, 0.3)",
                              "/paint green 20% box(0.5, 0.5, 0.5)"};
    for (const char* c : commands) {
        scene = applied(c, scene);
        EXPECT_NE(scene.find("<!-- the class's notes: keep the stem thin -->"), std::string::npos)
            << c << "\n"
            << scene;
        EXPECT_NE(scene.find("resolution='48'"), std::string::npos) << c;
    }
    EXPECT_NE(definitionOf(scene, "FGeometry").find("sphere(0, -0.8, 0, 0.3)"), std::string::npos);
    EXPECT_NE(definitionOf(scene, "FMaterial").find("mix(r, 0, paint)"), std::string::npos);
}

TEST(ChatCommands, ClassicClassScenesKeepTheirCommentsToo) {
    const std::string scene = "#X3D V3.3 utf8\nPROFILE Immersive\n# the class's notes\n"
                              "DEF CLASS FShape { geometry FGeometry { type \"implicit\"\n"
                              "  definition [ \"sphere(0, 0, 0, 1)\" ] # first try\n"
                              "  domainMin -2 -2 -2 domainMax 2 2 2 } }\n";
    const std::string s = applied("/add sphere(1, 0, 0, 0.5)", scene);
    EXPECT_NE(s.find("# the class's notes"), std::string::npos) << s;
    EXPECT_NE(s.find("# first try"), std::string::npos) << s;
    EXPECT_NE(definitionOf(s, "FGeometry").find("sphere(1, 0, 0, 0.5)"), std::string::npos);
}

} // namespace
} // namespace fl::classroom
