// The animator: TimeSensors, interpolators and ROUTEs with X3D semantics,
// PROTO IS connections, event utilities, function-node timing, and the
// paper's animated examples driven by an injected clock.
#include "animation/animator.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

using namespace fl::animation;
using fl::scene::FieldType;
using fl::scene::FieldValue;
using fl::scene::Node;
using fl::scene::Scene;

namespace {

std::unique_ptr<Scene> load(const std::string& body) {
    auto r = fl::scene::readSceneBytes("#X3D V3.3 utf8\nPROFILE Full\n" + body, "anim.x3dv");
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << fl::scene::formatSceneDiagnostic(d);
    return std::move(r.scene);
}

std::unique_ptr<Scene> loadExample(const std::string& name) {
    auto r = fl::scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok());
    return std::move(r.scene);
}

const Node& byName(const Scene& scene, std::string_view def) {
    const Node* found = nullptr;
    scene.forEachNode([&](const Node& n) {
        if (n.defName == def && !n.inProtoBody && !found) found = &n;
    });
    if (!found) throw std::runtime_error("no node " + std::string(def));
    return *found;
}

// A moment `seconds` after 1970 on the wall clock, with the scene started at
// `sceneStart` seconds.
Instant at(double seconds, double sceneStart = 0, int offset = 0) {
    const std::int64_t utc = secondsToNanoseconds(seconds);
    return {utc - secondsToNanoseconds(sceneStart), utc, offset};
}

std::vector<double> numbers(const Animator& a, const Node& n, std::string_view field) {
    return a.value(n, field).numbers;
}

FieldValue timeValue(double seconds) {
    FieldValue v;
    v.type = FieldType::SFTime;
    v.numbers = {seconds};
    return v;
}

bool changed(const Animator& a, const Node& n, std::string_view field) {
    for (const FieldChange& c : a.changes())
        if (c.node == &n && c.field == field) return true;
    return false;
}

const std::string kMover = R"(
DEF T Transform { children Shape { geometry Box {} } }
DEF CLOCK TimeSensor { cycleInterval 4 loop TRUE }
DEF MOVE PositionInterpolator { key [0 1] keyValue [0 0 0, 4 0 0] }
ROUTE CLOCK.fraction_changed TO MOVE.set_fraction
ROUTE MOVE.value_changed TO T.set_translation
)";

} // namespace

TEST(Animator, TimeSensorDrivesAnInterpolatorDrivesATransform) {
    auto scene = load(kMover);
    Animator a(*scene);
    EXPECT_TRUE(a.diagnostics().empty());
    EXPECT_EQ(a.routeCount(), 2u);
    EXPECT_EQ(a.timeSensorCount(), 1u);
    const Node& t = byName(*scene, "T");
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{0, 0, 0})); // the file's value
    a.tick(at(1001)); // X3D times are UTC: 1001 s is a quarter into a 4 s cycle
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{1, 0, 0}));
    EXPECT_TRUE(changed(a, t, "translation"));
    EXPECT_EQ(numbers(a, byName(*scene, "CLOCK"), "isActive"), std::vector<double>{1});
    a.tick(at(1003));
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{3, 0, 0}));
    // The file's scene is untouched.
    EXPECT_EQ(fl::scene::numbersField(t, "translation"), (std::vector<double>{0, 0, 0}));
}

TEST(Animator, OneShotSensorStartedByAnEventRunsOneCycleAndStops) {
    auto scene = load(R"(
DEF T Transform {}
DEF CLOCK TimeSensor { cycleInterval 4 }
DEF MOVE PositionInterpolator { key [0 1] keyValue [0 0 0, 4 0 0] }
ROUTE CLOCK.fraction_changed TO MOVE.set_fraction
ROUTE MOVE.value_changed TO T.set_translation
)");
    Animator a(*scene);
    const Node& t = byName(*scene, "T");
    const Node& clock = byName(*scene, "CLOCK");
    a.tick(at(2000)); // its one cycle from startTime 0 was over in 1970: silent
    EXPECT_TRUE(a.changes().empty());
    ASSERT_TRUE(a.send(clock, "set_startTime", timeValue(2000), at(2000)));
    EXPECT_EQ(numbers(a, clock, "isActive"), std::vector<double>{1});
    a.tick(at(2001));
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{1, 0, 0}));
    // While active, a new startTime is ignored (X3D).
    a.send(clock, "set_startTime", timeValue(2001), at(2001));
    EXPECT_EQ(numbers(a, clock, "startTime"), std::vector<double>{2000});
    a.tick(at(2004.5)); // past the end: the final fraction is 1, then inactive
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{4, 0, 0}));
    EXPECT_EQ(numbers(a, clock, "isActive"), std::vector<double>{0});
    a.tick(at(2010));
    EXPECT_FALSE(changed(a, t, "translation"));
}

