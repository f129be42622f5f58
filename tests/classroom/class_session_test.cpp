// The class's rules with no sockets: joins, edits under the lock, fencing,
// checks, chat and its commands, roles, freeze, the rate limit, leases and
// resuming a seat — on a ManualClock.
#include "classroom/class_session.h"
#include "classroom/starter_scene.h"

#include "scenes.h"
#include "session_harness.h"

#include <QJsonArray>

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

using test::chatFrame;
using test::classScene;
using test::editFrame;

class ClassSessionTest : public ::testing::Test {
  protected:
    ClassConfig config() {
        ClassConfig c;
        c.classCode = "C1";
        c.instructorKey = "secret";
        c.initialScene = classScene("sphere(0, 0, 0, 1)");
        return c;
    }
    ManualClock clock{1'000'000};
    ClassSession session{config(), clock, nullptr};
    test::Harness h{session};
};

TEST_F(ClassSessionTest, JoinIsWelcomedWithTheScene) {
    const ConnectionId ana = h.join("Ana");
    const QJsonObject w = h.last(ana, "welcome");
    ASSERT_FALSE(w.isEmpty());
    EXPECT_EQ(w["version"].toInt(), 1);
    EXPECT_EQ(w["scene"].toString().toStdString(), classScene("sphere(0, 0, 0, 1)"));
    EXPECT_EQ(w["role"].toString(), "student");
    EXPECT_FALSE(w["token"].toString().isEmpty());
    EXPECT_EQ(h.last(ana, "presence")["members"].toArray().size(), 1);
}

TEST_F(ClassSessionTest, WrongClassCodeIsAnError) {
    const ConnectionId c = h.connect();
    h.send(c, R"({"type":"join","class":"NOPE","name":"Eve"})");
    EXPECT_EQ(h.last(c, "error")["code"].toString(), "wrong-class");
    EXPECT_TRUE(h.last(c, "welcome").isEmpty());
    h.send(c, editFrame(1, classScene("sphere(1)")));
    EXPECT_EQ(h.last(c, "error")["code"].toString(), "not-joined");
}

TEST_F(ClassSessionTest, InstructorNeedsTheKey) {
    const ConnectionId bad = h.join("Prof", "instructor", R"(,"key":"guess")");
    EXPECT_EQ(h.last(bad, "error")["code"].toString(), "bad-key");
    const ConnectionId good = h.join("Prof", "instructor", R"(,"key":"secret")");
    EXPECT_EQ(h.last(good, "welcome")["role"].toString(), "instructor");
}

TEST_F(ClassSessionTest, FailedJoinsAreThrottledPerAddress) {
    ConnectionId c = 0;
    for (int i = 0; i < 15; ++i) {
        c = h.connect("10.1.1.1");
        h.send(c, R"({"type":"join","class":"X","name":"Eve"})");
        h.drop(c); // a window told the code is wrong closes
    }
    // Further wrong codes from that address are cut short ...
    c = h.connect("10.1.1.1");
    h.send(c, R"({"type":"join","class":"X","name":"Eve"})");
    EXPECT_EQ(h.last(c, "error")["code"].toString(), "too-many-joins");
    EXPECT_TRUE(h.closed(c));
    // ... but the right code from behind the same address still gets in
    // (a NAT or a TLS proxy is a whole class at one address).
    c = h.connect("10.1.1.1");
    h.send(c, R"({"type":"join","class":"C1","name":"Eve"})");
    EXPECT_FALSE(h.last(c, "welcome").isEmpty());
}

TEST_F(ClassSessionTest, AnEditReachesEveryone) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    const std::string next = classScene("sphere(0, 0, 0, 1.5)");
    h.send(ana, editFrame(1, next));
    for (ConnectionId c : {ana, bo}) {
        const QJsonObject s = h.last(c, "scene");
        EXPECT_EQ(s["version"].toInt(), 2);
        EXPECT_EQ(s["author"].toString(), "Ana");
        EXPECT_EQ(s["scene"].toString().toStdString(), next);
        EXPECT_EQ(h.last(c, "lock")["holder"].toObject()["name"].toString(), "Ana");
    }
    EXPECT_EQ(session.version(), 2);
}

