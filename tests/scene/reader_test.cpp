// Behaviour of the scene readers that the corpus does not pin down: formula
// diagnostics at the scene file's line:column, PROTO expansion, USE before
// DEF, limits, gzip, and what the effects plan says.
#include "scene/effects_plan.h"
#include "scene/field_access.h"
#include "scene/gzip.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "scene/utf8.h"

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

using namespace fl::scene;

namespace {

ReadResult read(const std::string& text, const std::string& name = "test.x3dv") {
    return readSceneBytes(text, name);
}

const SceneDiagnostic* firstError(const ReadResult& r) {
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) return &d;
    return nullptr;
}

TEST(FormulaDiagnostics, ClassicPointsIntoTheDefinitionString) {
    const std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\n"
                             "FShape {\n"
                             "  geometry FGeometry { definition \"1 - sine(x)\" }\n"
                             "}\n";
    ReadResult r = read(text);
    ASSERT_FALSE(r.ok());
    const SceneDiagnostic* e = firstError(r);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->pos.line, 4);
    // `sine` starts at column 39 of line 4
    EXPECT_EQ(e->pos.column,
              static_cast<int>(std::string("  geometry FGeometry { definition \"1 - ").size()) + 1);
    EXPECT_NE(e->message.find("sine"), std::string::npos);
    EXPECT_NE(e->suggestion.find("sin"), std::string::npos);
}

TEST(FormulaDiagnostics, ClassicEscapesAndLaterLinesOfAnMFString) {
    const std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\n"
                             "FShape { geometry FGeometry { type \"parametric\" definition [\n"
                             "  \"x = u; // \\\"quoted\\\"\"\n"
                             "  \"y = v;\" \"z = foo;\" ] } }\n";
    ReadResult r = read(text);
    const SceneDiagnostic* e = firstError(r);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->pos.line, 5);
    EXPECT_EQ(e->pos.column, static_cast<int>(std::string("  \"y = v;\" \"z = ").size()) + 1);
}

TEST(FormulaDiagnostics, XmlAttributeWithEntities) {
    const std::string text =
        "<X3D profile='Immersive'><Scene>\n"
        "<FShape><FGeometry definition='\"(1 &lt; 2) ? x : bogus\"'/></FShape>\n"
        "</Scene></X3D>\n";
    ReadResult r = read(text, "test.x3d");
    const SceneDiagnostic* e = firstError(r);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->pos.line, 2);
    EXPECT_EQ(
        e->pos.column,
        static_cast<int>(std::string("<FShape><FGeometry definition='\"(1 &lt; 2) ? x : ").size()) +
            1);
}

TEST(FormulaDiagnostics, ErrorsInAProtoBodyAreReportedOnce) {
    const std::string text =
        "#X3D V3.3 utf8\nPROFILE Immersive\n"
        "PROTO S [] { FShape { geometry FGeometry { definition \"1 - q\" } } }\n"
        "S {} S {}\n";
    ReadResult r = read(text);
    int errors = 0;
    for (const auto& d : r.diagnostics)
        errors += d.severity == Severity::Error;
    EXPECT_EQ(errors, 1);
}

TEST(Proto, InstancesAreExpandedWithTheirFieldValues) {
    const std::string text =
        "#X3D V3.3 utf8\nPROFILE Immersive\n"
        "PROTO Ball [ initializeOnly SFFloat r 1 ] { Shape { geometry Sphere { radius IS r } } }\n"
        "Ball { r 2.5 } Ball {}\n";
    ReadResult r = read(text);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene->roots.size(), 2u);
    auto radiusOf = [](const Node* instance) {
        const Node* shape = instance->expansion.at(0);
        return numberField(*nodeField(*shape, "geometry"), "radius");
    };
    EXPECT_EQ(radiusOf(r.scene->roots[0]), 2.5);
    EXPECT_EQ(radiusOf(r.scene->roots[1]), 1.0);
}