TEST(Animator, AWindowBetweenTwoTicksStillReachesItsEnd) {
    auto scene = load(R"(
DEF T Transform {}
DEF CLOCK TimeSensor { cycleInterval 0.2 startTime 2000.1 }
DEF MOVE PositionInterpolator { key [0 1] keyValue [0 0 0, 4 0 0] }
ROUTE CLOCK.fraction_changed TO MOVE.set_fraction
ROUTE MOVE.value_changed TO T.set_translation
)");
    Animator a(*scene);
    a.tick(at(2000));
    a.tick(at(2001)); // the 0.2 s window opened and closed in between
    EXPECT_EQ(numbers(a, byName(*scene, "T"), "translation"), (std::vector<double>{4, 0, 0}));
    EXPECT_EQ(numbers(a, byName(*scene, "CLOCK"), "isActive"), std::vector<double>{0});
}

TEST(Animator, StopTimePauseAndResume) {
    auto scene = load(R"(
DEF CLOCK TimeSensor { cycleInterval 10 loop TRUE startTime 100 pauseTime 102 resumeTime 0 }
)");
    Animator a(*scene);
    const Node& clock = byName(*scene, "CLOCK");
    a.tick(at(101));
    EXPECT_DOUBLE_EQ(numbers(a, clock, "fraction_changed")[0], 0.1);
    a.tick(at(103)); // paused at 102
    EXPECT_EQ(numbers(a, clock, "isPaused"), std::vector<double>{1});
    EXPECT_DOUBLE_EQ(numbers(a, clock, "fraction_changed")[0], 0.1);
    a.send(clock, "set_resumeTime", timeValue(105), at(104));
    a.tick(at(106)); // resumed at 106: 3 s paused (103..106) do not count
    EXPECT_EQ(numbers(a, clock, "isPaused"), std::vector<double>{0});
    EXPECT_NEAR(numbers(a, clock, "fraction_changed")[0], 0.3, 1e-12);
    a.send(clock, "set_stopTime", timeValue(107), at(106.5));
    a.tick(at(108));
    EXPECT_EQ(numbers(a, clock, "isActive"), std::vector<double>{0});
}

TEST(Animator, RouteLoopsFireEachRouteOncePerTimestamp) {
    auto scene = load(R"(
DEF CLOCK TimeSensor { loop TRUE }
DEF A ScalarInterpolator { key [0 1] keyValue [0 1] }
DEF B ScalarInterpolator { key [0 1] keyValue [1 0] }
ROUTE CLOCK.fraction_changed TO A.set_fraction
ROUTE A.value_changed TO B.set_fraction
ROUTE B.value_changed TO A.set_fraction
)");
    Animator a(*scene);
    a.tick(at(10.25));
    // A got 0.25 from the clock, B sent 0.75 back to A once, then the loop stopped.
    EXPECT_DOUBLE_EQ(numbers(a, byName(*scene, "A"), "value_changed")[0], 0.75);
    EXPECT_DOUBLE_EQ(numbers(a, byName(*scene, "B"), "value_changed")[0], 0.75);
    EXPECT_LT(a.eventsDelivered(), 10u);
}

