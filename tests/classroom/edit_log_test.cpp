// The class's log: versions written before they are announced, read back by
// a new class on the same folder; any version can be fetched for replay.
#include "class_session.h"
#include "edit_log.h"

#include "scenes.h"
#include "session_harness.h"

#include <QJsonArray>

#include <gtest/gtest.h>

#include <filesystem>

namespace fl::classroom {
namespace {

std::filesystem::path freshDir(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("functionlab-classroom-" + std::string(name) + "-" +
                      std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                      std::to_string(reinterpret_cast<std::uintptr_t>(&name) & 0xffff));
    std::filesystem::remove_all(dir);
    return dir;
}

ClassConfig config() {
    ClassConfig c;
    c.classCode = "C1";
    c.initialScene = test::classScene("sphere(0, 0, 0, 1)");
    return c;
}

TEST(EditLog, AppendAndReadBack) {
    const auto dir = freshDir("log");
    {
        EditLog log(dir);
        EXPECT_FALSE(log.latest());
        log.append({1, "server", EditKind::Start, "one", 10});
        log.append({2, "Ana", EditKind::Edit, "two", 20});
        EXPECT_THROW(log.append({2, "Bo", EditKind::Edit, "again", 30}), std::exception);
    }
    EditLog log(dir);
    EXPECT_EQ(log.latest()->version, 2);
    EXPECT_EQ(log.latest()->scene, "two");
    EXPECT_EQ(log.at(1)->author, "server");
    EXPECT_EQ(log.at(1)->kind, EditKind::Start);
    EXPECT_FALSE(log.at(3));
    const auto after = log.after(0, 10);
    ASSERT_EQ(after.size(), 2u);
    EXPECT_EQ(after[1].author, "Ana");
    EXPECT_TRUE(after[1].scene.empty());
    log.snapshot(2, "end", "Prof");
    EXPECT_EQ(log.snapshots().at(0).label, "end");
    std::filesystem::remove_all(dir);
}

TEST(EditLog, ARestartedClassGoesOnFromTheNewestVersion) {
    const auto dir = freshDir("restart");
    ManualClock clock;
    std::string scene;
    {
        EditLog log(dir);
        ClassSession session(config(), clock, &log);
        test::Harness h(session);
        const ConnectionId ana = h.join("Ana");
        h.send(ana, test::editFrame(1, test::classScene("sphere(0, 0, 0, 2)")));
        h.send(ana, test::chatFrame("/add box(0.5, 0.5, 3) difference"));
        h.send(ana, test::chatFrame("/save lesson one"));
        EXPECT_EQ(h.last(ana, "saved")["version"].toInt(), 3);
        EXPECT_EQ(session.version(), 3);
        scene = session.scene();
    }
    EditLog log(dir);
    ClassSession again(config(), clock, &log);
    EXPECT_EQ(again.version(), 3);
    EXPECT_EQ(again.scene(), scene);
    EXPECT_EQ(log.snapshots().back().label, "lesson one");
    test::Harness h(again);
    const ConnectionId bo = h.join("Bo", "student", R"(,"since":1)");
    const QJsonObject w = h.last(bo, "welcome");
    EXPECT_EQ(w["version"].toInt(), 3);
    EXPECT_EQ(w["missed"].toArray().size(), 2);
    h.send(bo, R"({"type":"history","version":2})");
    EXPECT_EQ(h.last(bo, "version")["scene"].toString().toStdString(),
              test::classScene("sphere(0, 0, 0, 2)"));
    h.send(bo, R"({"type":"history","version":99})");
    EXPECT_EQ(h.last(bo, "error")["code"].toString(), "not-found");
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace fl::classroom