TEST(Proto, SelfInstantiationIsStoppedWithAnError) {
    ReadResult r =
        read("#X3D V3.3 utf8\nPROFILE Immersive\nPROTO P [] { Group { children P {} } }\nP {}\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(firstError(r)->message.find("nest more than"), std::string::npos);
}

TEST(DefUse, UseBeforeDefIsResolvedWithAWarning) {
    ReadResult r =
        read("#X3D V3.3 utf8\nPROFILE Immersive\nGroup { children USE B }\nDEF B Shape {}\n");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(nodesField(*r.scene->roots[0], "children").at(0), r.scene->roots[1]);
    EXPECT_FALSE(r.diagnostics.empty());
}

TEST(Limits, DeepNestingIsALocatedError) {
    std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\n";
    for (int i = 0; i < 400; ++i)
        text += "Group { children ";
    ReadResult r = read(text);
    ASSERT_FALSE(r.ok());
    EXPECT_GT(firstError(r)->pos.line, 0);
    EXPECT_NE(firstError(r)->message.find("nested"), std::string::npos);
}

TEST(Limits, ExponentialProtoExpansionIsBounded) {
    // Each level doubles: 2^40 nodes if nothing stopped it.
    std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\nPROTO L0 [] { Group {} }\n";
    for (int i = 1; i <= 40; ++i)
        text += "PROTO L" + std::to_string(i) + " [] { Group { children [ L" +
                std::to_string(i - 1) + " {} L" + std::to_string(i - 1) + " {} ] } }\n";
    text += "L40 {}\n";
    ReadResult r = read(text);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(firstError(r)->message.find("PROTO"), std::string::npos);
}

TEST(Limits, GzipBombIsRefused) {
    ReadOptions options;
    options.limits.maxDecodedBytes = 1 << 20;
    std::string big = "#X3D V3.3 utf8\nPROFILE Immersive\n" + std::string(4 << 20, ' ');
    ReadResult r = readSceneBytes(gzip(big), "bomb.x3dv.gz", options);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics.at(0).message.find("unpacks"), std::string::npos);
}

TEST(Gzip, CompressedFilesReadLikePlainOnes) {
    const std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Box {} }\n";
    ReadResult plain = read(text);
    ReadResult packed = readSceneBytes(gzip(text), "box.x3dv.gz");
    ASSERT_TRUE(plain.ok() && packed.ok());
    EXPECT_TRUE(sameModel(*plain.scene, *packed.scene));
}

TEST(Garbage, NeverCrashesAndSaysWhere) {
    // Each input with the line:column its error must name and a word of why.
    const std::string zeros(400, '0');
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {std::string("\0\1\2", 3), "1:1", "control character"},
        {"#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry", "3:17", "end of the file"},
        {"<X3D profile='Full'><Scene><Shape>", "1:35", "malformed XML"},
        {"#VRML V2.0 utf8\n\"open", "2:1", "expected a node"},
        {"#X3D V3.3 utf8\nPROFILE Full\nTransform { translation 1e999 0 0 }", "3:25", "too large"},
        {"#X3D V3.3 utf8\nPROFILE Full\nTransform { translation 1" + zeros + " 0 0 }", "3:25",
         "too large"},
        {"<X3D profile='Full'><Scene><Transform translation='1" + zeros + " 0 0'/></Scene></X3D>",
         "1:52", "too large"},
    };
    for (const auto& [text, where, why] : cases) {
        ReadResult r = read(text);
        EXPECT_FALSE(r.ok());
        std::string first;
        for (const auto& d : r.diagnostics)
            if (d.severity == Severity::Error && first.empty()) first = formatSceneDiagnostic(d);
        EXPECT_NE(first.find(":" + where + ": error:"), std::string::npos)
            << "expected " << where << ", got: " << first;
        EXPECT_NE(first.find(why), std::string::npos) << "expected '" << why << "': " << first;
    }
}