TEST_F(ClassSessionTest, AnEditUnderAnothersLockIsRefusedWithTheHolder) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(0, 0, 0, 1.5)")));
    h.send(bo, editFrame(2, classScene("sphere(0, 0, 0, 3)")));
    const QJsonObject r = h.last(bo, "refused");
    EXPECT_EQ(r["reason"].toString(), "locked");
    EXPECT_EQ(r["holder"].toString(), "Ana");
    EXPECT_EQ(h.count(ana, "refused"), 0);
    EXPECT_EQ(h.count(ana, "scene"), 1); // the refused edit went to nobody
    EXPECT_EQ(session.version(), 2);
    // Released: Bo's edit goes through.
    h.send(ana, R"({"type":"release"})");
    EXPECT_TRUE(h.last(bo, "lock")["holder"].isNull());
    h.send(bo, editFrame(2, classScene("sphere(0, 0, 0, 3)")));
    EXPECT_EQ(h.last(ana, "scene")["author"].toString(), "Bo");
}

TEST_F(ClassSessionTest, AnEditOnAnOldVersionIsStale) {
    const ConnectionId ana = h.join("Ana");
    h.send(ana, editFrame(1, classScene("sphere(0, 0, 0, 1.5)")));
    h.send(ana, editFrame(1, classScene("sphere(0, 0, 0, 2)")));
    const QJsonObject r = h.last(ana, "refused");
    EXPECT_EQ(r["reason"].toString(), "stale");
    EXPECT_EQ(r["version"].toInt(), 2);
}

TEST_F(ClassSessionTest, AnInvalidSceneIsRefusedWithLocatedDiagnostics) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(0, 0, 0, 1) + sine(x)")));
    const QJsonObject r = h.last(ana, "refused");
    EXPECT_EQ(r["reason"].toString(), "invalid");
    const QJsonArray d = r["diagnostics"].toArray();
    ASSERT_FALSE(d.isEmpty());
    EXPECT_EQ(d[0].toObject()["line"].toInt(), 4);
    EXPECT_GT(d[0].toObject()["column"].toInt(), 0);
    EXPECT_TRUE(r["message"].toString().startsWith("scene:4:"));
    EXPECT_EQ(h.count(bo, "scene"), 0);
    // A refused edit takes no lock.
    EXPECT_TRUE(h.last(bo, "lock").isEmpty());
}

TEST_F(ClassSessionTest, TooLargeSceneIsRefused) {
    const ConnectionId ana = h.join("Ana");
    h.send(ana, editFrame(1, std::string(300 * 1024, ' ')));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "too-large");
}

TEST_F(ClassSessionTest, MalformedMessagesGetAnErrorAndTheConnectionGoesOn) {
    const ConnectionId ana = h.join("Ana");
    h.send(ana, "{oops");
    EXPECT_EQ(h.last(ana, "error")["code"].toString(), "malformed");
    EXPECT_FALSE(h.closed(ana));
    h.send(ana, chatFrame("still here"));
    EXPECT_EQ(h.last(ana, "chat")["text"].toString(), "still here");
}

TEST_F(ClassSessionTest, ChatGoesToEveryoneAndCommandsNever) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, chatFrame("hello"));
    EXPECT_EQ(h.last(bo, "chat")["from"].toString(), "Ana");
    EXPECT_EQ(h.last(bo, "chat")["text"].toString(), "hello");
    h.send(ana, chatFrame("/add sphere(1, 0, 0, 0.5) difference"));
    EXPECT_EQ(h.count(bo, "chat"), 1);
    const QJsonObject s = h.last(bo, "scene");
    EXPECT_EQ(s["version"].toInt(), 2);
    EXPECT_EQ(s["kind"].toString(), "command");
    EXPECT_TRUE(s["scene"].toString().contains("sphere(1, 0, 0, 0.5)"));
}

TEST_F(ClassSessionTest, CommandsAreRefusedToTheSenderOnly) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, chatFrame("/fly away"));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "invalid");
    EXPECT_EQ(h.last(ana, "refused")["command"].toString(), "/fly away");
    h.send(ana, chatFrame("/add sphere(0, 0"));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "invalid");
    const QJsonArray where = h.last(ana, "refused")["diagnostics"].toArray();
    ASSERT_FALSE(where.isEmpty());
    // Located in what Ana typed (line 1 of the command), not in the scene.
    EXPECT_EQ(where.at(0).toObject()["line"].toInt(), 1);
    EXPECT_LE(where.at(0).toObject()["column"].toInt(), 17);
    EXPECT_TRUE(h.last(ana, "refused")["message"].toString().startsWith("column "));
    // Under Bo's lock a command is refused like an edit.
    h.send(bo, editFrame(1, classScene("sphere(0, 0, 0, 2)")));
    h.send(ana, chatFrame("/add box(1, 1, 1)"));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "locked");
    EXPECT_EQ(h.count(bo, "chat"), 0);
    EXPECT_EQ(h.count(bo, "refused"), 0);
}

