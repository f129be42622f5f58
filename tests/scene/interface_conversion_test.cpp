// Issue 20: a ComposedShader's uniforms (fields it declares itself), IS
// connections of declared fields inside a PROTO body, and the interfaces of
// Script, PackagedShader, ShaderProgram and unknown nodes survive every
// encoding and its gzip form, values (nodes too) included.
#include "scene/gzip.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <string>

using namespace fl::scene;

namespace {

const char* kShaderScene = R"(#X3D V3.3 utf8
PROFILE Immersive
COMPONENT Shaders:1
PROTO Effect [
  inputOnly SFTime someEvent3
  inputOutput SFFloat strength 0.5
] {
  Shape {
    appearance Appearance {
      shaders ComposedShader {
        language "GLSL"
        inputOnly SFTime time
        inputOnly SFTime anotherEvent IS someEvent3
        inputOutput SFFloat far 50
        inputOutput SFFloat gain IS strength
        initializeOnly SFVec3f offset 1 2 3
        outputOnly SFBool done
        inputOutput SFNode grainTexture ImageTexture { url "grain.png" }
        inputOutput MFNode layers [ ImageTexture { url "a.png" } ImageTexture { url "b.png" } ]
        parts ShaderPart { type "FRAGMENT" url "data:text/plain,void main(){}" }
      }
    }
    geometry Box { }
  }
}
Effect { strength 0.8 }
)";

std::unique_ptr<Scene> read(const std::string& bytes, const std::string& name) {
    ReadOptions options;
    options.compileFunctions = false;
    ReadResult r = readSceneBytes(bytes, name, options);
    std::string errors;
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) errors += formatSceneDiagnostic(d) + "\n";
    EXPECT_TRUE(r.ok()) << name << "\n" << errors;
    return std::move(r.scene);
}

} // namespace

TEST(InterfaceConversion, TheShaderSceneKeepsItsUniformsThroughXml) {
    auto a = read(kShaderScene, "a.x3dv");
    ASSERT_TRUE(a);
    const std::string classic = writeScene(*a, Encoding::ClassicVrml);
    const std::string xml = writeScene(*a, Encoding::Xml);
    // The XML says it the XML way: <field> children, IS as <connect>, node
    // values as children of their <field>, SFString attributes unquoted.
    for (const char* piece :
         {"<ComposedShader language='GLSL'>",
          "<field name='far' type='SFFloat' accessType='inputOutput' value='50'/>",
          "<field name='grainTexture' type='SFNode' accessType='inputOutput'>",
          "<connect nodeField='anotherEvent' protoField='someEvent3'/>",
          "<connect nodeField='gain' protoField='strength'/>", "<ShaderPart type='FRAGMENT'"})
        EXPECT_NE(xml.find(piece), std::string::npos) << piece << "\n" << xml;
    for (bool gzipped : {false, true}) {
        auto b = read(gzipped ? gzip(xml) : xml, gzipped ? "b.x3d.gz" : "b.x3d");
        ASSERT_TRUE(b);
        EXPECT_EQ(writeScene(*b, Encoding::ClassicVrml), classic) << "gzip " << gzipped;
        std::string difference;
        EXPECT_TRUE(sameModel(*a, *b, &difference)) << difference;
    }
    for (const char* line :
         {"inputOnly SFTime anotherEvent IS someEvent3", "inputOutput SFFloat gain IS strength",
          "inputOutput SFFloat far 50", "initializeOnly SFVec3f offset 1 2 3",
          "outputOnly SFBool done", "inputOutput SFNode grainTexture ImageTexture {",
          "inputOutput MFNode layers ["})
        EXPECT_NE(classic.find(line), std::string::npos) << line << "\n" << classic;
}

TEST(InterfaceConversion, ClassicGzipAndVrml97KeepAScriptsInterface) {
    const std::string vrml = R"(#VRML V2.0 utf8
PROTO Clock [ eventIn SFTime tick field SFNode target NULL ] {
  Script {
    eventIn SFTime beat IS tick
    field SFNode who IS target
    field MFNode spare [ Group { } ]
    eventOut SFFloat angle
    url "javascript: function beat(t) { angle = t; }"
  }
}
Clock { target Transform { } }
)";
    auto a = read(vrml, "a.wrl");
    ASSERT_TRUE(a);
    for (Encoding e : {Encoding::Vrml97, Encoding::ClassicVrml, Encoding::Xml})
        for (bool gzipped : {false, true}) {
            const std::string text = writeScene(*a, e);
            auto b =
                read(gzipped ? gzip(text) : text,
                     e == Encoding::Xml ? "b.x3d" : (e == Encoding::Vrml97 ? "b.wrl" : "b.x3dv"));
            ASSERT_TRUE(b);
            std::string difference;
            EXPECT_TRUE(sameModel(*a, *b, &difference))
                << int(e) << " gzip " << gzipped << ": " << difference;
        }
}