TEST(Animator, EventsPassThroughProtoInterfaces) {
    auto scene = load(R"(
PROTO Mover [ inputOnly SFFloat set_fraction outputOnly SFVec3f position_changed ] {
  PositionInterpolator { key [0 1] keyValue [0 0 0, 0 2 0]
                         set_fraction IS set_fraction value_changed IS position_changed }
}
PROTO Spinner [ inputOutput SFTime cycle 2 outputOnly SFRotation turn ] {
  Group { children [
    DEF C TimeSensor { loop TRUE cycleInterval IS cycle }
    DEF O OrientationInterpolator { key [0 1] keyValue [0 1 0 0, 0 1 0 3] value_changed IS turn }
  ] }
  ROUTE C.fraction_changed TO O.set_fraction
}
DEF M Mover {}
DEF S Spinner { cycle 4 }
DEF T Transform {}
DEF CLOCK TimeSensor { loop TRUE cycleInterval 2 }
ROUTE CLOCK.fraction_changed TO M.set_fraction
ROUTE M.position_changed TO T.set_translation
ROUTE S.turn TO T.set_rotation
)");
    Animator a(*scene);
    EXPECT_EQ(a.timeSensorCount(), 2u); // the one in Spinner's expansion counts
    a.tick(at(1001));                   // CLOCK: 1 s of 2 -> 0.5; Spinner's: 1 of 4 -> 0.25
    const Node& t = byName(*scene, "T");
    EXPECT_EQ(numbers(a, t, "translation"), (std::vector<double>{0, 1, 0}));
    const std::vector<double> r = numbers(a, t, "rotation");
    ASSERT_EQ(r.size(), 4u);
    EXPECT_NEAR(r[3], 0.75, 1e-12);
}

TEST(Animator, EventUtilities) {
    auto scene = load(R"(
DEF F BooleanFilter {}
DEF TOGGLE BooleanToggle {}
DEF TRIGGER IntegerTrigger { integerKey 7 }
DEF WHEN TimeTrigger {}
DEF SEQ IntegerSequencer { key [0 0.5 1] keyValue [1 2 3] }
DEF SW Switch {}
ROUTE F.inputTrue TO TOGGLE.set_boolean
ROUTE F.inputNegate TO WHEN.set_boolean
ROUTE TOGGLE.toggle_changed TO TRIGGER.set_boolean
ROUTE TRIGGER.triggerValue TO SW.set_whichChoice
)");
    Animator a(*scene);
    FieldValue yes;
    yes.type = FieldType::SFBool;
    yes.numbers = {1};
    ASSERT_TRUE(a.send(byName(*scene, "F"), "set_boolean", yes, at(50)));
    EXPECT_EQ(numbers(a, byName(*scene, "TOGGLE"), "toggle"), std::vector<double>{1});
    EXPECT_EQ(numbers(a, byName(*scene, "SW"), "whichChoice"), std::vector<double>{7});
    EXPECT_EQ(numbers(a, byName(*scene, "WHEN"), "triggerTime"), std::vector<double>{50});
    const Node& seq = byName(*scene, "SEQ");
    a.send(seq, "next", yes, at(51));
    EXPECT_EQ(numbers(a, seq, "value_changed"), std::vector<double>{2});
    a.send(seq, "previous", yes, at(52));
    a.send(seq, "previous", yes, at(53)); // wraps round
    EXPECT_EQ(numbers(a, seq, "value_changed"), std::vector<double>{3});
}

TEST(Animator, ScriptsAreNeverRunAndUnknownFieldsAreRefused) {
    auto r = fl::scene::readSceneBytes(R"(#X3D V3.3 utf8
PROFILE Full
DEF CLOCK TimeSensor { loop TRUE }
DEF S Script { inputOnly SFFloat set_f outputOnly SFFloat out url "ecmascript: function set_f(v) { out = v; }" }
DEF T Transform {}
ROUTE CLOCK.fraction_changed TO S.set_f
)",
                                       "s.x3dv");
    ASSERT_TRUE(r.ok());
    Animator a(*r.scene);
    a.tick(at(3.5));
    EXPECT_TRUE(a.value(byName(*r.scene, "S"), "out").numbers.empty());
    EXPECT_FALSE(a.send(byName(*r.scene, "T"), "nonsense", timeValue(1), at(4)));
    EXPECT_FALSE(a.send(byName(*r.scene, "CLOCK"), "fraction_changed", timeValue(1), at(4)));
}