TEST_F(ClassSessionTest, HelpAnswersOnlyTheAsker) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, chatFrame("/help"));
    EXPECT_TRUE(h.last(ana, "notice")["text"].toString().contains("/add"));
    EXPECT_EQ(h.count(bo, "notice"), 0);
}

TEST_F(ClassSessionTest, UndoTakesBackOnesOwnLastCommand) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    const std::string before = session.scene();
    h.send(ana, chatFrame("/add box(0.5, 0.5, 0.5) difference"));
    EXPECT_EQ(session.version(), 2);
    h.send(bo, chatFrame("/undo"));
    EXPECT_EQ(h.last(bo, "refused")["reason"].toString(), "invalid"); // Bo has no command
    h.send(ana, chatFrame("/undo"));
    EXPECT_EQ(session.version(), 3);
    EXPECT_EQ(session.scene(), before);
    EXPECT_EQ(h.last(bo, "scene")["kind"].toString(), "undo");
    h.send(ana, chatFrame("/undo"));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "invalid");
}

TEST_F(ClassSessionTest, UndoAfterAnotherChangeIsStale) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, chatFrame("/add box(0.5, 0.5, 0.5)"));
    h.send(ana, R"({"type":"release"})");
    h.send(bo, editFrame(2, classScene("sphere(0, 0, 0, 2)")));
    h.send(bo, R"({"type":"release"})");
    h.send(ana, chatFrame("/undo"));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "stale");
    EXPECT_EQ(session.version(), 3);
}

TEST_F(ClassSessionTest, ObserversAreReadOnly) {
    const ConnectionId o = h.join("Guest", "observer");
    h.send(o, editFrame(1, classScene("sphere(2)")));
    EXPECT_EQ(h.last(o, "refused")["reason"].toString(), "read-only");
    h.send(o, chatFrame("/add sphere(2)"));
    EXPECT_EQ(h.last(o, "refused")["reason"].toString(), "read-only");
}

TEST_F(ClassSessionTest, FreezeStopsStudentsNotTheInstructor) {
    const ConnectionId prof = h.join("Prof", "instructor", R"(,"key":"secret")");
    const ConnectionId ana = h.join("Ana");
    h.send(ana, R"({"type":"freeze"})");
    EXPECT_EQ(h.last(ana, "error")["code"].toString(), "forbidden");
    h.send(prof, R"({"type":"freeze","frozen":true})");
    EXPECT_TRUE(h.last(ana, "frozen")["frozen"].toBool());
    h.send(ana, editFrame(1, classScene("sphere(2)")));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "read-only");
    h.send(prof, editFrame(1, classScene("sphere(2)")));
    EXPECT_EQ(session.version(), 2);
    h.send(prof, R"({"type":"freeze","frozen":false})");
    h.send(prof, R"({"type":"release"})");
    h.send(ana, editFrame(2, classScene("sphere(3)")));
    EXPECT_EQ(session.version(), 3);
}

TEST_F(ClassSessionTest, InstructorTakesAndBreaksLocksAndPushes) {
    const ConnectionId prof = h.join("Prof", "instructor", R"(,"key":"secret")");
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(2)")));
    h.send(prof, R"({"type":"take-lock"})");
    EXPECT_EQ(h.last(ana, "lock")["holder"].toObject()["name"].toString(), "Prof");
    h.send(prof, R"({"type":"break-lock"})");
    EXPECT_TRUE(h.last(bo, "lock")["holder"].isNull());
    h.send(bo, editFrame(2, classScene("sphere(3)")));
    // A push lands under anyone's lock and ends it.
    const QJsonObject push{{"type", "push"},
                           {"scene", QString::fromStdString(classScene("box(1, 1, 1)"))}};
    h.send(prof, QJsonDocument(push).toJson(QJsonDocument::Compact).toStdString());
    EXPECT_EQ(h.last(ana, "scene")["kind"].toString(), "push");
    EXPECT_EQ(session.version(), 4);
    EXPECT_TRUE(h.last(ana, "lock")["holder"].isNull());
}