TEST(InterfaceConversion, AnUnknownNodesFieldsSurviveBothWays) {
    const std::string xml = R"(<X3D profile='Full' version='3.3'><Scene>
  <SomeoneElsesNode DEF='X' size='2'>
    <field name='speed' type='SFFloat' accessType='inputOutput' value='1.5'/>
    <field name='kick' type='SFTime' accessType='inputOnly'/>
    <field name='target' type='SFNode' accessType='initializeOnly'><Box size='1 2 3'/></field>
  </SomeoneElsesNode>
</Scene></X3D>)";
    auto a = read(xml, "a.x3d");
    ASSERT_TRUE(a);
    const std::string classic = writeScene(*a, Encoding::ClassicVrml);
    EXPECT_NE(classic.find("inputOutput SFFloat speed 1.5"), std::string::npos) << classic;
    EXPECT_NE(classic.find("initializeOnly SFNode target Box {"), std::string::npos) << classic;
    auto b = read(classic, "b.x3dv");
    ASSERT_TRUE(b);
    auto c = read(writeScene(*b, Encoding::Xml), "c.x3d");
    ASSERT_TRUE(c);
    EXPECT_EQ(writeScene(*c, Encoding::ClassicVrml), classic);
}

TEST(InterfaceConversion, NamesNoOtherEncodingCouldWriteAreRefusedWhereTheyStand) {
    auto errorOf = [](const std::string& text, const std::string& name) {
        ReadOptions options;
        options.compileFunctions = false;
        ReadResult r = readSceneBytes(text, name, options);
        for (const auto& d : r.diagnostics)
            if (d.severity == Severity::Error) return formatSceneDiagnostic(d);
        return std::string();
    };
    // An XML element name with a '.', a field name with '/', a field name XML reserves.
    EXPECT_NE(errorOf("<X3D profile='Full'><Scene><Ng.e/></Scene></X3D>", "a.x3d")
                  .find("a.x3d:1:28: error: 'Ng.e' is not a valid node type name"),
              std::string::npos);
    EXPECT_NE(errorOf("#X3D V3.3 utf8\nPROFILE Full\nGroup { res/lution 2 }\n", "b.x3dv")
                  .find("b.x3dv:3:9: error: 'res/lution' is not a valid field name"),
              std::string::npos);
    EXPECT_NE(
        errorOf("#X3D V3.3 utf8\nPROFILE Full\nFoo { inputOutput SFFloat xmlns 1 }\n", "c.x3dv")
            .find("'xmlns' is not a valid field name"),
        std::string::npos);
    // A control character: a scene file is text.
    EXPECT_NE(errorOf(std::string("#X3D V3.3 utf8\nPROFILE Full\nGroup {\x01}\n"), "d.x3dv")
                  .find("d.x3dv:3:8: error: the file holds the control character U+0001"),
              std::string::npos);
}

// Issue 27 §6 (Castle Game Engine's proto_tricky_is_clauses.x3dv): one field
// connected to two interface fields keeps both connections in every encoding,
// and nothing warns that the field "is given twice".
TEST(InterfaceConversion, AFieldConnectedToTwoInterfaceFieldsKeepsBoth) {
    const std::string classic = R"(#X3D V3.3 utf8
PROFILE Immersive
PROTO Tricky [
  inputOnly SFTime someEvent
  inputOnly SFTime someEvent3
  inputOutput SFVec3f where 0 0 0
  inputOutput SFVec3f there 1 1 1
] {
  Transform {
    translation IS where
    translation IS there
    children DEF S Script {
      inputOnly SFTime anotherEvent IS someEvent
      anotherEvent IS someEvent3
    }
  }
}
Tricky { }
)";
    ReadOptions options;
    options.compileFunctions = false;
    const ReadResult r = readSceneBytes(classic, "tricky.x3dv", options);
    ASSERT_TRUE(r.ok());
    for (const auto& d : r.diagnostics)
        EXPECT_EQ(d.message.find("given twice"), std::string::npos) << d.message;
    const Node* body = r.scene->protos.at(0)->body.at(0);
    EXPECT_EQ(body->field("translation")->isReferences,
              (std::vector<std::string>{"where", "there"}));
    const Node* script = body->field("children")->value.nodes.at(0);
    ASSERT_EQ(script->declarations.size(), 1u);
    EXPECT_EQ(script->declarations[0].isReferences,
              (std::vector<std::string>{"someEvent", "someEvent3"}));
    for (const Encoding e : {Encoding::Xml, Encoding::ClassicVrml}) {
        const std::string written = writeScene(*r.scene, e);
        const ReadResult back =
            readSceneBytes(written, e == Encoding::Xml ? "t.x3d" : "t.x3dv", options);
        ASSERT_TRUE(back.ok()) << written;
        for (const auto& d : back.diagnostics)
            EXPECT_EQ(d.message.find("given twice"), std::string::npos) << d.message;
        std::string difference;
        EXPECT_TRUE(sameModel(*r.scene, *back.scene, &difference)) << difference << "\n" << written;
    }
}