TEST(Writer, NumbersReadBackExactly) {
    // 0.000…1 with 400 zeros underflows to zero: harmless, not an error.
    const std::string text = "#X3D V3.3 utf8\nPROFILE Immersive\n"
                             "Transform { translation 0.1 -0 1e-300 scale 3.0000000000000004 1 0." +
                             std::string(400, '0') + "1 }\n";
    ReadResult r = read(text);
    ASSERT_TRUE(r.ok());
    for (Encoding e : {Encoding::Xml, Encoding::ClassicVrml, Encoding::Vrml97}) {
        ReadResult back = readSceneBytes(writeScene(*r.scene, e), "back");
        ASSERT_TRUE(back.ok());
        std::string why;
        EXPECT_TRUE(sameModel(*r.scene, *back.scene, &why)) << why;
    }
}

TEST(Plan, TransformOnlyAnimationNeverNeedsRemeshing) {
    const std::string text =
        "#X3D V3.3 utf8\nPROFILE Immersive\n"
        "FTransform { rotationAngle \"2*pi*t\" timeBase \"local\" cycleInterval 60 loop TRUE\n"
        "  children FShape { geometry FGeometry { definition \"1 - x^2 - y^2 - z^2\" } } }\n";
    ReadResult r = read(text);
    ASSERT_TRUE(r.ok());
    EffectsPlan plan = makeEffectsPlan(*r.scene);
    EXPECT_EQ(plan.timeVarying, kTransform);
    EXPECT_TRUE(plan.usesWallClock);
    EXPECT_FALSE(plan.needsHaptics);
}

TEST(Plan, TimeDependentGeometryColourAndPhysics) {
    const std::string text =
        "#X3D V3.3 utf8\nPROFILE Immersive\n"
        "FShape { geometry FGeometry { definition \"1 - x^2 - (y - sin(pi*t))^2 - z^2\" }\n"
        "  appearance FAppearance { material FMaterial { definition [\"r = t;\" \"g = 1 - t;\" \"b "
        "= 0;\"] } }\n"
        "  physics FPhysics { density FDensity { definition \"0.5\" } } }\n";
    ReadResult r = read(text);
    ASSERT_TRUE(r.ok());
    EffectsPlan plan = makeEffectsPlan(*r.scene);
    EXPECT_EQ(plan.timeVarying, kGeometry | kColour);
    EXPECT_TRUE(plan.needsHaptics);
    ASSERT_EQ(plan.entries.size(), 1u);
    ASSERT_EQ(plan.entries[0].tangible.size(), 1u);
    EXPECT_EQ(plan.entries[0].tangible[0].kind, TangibleKind::Density);
    EXPECT_FALSE(plan.entries[0].tangible[0].timeVarying);
}

TEST(Plan, RoutedInterpolatorAnimatesATransform) {
    const std::string text =
        "#X3D V3.3 utf8\nPROFILE Immersive\n"
        "DEF T Transform { children Shape { geometry Box {} } }\n"
        "DEF C TimeSensor { loop TRUE }\n"
        "DEF O OrientationInterpolator { key [0 1] keyValue [0 1 0 0, 0 1 0 3.14] }\n"
        "ROUTE C.fraction_changed TO O.set_fraction\nROUTE O.value_changed TO T.set_rotation\n";
    ReadResult r = read(text);
    ASSERT_TRUE(r.ok());
    EffectsPlan plan = makeEffectsPlan(*r.scene);
    EXPECT_EQ(plan.timeVarying, kTransform);
    EXPECT_EQ(plan.functionShapes, 0u);
}

} // namespace

namespace {

// The diagnostics of a one-node scene, as "line:col: severity: message".
std::vector<std::string> checks(const std::string& body) {
    ReadResult r = read("#X3D V3.3 utf8\nPROFILE Immersive\n" + body);
    std::vector<std::string> out;
    for (const auto& d : r.diagnostics)
        out.push_back(std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + ": " +
                      std::string(fl::formula::severityName(d.severity)) + ": " + d.message);
    return out;
}

::testing::AssertionResult mentions(const std::vector<std::string>& all, const std::string& text) {
    std::string listed;
    for (const std::string& s : all) {
        if (s.find(text) != std::string::npos) return ::testing::AssertionSuccess();
        listed += "\n  " + s;
    }
    return ::testing::AssertionFailure() << "no '" << text << "' among:" << listed;
}

} // namespace