TEST_F(ClassSessionTest, AnonymisedNamesHideWhoIsWho) {
    const ConnectionId prof = h.join("Prof", "instructor", R"(,"key":"secret")");
    const ConnectionId ana = h.join("Ana");
    h.send(prof, R"({"type":"anonymise","anonymous":true})");
    for (const auto& m : h.last(ana, "presence")["members"].toArray())
        EXPECT_NE(m.toObject()["name"].toString(), "Ana");
    h.send(ana, chatFrame("hi"));
    EXPECT_TRUE(h.last(prof, "chat")["from"].toString().startsWith("Learner"));
}

TEST_F(ClassSessionTest, RateLimitRefusesABurst) {
    const ConnectionId ana = h.join("Ana");
    for (int i = 0; i < 12; ++i)
        h.send(ana, chatFrame("spam " + std::to_string(i)));
    EXPECT_EQ(h.last(ana, "refused")["reason"].toString(), "rate");
    EXPECT_EQ(h.count(ana, "chat"), 10);
    clock.advance(1'000);
    h.send(ana, chatFrame("later"));
    EXPECT_EQ(h.last(ana, "chat")["text"].toString(), "later");
}

TEST_F(ClassSessionTest, LeaseRunsOutWithoutEditsWhateverTheHeartbeats) {
    // Heartbeats keep Ana's seat, not the lock (issue 26 §4): an edit renews it.
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(2)")));
    clock.advance(9'000);
    h.send(ana, editFrame(2, classScene("sphere(2.5)")));
    clock.advance(9'000);
    h.send(ana, R"({"type":"heartbeat"})");
    h.tick();
    EXPECT_FALSE(h.last(bo, "lock")["holder"].isNull());
    clock.advance(1'001);
    h.send(ana, R"({"type":"heartbeat"})");
    h.tick();
    EXPECT_TRUE(h.last(bo, "lock")["holder"].isNull());
}

TEST_F(ClassSessionTest, AReconnectWithinTheGraceKeepsSeatAndLock) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(2)")));
    const std::string token = h.last(ana, "welcome")["token"].toString().toStdString();
    h.drop(ana);
    clock.advance(15'000);
    h.tick();
    h.send(bo, editFrame(2, classScene("sphere(3)")));
    EXPECT_EQ(h.last(bo, "refused")["reason"].toString(), "locked");
    const ConnectionId back = h.join("Ana", "student", R"(,"resume":")" + token + R"(","since":1)");
    const QJsonObject w = h.last(back, "welcome");
    EXPECT_TRUE(w["resumed"].toBool());
    EXPECT_EQ(w["lock"].toObject()["name"].toString(), "Ana");
    EXPECT_EQ(w["version"].toInt(), 2);
    h.send(back, editFrame(2, classScene("sphere(4)")));
    EXPECT_EQ(session.version(), 3);
}

TEST_F(ClassSessionTest, AHolderGoneLongerThanTheGraceLosesTheLock) {
    const ConnectionId ana = h.join("Ana"), bo = h.join("Bo");
    h.send(ana, editFrame(1, classScene("sphere(2)")));
    h.drop(ana);
    clock.advance(20'000);
    h.tick();
    EXPECT_TRUE(h.last(bo, "lock")["holder"].isNull());
    EXPECT_EQ(h.last(bo, "presence")["members"].toArray().size(), 1);
}

TEST_F(ClassSessionTest, SilentConnectionsAreClosed) {
    const ConnectionId ana = h.join("Ana");
    clock.advance(31'000);
    h.tick();
    EXPECT_TRUE(h.closed(ana));
}

TEST(ClassSessionStart, AnInvalidInitialSceneIsAnError) {
    ManualClock clock;
    ClassConfig c;
    c.classCode = "C";
    c.initialScene =
        "<X3D profile='Immersive' version='3.3'><Scene><Inline url='\"x.x3d\"'/></Scene></X3D>";
    EXPECT_THROW(ClassSession(c, clock, nullptr), std::runtime_error);
}

} // namespace
} // namespace fl::classroom
