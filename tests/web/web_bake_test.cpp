// A function scene baked into standard X3D for a web page (issue 32 §1):
// levels of detail, time as frames, what passes through and what is left
// out, and the page's escaping of text from the scene.
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "web/web_bake.h"
#include "web/web_page.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>

using namespace fl;

namespace {

std::unique_ptr<scene::Scene> read(const std::string& body) {
    const std::string text = "<?xml version='1.0' encoding='UTF-8'?>\n"
                             "<X3D profile='Immersive' version='3.3'><head>"
                             "<component name='FunctionLab' level='1'/></head><Scene>\n" +
                             body + "\n</Scene></X3D>\n";
    auto r = scene::readSceneBytes(text, "bake.x3d");
    for (const auto& d : r.diagnostics)
        if (d.severity == scene::Severity::Error) ADD_FAILURE() << scene::formatSceneDiagnostic(d);
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

const std::string kBall = "<FShape><FGeometry type='implicit' definition='1 - x^2 - y^2 - z^2' "
                          "domainMin='-1.2 -1.2 -1.2' domainMax='1.2 1.2 1.2'/></FShape>";

// Every node of the baked scene, once, in the order written.
void forEach(const scene::Scene& s, const std::function<void(const scene::Node&)>& f) {
    std::set<const scene::Node*> seen;
    std::function<void(const scene::Node*)> walk = [&](const scene::Node* n) {
        if (!n || !seen.insert(n).second) return;
        f(*n);
        for (const scene::Field& field : n->fields)
            for (const scene::Node* c : field.value.nodes)
                walk(c);
    };
    for (const scene::Node* r : s.roots)
        walk(r);
}

std::size_t count(const scene::Scene& s, std::string_view type) {
    std::size_t n = 0;
    forEach(s, [&](const scene::Node& node) { n += node.type == type; });
    return n;
}

const scene::Node* find(const scene::Scene& s, std::string_view type) {
    const scene::Node* found = nullptr;
    forEach(s, [&](const scene::Node& node) {
        if (!found && node.type == type) found = &node;
    });
    return found;
}

web::BakeOptions small() {
    web::BakeOptions o;
    o.resolutions = {8, 16};
    o.frames = 4;
    o.threads = 1;
    return o;
}

bool mentions(const std::vector<std::string>& warnings, std::string_view text) {
    for (const std::string& w : warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

} // namespace

TEST(WebBake, AStaticShapeBecomesAnLodOfEachResolutionWhereItStood) {
    auto s = read("<Transform DEF='PLACE' translation='3 0 0'><FShape DEF='BALL'>"
                  "<FGeometry type='implicit' definition='1 - x^2 - y^2 - z^2' "
                  "domainMin='-1.2 -1.2 -1.2' domainMax='1.2 1.2 1.2'/></FShape></Transform>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(b.roots, 1u);
    EXPECT_EQ(b.animated, 0u);
    EXPECT_TRUE(b.clocks.empty());
    forEach(b.scene, [](const scene::Node& n) {
        ASSERT_NE(n.spec, nullptr) << n.type;
        EXPECT_NE(n.spec->component, "FunctionLab") << n.type;
    });
    const scene::Node* place = b.scene.roots.at(0);
    ASSERT_EQ(place->defName, "PLACE");
    const scene::Node* ball = place->field("children")->value.nodes.at(0);
    EXPECT_EQ(ball->type, "Group");
    EXPECT_EQ(ball->defName, "BALL");
    const scene::Node* lod = ball->field("children")->value.nodes.at(0);
    ASSERT_EQ(lod->type, "LOD");
    ASSERT_EQ(lod->field("children")->value.nodes.size(), 2u);
    ASSERT_EQ(lod->field("range")->value.numbers.size(), 1u);
    EXPECT_GT(lod->field("range")->value.numbers[0], 0);
    // Meshed in the Transform's frame: the ball's centre is at its origin.
    for (double c : lod->field("center")->value.numbers)
        EXPECT_NEAR(c, 0, 0.05);
    // The finer level first, with more triangles.
    const auto faces = [&](std::size_t level) {
        const scene::Node* shape = lod->field("children")->value.nodes.at(level);
        return shape->field("geometry")
            ->value.nodes.at(0)
            ->field("coordIndex")
            ->value.numbers.size();
    };
    EXPECT_GT(faces(0), faces(1));
}

TEST(WebBake, AShapeThatChangesWithTimeBecomesFramesASequencerFlips) {
    auto s = read("<FShape DEF='PULSE'><FGeometry type='implicit' "
                  "definition='(0.5 + 0.4*t)^2 - x^2 - y^2 - z^2' cycleInterval='2' loop='true' "
                  "domainMin='-1 -1 -1' domainMax='1 1 1'/></FShape>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(b.animated, 1u);
    ASSERT_EQ(b.clocks.size(), 1u);
    EXPECT_EQ(b.clocks[0].cycleSeconds, 2);
    EXPECT_TRUE(b.clocks[0].loop);
    EXPECT_EQ(b.clocks[0].base, web::ClockBase::Scene);
    const scene::Node* sensor = find(b.scene, "TimeSensor");
    ASSERT_NE(sensor, nullptr);
    EXPECT_EQ(sensor->defName, b.clocks[0].timeSensor);
    EXPECT_EQ(sensor->field("cycleInterval")->value.numbers.at(0), 2);
    const scene::Node* sequencer = find(b.scene, "IntegerSequencer");
    ASSERT_NE(sequencer, nullptr);
    EXPECT_EQ(sequencer->field("key")->value.numbers, (std::vector<double>{0, 0.25, 0.5, 0.75}));
    EXPECT_EQ(sequencer->field("keyValue")->value.numbers, (std::vector<double>{0, 1, 2, 3}));
    const scene::Node* frames = find(b.scene, "Switch");
    ASSERT_NE(frames, nullptr);
    ASSERT_EQ(frames->field("children")->value.nodes.size(), 4u);
    ASSERT_EQ(b.scene.routes.size(), 2u);
    EXPECT_EQ(b.scene.routes[0].fromField, "fraction_changed");
    EXPECT_EQ(b.scene.routes[1].toNode, frames);
    // The ball grows from frame to frame: its first level's box widens.
    const auto radius = [&](std::size_t frame) {
        const scene::Node* group = frames->field("children")->value.nodes.at(frame);
        const scene::Node* lod = group->field("children")->value.nodes.at(0);
        const scene::Node* shape = lod->field("children")->value.nodes.at(0);
        const auto& points = shape->field("geometry")
                                 ->value.nodes.at(0)
                                 ->field("coord")
                                 ->value.nodes.at(0)
                                 ->field("point")
                                 ->value.numbers;
        double r = 0;
        for (std::size_t i = 0; i < points.size(); i += 3)
            r = std::max(r, points[i]);
        return r;
    };
    EXPECT_LT(radius(0), radius(2) - 0.1);
    // The sequencer needs its component beyond the profile.
    bool eventUtilities = false;
    for (const auto& c : b.scene.components)
        eventUtilities = eventUtilities || c.name == "EventUtilities";
    EXPECT_TRUE(eventUtilities);
}

TEST(WebBake, StandardNodesRoutesAndViewpointsPassThrough) {
    auto s = read("<Viewpoint DEF='VIEW' description='Front' position='0 0 5'/>"
                  "<TimeSensor DEF='T' cycleInterval='3' loop='true'/>"
                  "<PositionInterpolator DEF='P' key='0 1' keyValue='0 0 0 1 0 0'/>"
                  "<Transform DEF='MOVER'><Shape><Box size='1 2 3'/></Shape>" +
                  kBall +
                  "</Transform>"
                  "<ROUTE fromNode='T' fromField='fraction_changed' toNode='P' "
                  "toField='set_fraction'/>"
                  "<ROUTE fromNode='P' fromField='value_changed' toNode='MOVER' "
                  "toField='set_translation'/>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(count(b.scene, "Viewpoint"), 1u);
    EXPECT_EQ(count(b.scene, "Box"), 1u);
    EXPECT_EQ(count(b.scene, "PositionInterpolator"), 1u);
    ASSERT_EQ(b.scene.routes.size(), 2u);
    EXPECT_EQ(b.scene.routes[1].toNode->defName, "MOVER");
    EXPECT_EQ(b.scene.routes[1].toField, "set_translation");
    // The ball stays static under an animated Transform: the browser moves it.
    EXPECT_EQ(b.animated, 0u);
    EXPECT_EQ(b.roots, 1u);
    EXPECT_TRUE(b.warnings.empty()) << b.warnings.front();
}

TEST(WebBake, ScriptsAndUrlsOutsideTheFolderAreLeftOutWithAWarning) {
    auto s = read("<Script DEF='S'><![CDATA[ecmascript: function initialize() {}]]></Script>"
                  "<Shape><Appearance><ImageTexture url='\"http://example.com/x.png\" "
                  "\"javascript:alert(1)\"'/></Appearance><Box/></Shape>"
                  "<Anchor url='\"#VIEW\" \"javascript:alert(2)\"'><Shape><Box/></Shape></Anchor>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(count(b.scene, "Script"), 0u);
    EXPECT_TRUE(mentions(b.warnings, "Script node is left out"));
    const scene::Node* texture = find(b.scene, "ImageTexture");
    ASSERT_NE(texture, nullptr);
    EXPECT_TRUE(texture->field("url")->value.strings.empty());
    EXPECT_TRUE(mentions(b.warnings, "http://example.com/x.png"));
    EXPECT_TRUE(mentions(b.warnings, "javascript:alert(1)"));
    const scene::Node* anchor = find(b.scene, "Anchor");
    ASSERT_NE(anchor, nullptr);
    EXPECT_EQ(anchor->field("url")->value.strings, (std::vector<std::string>{"#VIEW"}));
}

TEST(WebBake, ARouteIntoAFunctionNodeIsDroppedAndSaid) {
    auto s = read("<TimeSensor DEF='T' loop='true'/>"
                  "<FTransform DEF='SPIN' rotationAngle='t'>" +
                  kBall +
                  "</FTransform>"
                  "<ROUTE fromNode='T' fromField='cycleTime' toNode='SPIN' "
                  "toField='set_startTime'/>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_TRUE(mentions(b.warnings, "1 ROUTE(s)"));
    for (const scene::Route& r : b.scene.routes)
        EXPECT_NE(r.toField, "set_startTime");
}

TEST(WebBake, AShapeUsedTwiceIsBakedOnceAndUsedTwice) {
    auto s = read("<Transform translation='-2 0 0'><FShape DEF='BALL'>"
                  "<FGeometry type='implicit' definition='1 - x^2 - y^2 - z^2' "
                  "domainMin='-1.2 -1.2 -1.2' domainMax='1.2 1.2 1.2'/></FShape></Transform>"
                  "<Transform translation='2 0 0'><FShape USE='BALL'/></Transform>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    const auto& a = b.scene.roots.at(0)->field("children")->value.nodes;
    const auto& c = b.scene.roots.at(1)->field("children")->value.nodes;
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(a[0], c[0]);
    EXPECT_EQ(count(b.scene, "LOD"), 1u);
    const std::string text = scene::writeScene(b.scene, scene::Encoding::Xml);
    EXPECT_NE(text.find("USE='BALL'"), std::string::npos);
}

TEST(WebBake, AFlatShapeKeepsItsLevels) {
    // The clock's face: a disc with a box of no depth.
    auto s = read("<FShape DEF='FACE'><FGeometry type='parametric' "
                  "definition='x = u*cos(v); y = u*sin(v); z = 0;' uRange='0 1' "
                  "vRange='0 6.2832'/></FShape>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(count(b.scene, "LOD"), 1u);
    EXPECT_EQ(count(b.scene, "IndexedFaceSet"), 2u);
}

TEST(WebBake, TheBakedSceneReadsBackWithoutADiagnostic) {
    auto s = read("<FShape DEF='PULSE'><FGeometry type='implicit' "
                  "definition='(0.5 + 0.4*t)^2 - x^2 - y^2 - z^2' cycleInterval='2' "
                  "domainMin='-1 -1 -1' domainMax='1 1 1'/></FShape>" +
                  kBall);
    const web::BakeResult b = web::bakeForWeb(*s, small());
    const std::string text = scene::writeScene(b.scene, scene::Encoding::Xml);
    auto back = scene::readSceneBytes(text, "baked.x3d");
    ASSERT_TRUE(back.ok());
    for (const auto& d : back.diagnostics)
        ADD_FAILURE() << scene::formatSceneDiagnostic(d);
}

TEST(WebBake, LodRangesGrowWithCoarserLevels) {
    const field::Box3 box{{-1, -1, -1}, {1, 1, 1}};
    const auto r = web::lodRanges({64, 32, 16}, box);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_GT(r[0], 0);
    EXPECT_NEAR(r[1] / r[0], 2, 1e-9); // halving the resolution doubles the distance
    EXPECT_TRUE(web::lodRanges({32}, box).empty());
}

TEST(WebPage, TextFromTheSceneIsEscapedForScriptsAndHtml) {
    EXPECT_EQ(web::javaScriptString("a\"b\\c\nd</script>\x01"),
              "\"a\\\"b\\\\c\\nd\\u003c/script\\u003e\\u0001\"");
    EXPECT_EQ(web::javaScriptString("\xe2\x80\xa8"), "\"\\u2028\"");
    const std::string shown = web::htmlText("<b onclick='x'>&\x1b[2J");
    EXPECT_EQ(shown.find_first_of("<>'\x1b"), std::string::npos) << shown;
    EXPECT_NE(shown.find("&lt;b onclick="), std::string::npos) << shown;
    EXPECT_NE(shown.find("&amp;[2J"), std::string::npos) << shown;
}

TEST(WebPage, AHostileTitleIsShownNotObeyed) {
    std::string why;
    const auto xIte = web::findXite(why);
    if (!xIte) GTEST_SKIP() << why;
    auto s = read("<Shape><Box/></Shape>");
    s->meta.emplace_back("title", "<script>alert(1)</script>\x1b[2J");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("functionlab-web-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::remove_all(dir);
    web::PageOptions options;
    options.xIteDir = *xIte;
    web::PageResult written;
    ASSERT_TRUE(web::writeWebFolder(b, *s, dir, options, written, why)) << why;
    std::ifstream in(dir / "index.html");
    std::stringstream html;
    html << in.rdbuf();
    EXPECT_EQ(html.str().find("<script>alert"), std::string::npos);
    EXPECT_NE(html.str().find("&lt;script&gt;alert(1)&lt;/script&gt;[2J"), std::string::npos);
    for (const char* file : {"scene.x3d", "scene.js", "viewer/x_ite.min.js",
                             "viewer/functionlab-page.js", "viewer/x_ite_css.js"})
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
    std::filesystem::remove_all(dir);
}

TEST(WebBake, APageTooLargeToOpenIsRefusedWithWhatToLower) {
    auto s = read("<FShape><FGeometry type='implicit' definition='(0.5 + 0.4*t)^2 - x^2 - y^2 - "
                  "z^2' cycleInterval='2' domainMin='-1 -1 -1' domainMax='1 1 1'/></FShape>");
    web::BakeOptions o = small();
    o.frames = 200;
    o.maxTriangles = 20'000;
    const web::BakeResult b = web::bakeForWeb(*s, o);
    EXPECT_TRUE(b.cancelled);
    EXPECT_NE(b.error.find("--frames"), std::string::npos) << b.error;
    // It stopped soon after the budget, not after 200 frames.
    EXPECT_LT(b.triangles, 40'000u);
}

TEST(WebBake, ACycleNoPageCanPlayIsShownStillAndSaid) {
    auto s = read("<FShape><FGeometry type='implicit' definition='(0.5 + 0.4*t)^2 - x^2 - y^2 - "
                  "z^2' cycleInterval='1e300' domainMin='-1 -1 -1' domainMax='1 1 1'/></FShape>");
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(b.animated, 0u);
    EXPECT_EQ(b.roots, 1u);
    EXPECT_TRUE(mentions(b.warnings, "cannot be played as frames"));
}

TEST(WebPage, ImagesTravelInsideThePagesCopyOfTheScene) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("functionlab-web-images-" +
                      std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir / "pictures");
    {
        std::ofstream png(dir / "pictures" / "wood.png", std::ios::binary);
        png << "\x89PNG\r\n\x1a\n not really an image";
    }
    {
        std::ofstream scene(dir / "scene.x3d");
        scene << "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Immersive' "
                 "version='3.3'><Scene><Shape><Appearance><ImageTexture "
                 "url='\"pictures/wood.png\"'/></Appearance><Box/></Shape></Scene></X3D>\n";
    }
    auto r = scene::readSceneFile(dir / "scene.x3d");
    ASSERT_TRUE(r.ok());
    const web::BakeResult b = web::bakeForWeb(*r.scene, small());
    ASSERT_EQ(b.files.size(), 1u);
    EXPECT_EQ(b.files[0].target, "files/pictures/wood.png");
    const std::string x3d = scene::writeScene(b.scene, scene::Encoding::Xml);
    EXPECT_NE(x3d.find("files/pictures/wood.png"), std::string::npos);
    const std::string inside = web::withImagesInside(x3d, b);
    EXPECT_EQ(inside.find("files/pictures/wood.png"), std::string::npos);
    EXPECT_NE(inside.find("data:image/png;base64,iVBORw0K"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(WebBake, AUseDagThatExplodesAsATreeIsBakedInLinearWork) {
    // Each Group holds the one before it twice: 2^40 paths through 40 nodes.
    std::string body = "<Group DEF='G0'>" + kBall + "</Group>";
    for (int i = 1; i <= 40; ++i)
        body = "<Group DEF='G" + std::to_string(i) + "'>" + body + "<Group USE='G" +
               std::to_string(i - 1) + "'/></Group>";
    auto s = read(body);
    const web::BakeResult b = web::bakeForWeb(*s, small());
    EXPECT_EQ(b.roots, 1u);                  // the ball, baked once and USEd
    EXPECT_EQ(count(b.scene, "Group"), 42u); // 41 Groups and the ball's
    const std::string text = scene::writeScene(b.scene, scene::Encoding::Xml);
    EXPECT_LT(text.size(), 2'000'000u);
}

TEST(WebBake, ASceneThatLoopsNeverReachesTheBaker) {
    auto r = scene::readSceneBytes(
        "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Immersive' version='3.3'>"
        "<Scene><Group DEF='A'><Transform><Group USE='A'/></Transform></Group></Scene></X3D>\n",
        "loop.x3d");
    ASSERT_FALSE(r.ok() && r.diagnostics.empty());
    bool located = false;
    for (const auto& d : r.diagnostics)
        located = located || scene::formatSceneDiagnostic(d).find("loop.x3d:") == 0;
    EXPECT_TRUE(located);
    if (r.ok()) { // kept with the loop cut: the baker still ends
        const web::BakeResult b = web::bakeForWeb(*r.scene, small());
        EXPECT_FALSE(b.cancelled);
    }
}