TEST(Animator, FunctionNodeTimeFollowsItsTimingFields) {
    auto scene = load(R"(
FShape { geometry DEF G FGeometry { definition "1 - x*x - y*y - z*z + 0*t"
                                    cycleInterval 2 loop TRUE timeSpan 0 10 } }
FShape { geometry DEF ONCE FGeometry { definition "t - x" cycleInterval 4 startTime 1 } }
)");
    Animator a(*scene);
    const Node& g = byName(*scene, "G");
    const Node& once = byName(*scene, "ONCE");
    EXPECT_EQ(a.time(g), 0);  // before the first tick: timeSpan[0]
    a.tick(at(1000.5, 1000)); // 0.5 s into the scene
    EXPECT_DOUBLE_EQ(a.time(g), 2.5);
    EXPECT_EQ(a.time(once), 0); // starts at scene second 1
    a.tick(at(1003, 1000));
    EXPECT_DOUBLE_EQ(a.time(g), 5);
    EXPECT_DOUBLE_EQ(a.time(once), 0.5);
    a.tick(at(1100, 1000));
    EXPECT_EQ(a.time(once), 1); // one cycle, then frozen at timeSpan[1]
    a.reset();
    EXPECT_EQ(a.time(g), 0);
}

TEST(Animator, WarnsWhenAUtcTimeIsRoutedIntoSceneTime) {
    auto scene = load(R"(
DEF TOUCH TouchSensor {}
FShape { geometry DEF G FGeometry { definition "t - x" } }
ROUTE TOUCH.touchTime TO G.set_startTime
)");
    Animator a(*scene);
    ASSERT_EQ(a.diagnostics().size(), 1u);
    const auto& d = a.diagnostics()[0];
    EXPECT_EQ(d.pos.line, 6); // the ROUTE
    EXPECT_NE(d.message.find("UTC"), std::string::npos);
    EXPECT_NE(d.suggestion.find("timeBase \"utc\""), std::string::npos);
}

TEST(Animator, WarnsAboutInterpolatorKeysItCannotUse) {
    auto scene = load("DEF BAD ScalarInterpolator { key [0 0.5 1] keyValue [1 2] }\n");
    Animator a(*scene);
    ASSERT_EQ(a.diagnostics().size(), 1u);
    EXPECT_NE(a.diagnostics()[0].message.find("2 values for 3 keys"), std::string::npos);
    EXPECT_EQ(a.diagnostics()[0].pos.line, 3);
}

TEST(AnimatedExamples, ClockHandsFollowLocalTime) {
    auto scene = loadExample("clock.x3d");
    Animator a(*scene);
    EXPECT_TRUE(a.diagnostics().empty());
    // 2026-11-22 09:30:15 local time in a UTC+1 zone.
    const double local = 20'414.0 * 86400 + 9 * 3600 + 30 * 60 + 15;
    a.tick(at(local - 3600, local - 3600 - 5, 3600));
    EXPECT_DOUBLE_EQ(a.time(byName(*scene, "SECOND_HAND")), 0.25);
    EXPECT_DOUBLE_EQ(a.time(byName(*scene, "MINUTE_HAND")), (30 * 60 + 15) / 3600.0);
    EXPECT_DOUBLE_EQ(a.time(byName(*scene, "HOUR_HAND")), (9 * 3600 + 30 * 60 + 15) / 43200.0);
}

TEST(AnimatedExamples, FanStartsWhenTouched) {
    auto scene = loadExample("fan.x3d");
    Animator a(*scene);
    EXPECT_TRUE(a.diagnostics().empty());
    const Node& rotor = byName(*scene, "ROTOR_XFORM");
    const Node& wind = byName(*scene, "WIND_FORCE");
    const double now = 1'795'000'000;
    a.tick(at(now, now));
    EXPECT_FALSE(changed(a, rotor, "rotation")); // off until touched
    FieldValue touch = timeValue(now + 1);
    // The viewer reports the click as the TouchSensor's output.
    ASSERT_TRUE(a.sensorOutput(byName(*scene, "SWITCH"), "touchTime", touch, at(now + 1, now)));
    a.tick(at(now + 1.25, now));
    EXPECT_TRUE(changed(a, rotor, "rotation"));
    EXPECT_DOUBLE_EQ(a.time(wind), 0.25); // the air flow turns with the blades
}