TEST(Checks, PhysicalPropertiesReadUvwAsWellAsXyz) {
    EXPECT_TRUE(checks("FShape { physics FPhysics { surface FSurface {\n"
                       "  friction FFriction { definition \"0.1 + 0.2*u*v\" }\n"
                       "  tension FTension { definition \"w\" } }\n"
                       "  density FDensity { definition \"x + u\" }\n"
                       "  force FForce { definition \"fx = u; fy = v; fz = w - z;\" } } }\n")
                    .empty());
}

TEST(Checks, GeometryModeAndLodValues) {
    auto all =
        checks("FShape { geometry FGeometry { definition \"1 - x*x - y*y - z*z\"\n"
               "  setOperations \"rfunction\" rfunctionAlpha -1 rfunctionM -2 lodRange 64 8 } }\n");
    EXPECT_TRUE(mentions(all, "4:29: error: rfunctionAlpha must lie in (-1, 1]"));
    EXPECT_TRUE(mentions(all, "error: rfunctionM"));
    EXPECT_TRUE(mentions(all, "error: lodRange"));
    all = checks("FShape { geometry FGeometry { type \"parametric\" collision \"function\"\n"
                 "  definition \"x = u; y = v; z = 0;\" } }\n");
    EXPECT_TRUE(mentions(all, "warning: collision 'function' needs a formula"));
    // Left at its default, "function" quietly means polygons: no warning.
    EXPECT_TRUE(checks("FShape { geometry FGeometry { type \"parametric\"\n"
                       "  definition \"x = u; y = v; z = 0;\" } }\n")
                    .empty());
}

TEST(Checks, MaterialTypeMustMatchWhatTheDefinitionGives) {
    auto all =
        checks("FShape { appearance FAppearance { material FMaterial { type \"explicit\"\n"
               "  key [0 1] keyValue [0 0 0, 1 1 1] definition \"r = x; g = y; b = z;\" } } }\n");
    EXPECT_TRUE(mentions(all, "error: an explicit FMaterial maps one value"));
    all = checks("FShape { appearance FAppearance { material FMaterial { type \"parametric\"\n"
                 "  definition \"x*x\" } } }\n");
    EXPECT_TRUE(mentions(all, "error: a parametric FMaterial assigns r"));
}

TEST(Checks, TransformOperationAndTiming) {
    auto all = checks("FTransform { operation \"blend\" }\n");
    EXPECT_TRUE(mentions(all, "3:14: error: FTransform operation 'blend' is not group"));
    all = checks("FTransform { operation \"formula\" }\n");
    EXPECT_TRUE(
        mentions(all, "error: operation 'formula' combines the children by operationDefinition"));
    all = checks("FTransform { operation \"morph\" }\n");
    EXPECT_TRUE(mentions(all, "warning: operation 'morph' without a morphFactor"));
    all = checks("FTransform { cycleInterval 0 timeBase \"gmt\" }\n");
    EXPECT_TRUE(mentions(all, "error: cycleInterval must be positive"));
    EXPECT_TRUE(mentions(all, "error: timeBase 'gmt' is not scene, local or utc"));
}

TEST(Checks, HintsForStringsWrittenTheOtherEncodingsWay) {
    // ClassicVRML: a single backslash escapes the next character and vanishes.
    auto all = checks(
        "FShape { geometry FGeometry { definition \"sphere(x,y,z,1) \\ box(x,y,z,1,1,1)\" } }\n");
    EXPECT_TRUE(mentions(all, "3:59: warning: a single \\ in a ClassicVRML string is dropped"));
    EXPECT_TRUE(checks("FShape { geometry FGeometry { definition \"sphere(x,y,z,1) \\\\ "
                       "box(x,y,z,1,1,1)\" } }\n")
                    .empty());
    // X3D XML: SFString attributes are written without quotes.
    ReadResult r = readSceneBytes("<X3D profile='Immersive'><Scene><FShape>\n"
                                  "<FGeometry type='\"explicit\"' definition='\"1 - x*x\"'/>\n"
                                  "</FShape></Scene></X3D>\n",
                                  "q.x3d");
    ASSERT_NE(firstError(r), nullptr);
    EXPECT_NE(firstError(r)->suggestion.find("drop the double quotes"), std::string::npos);
}

TEST(Utf8, ValidationFollowsRfc3629) {
    EXPECT_TRUE(isValidUtf8("plain ascii"));
    EXPECT_TRUE(isValidUtf8("\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80")); // é € 😀
    EXPECT_FALSE(isValidUtf8("\xC0\xAF"));                            // overlong '/'
    EXPECT_FALSE(isValidUtf8("\xED\xA0\x80"));                        // a surrogate
    EXPECT_FALSE(isValidUtf8("\xF4\x90\x80\x80"));                    // above U+10FFFF
    EXPECT_FALSE(isValidUtf8("\xE2\x82"));                            // cut short
    EXPECT_EQ(replaceInvalidUtf8("a\x83L\xC3\xA9"), "a\xEF\xBF\xBDL\xC3\xA9");
}

TEST(Utf8, ClassicStringsInAnotherEncodingAreRepairedWithAWarning) {
    ReadResult r =
        read("#VRML V2.0 utf8\nShape { geometry Text { string \"\x83L\x83\x83\" } }\n", "sjis.wrl");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].pos.line, 2);
    EXPECT_NE(r.diagnostics[0].message.find("not UTF-8"), std::string::npos);
    const Node* text = nodeField(*r.scene->roots[0], "geometry");
    ASSERT_NE(text, nullptr);
    EXPECT_TRUE(isValidUtf8(stringsField(*text, "string").at(0)));
}

TEST(Profiles, NodesOutsideTheProfileAndComponentsAreNamedWhereTheyStand) {
    // Xj3D's invalid_node_profile.x3dv and invalid_node_component.x3dv, with
    // their unrelated syntax slip (a DEF without a node type) mended: they
    // load, and say which node the declared profile does not include.
    auto warningsOf = [](const std::string& text) {
        ReadResult r = read(text);
        EXPECT_TRUE(r.ok());
        std::vector<std::string> out;
        for (const auto& d : r.diagnostics)
            if (d.message.find("is not part of profile") != std::string::npos)
                out.push_back(formatSceneDiagnostic(d));
        return out;
    };
    const std::string shape =
        "Shape { appearance Appearance { material DEF M Material { emissiveColor 0 0 1 } } "
        "geometry Sphere { radius 0.25 } }\n";
    const auto script = warningsOf("#X3D V3.0 utf8\nPROFILE Interchange\nScript {}\n" + shape);
    ASSERT_EQ(script.size(), 1u);
    EXPECT_NE(script[0].find("test.x3dv:3:1: warning: Script (Scripting:1) is not part of profile "
                             "Interchange (declare COMPONENT Scripting:1"),
              std::string::npos)
        << script[0];
    const std::string sensor = "Group { children [ VisibilitySensor {}\n" + shape + "] }\n";
    const auto level = warningsOf(
        "#X3D V3.0 utf8\nPROFILE Interchange\nCOMPONENT EnvironmentalSensor:1\n" + sensor);
    ASSERT_EQ(level.size(), 1u);
    EXPECT_NE(level[0].find("4:20: warning: VisibilitySensor (EnvironmentalSensor:2) is not part "
                            "of profile Interchange or the declared components"),
              std::string::npos)
        << level[0];
    // Declared, or in the profile: nothing to say.
    EXPECT_TRUE(
        warningsOf("#X3D V3.0 utf8\nPROFILE Interchange\nCOMPONENT EnvironmentalSensor:2\n" +
                   sensor)
            .empty());
    EXPECT_TRUE(warningsOf("#X3D V3.0 utf8\nPROFILE Immersive\nScript {}\n" + shape).empty());
    EXPECT_TRUE(warningsOf("#X3D V3.3 utf8\nPROFILE Full\nScript {}\nComposedShader {}\n").empty());
    // Once per node type, not per node.
    EXPECT_EQ(warningsOf("#X3D V3.0 utf8\nPROFILE Core\nScript {}\nScript {}\n").size(), 1u);
}