TEST(AnimatedExamples, SharkTailSwingsAndItsForceKeepsStep) {
    auto scene = loadExample("shark.x3d");
    Animator a(*scene);
    EXPECT_TRUE(a.diagnostics().empty());
    const double now = 1'795'000'001; // 1 s into a 5 s cycle
    a.tick(at(now, now - 10));
    EXPECT_TRUE(changed(a, byName(*scene, "TAIL"), "rotation"));
    EXPECT_DOUBLE_EQ(numbers(a, byName(*scene, "SWIM"), "fraction_changed")[0], 0.2);
    const Node* force = nullptr;
    scene->forEachNode([&](const Node& n) {
        if (n.type == "FForce" && !n.inProtoBody) force = &n;
    });
    ASSERT_NE(force, nullptr);
    EXPECT_DOUBLE_EQ(a.time(*force), 0.2);
}

TEST(Animator, RunsTheAnimationsOfInlinedScenes) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("functionlab-anim-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "part.x3dv") << "#X3D V3.3 utf8\nPROFILE Full\n" << kMover;
    std::ofstream(dir / "top.x3dv")
        << "#X3D V3.3 utf8\nPROFILE Full\nInline { url \"part.x3dv\" }\n";
    auto r = fl::scene::readSceneFile(dir / "top.x3dv");
    fs::remove_all(dir);
    ASSERT_TRUE(r.ok());
    Animator a(*r.scene);
    EXPECT_EQ(a.timeSensorCount(), 1u);
    a.tick(at(1001));
    const auto shown = fl::scene::scenesShownBy(*r.scene);
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_EQ(numbers(a, byName(*shown[1], "T"), "translation"), (std::vector<double>{1, 0, 0}));
}

// X3D 7.2.2 binding stacks: set_bind TRUE binds (the old top sends isBound
// FALSE), FALSE unbinds and binds the node below again; each kind has its
// own stack (a Viewpoint does not unbind a NavigationInfo); bindTime is the
// moment; isBound can be routed on.
TEST(Animator, BindingStacks) {
    auto scene = load(R"(
DEF A Viewpoint {}
DEF B OrthoViewpoint {}
DEF NAV NavigationInfo {}
DEF COPY BooleanFilter {}
ROUTE B.isBound TO COPY.set_boolean
)");
    Animator a(*scene);
    const Node &A = byName(*scene, "A"), &B = byName(*scene, "B"), &nav = byName(*scene, "NAV");
    FieldValue yes, no;
    yes.type = no.type = FieldType::SFBool;
    yes.numbers = {1};
    no.numbers = {0};
    EXPECT_FALSE(a.holdsEventValues(A));
    ASSERT_TRUE(a.send(A, "set_bind", yes, at(10)));
    ASSERT_TRUE(a.send(nav, "set_bind", yes, at(11)));
    ASSERT_TRUE(a.send(B, "set_bind", yes, at(12)));
    EXPECT_TRUE(a.holdsEventValues(A));
    EXPECT_EQ(numbers(a, A, "isBound"), std::vector<double>{0}) << "pushed down by B";
    EXPECT_EQ(numbers(a, B, "isBound"), std::vector<double>{1});
    EXPECT_EQ(numbers(a, B, "bindTime"), std::vector<double>{12});
    EXPECT_EQ(numbers(a, nav, "isBound"), std::vector<double>{1}) << "another stack";
    EXPECT_EQ(numbers(a, byName(*scene, "COPY"), "inputTrue"), std::vector<double>{1});
    ASSERT_TRUE(a.send(B, "set_bind", no, at(13)));
    EXPECT_EQ(numbers(a, B, "isBound"), std::vector<double>{0});
    EXPECT_EQ(numbers(a, A, "isBound"), std::vector<double>{1}) << "bound again";
    EXPECT_EQ(numbers(a, A, "bindTime"), std::vector<double>{13});
    // Unbinding a node that is not on top only takes it out of the stack.
    ASSERT_TRUE(a.send(nav, "set_bind", no, at(14)));
    EXPECT_EQ(numbers(a, nav, "isBound"), std::vector<double>{0});
    EXPECT_EQ(numbers(a, A, "isBound"), std::vector<double>{1});
}
