// The class's log: versions written before they are announced, read back by
// a new class on the same folder; any version can be fetched for replay.
#include "classroom/class_session.h"
#include "classroom/edit_log.h"
#include "platform/sqlite_database.h"

#include "scenes.h"
#include "session_harness.h"

#include <QJsonArray>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

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

// ---- the log refuses damage (issue 26 §5) ------------------------------------

// A log of `n` versions, each about 600 bytes of scene, closed (checkpointed).
void writeVersions(const std::filesystem::path& dir, int n) {
    EditLog log(dir);
    for (int v = 1; v <= n; ++v)
        log.append(
            {v, "Ana", EditKind::Edit,
             test::classScene("sphere(0, 0, 0, " + std::to_string(v) + ")") + std::string(500, ' '),
             v});
}

void overwrite(const std::filesystem::path& file, std::uintmax_t at, std::size_t bytes) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(at));
    std::uint32_t x = 0x9e3779b9u;
    for (std::size_t i = 0; i < bytes; ++i) {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        f.put(char(x & 0xff));
    }
}

TEST(EditLog, RandomBytesOverMiddlePagesAreRefusedWithTheWayOut) {
    const auto dir = freshDir("damaged");
    writeVersions(dir, 300);
    const auto file = dir / EditLog::kLogFile;
    const auto size = std::filesystem::file_size(file);
    ASSERT_GT(size, 40'000u);
    overwrite(file, (size / 2) & ~std::uintmax_t(4095), 8192); // two middle pages
    try {
        EditLog log(dir);
        FAIL() << "a damaged log was opened";
    } catch (const EditLogRefused& e) {
        const std::string why = e.what();
        EXPECT_NE(why.find("is damaged"), std::string::npos) << why;
        EXPECT_NE(why.find(".recover"), std::string::npos) << why;
    }
    std::filesystem::remove_all(dir);
}

TEST(EditLog, AnEmptiedLogOfAClassIsRefusedUnlessANewClassIsAsked) {
    const auto dir = freshDir("emptied");
    writeVersions(dir, 3);
    std::filesystem::resize_file(dir / EditLog::kLogFile, 0);
    EXPECT_THROW(EditLog log(dir), EditLogRefused);
    std::filesystem::remove(dir / EditLog::kLogFile);
    EXPECT_THROW(EditLog log(dir), EditLogRefused);
    EditLog fresh(dir, true);
    EXPECT_FALSE(fresh.latest());
    std::filesystem::remove_all(dir);
}

TEST(EditLog, ANewFolderIsNotAClassUntilItsFirstVersion) {
    const auto dir = freshDir("new");
    { EditLog log(dir); } // opened, nothing written: no class yet
    EditLog again(dir);
    EXPECT_FALSE(again.latest());
    std::filesystem::remove_all(dir);
}

TEST(EditLog, OneServerPerFolder) {
    const auto dir = freshDir("twice");
    EditLog first(dir);
    try {
        EditLog second(dir);
        FAIL() << "two logs on one folder";
    } catch (const EditLogRefused& e) {
        EXPECT_NE(std::string(e.what()).find("another server"), std::string::npos);
    }
    std::filesystem::remove_all(dir);
}

TEST(EditLog, ChatIsKeptAndShownToNewcomersAfterARestart) {
    const auto dir = freshDir("chat");
    ManualClock clock;
    {
        EditLog log(dir);
        ClassSession session(config(), clock, &log);
        test::Harness h(session);
        const ConnectionId ana = h.join("Ana");
        h.send(ana, test::chatFrame("hello class"));
    }
    EditLog log(dir);
    ClassSession again(config(), clock, &log);
    test::Harness h(again);
    const ConnectionId bo = h.join("Bo");
    const QJsonArray chat = h.last(bo, "welcome")["chat"].toArray();
    ASSERT_EQ(chat.size(), 1);
    EXPECT_EQ(chat[0].toObject()["from"].toString(), "Ana");
    EXPECT_EQ(chat[0].toObject()["text"].toString(), "hello class");
    std::filesystem::remove_all(dir);
}

TEST(EditLog, ANewestVersionThatIsNoLongerAcceptedIsNotServed) {
    // Written before the loop check existed: a node that contains itself.
    const auto dir = freshDir("poisoned");
    {
        EditLog log(dir);
        log.append({1, "server", EditKind::Start, test::classScene("sphere(0, 0, 0, 1)"), 1});
        log.append({2, "Mallory", EditKind::Edit,
                    "<X3D profile='Immersive'><Scene><Transform DEF='A'><Transform USE='A'/>"
                    "</Transform></Scene></X3D>",
                    2});
    }
    ManualClock clock;
    EditLog log(dir);
    ClassSession session(config(), clock, &log);
    EXPECT_EQ(session.version(), 3);
    EXPECT_EQ(session.scene(), test::classScene("sphere(0, 0, 0, 1)"));
    EXPECT_NE(session.startNote().find("version 2"), std::string::npos) << session.startNote();
    std::filesystem::remove_all(dir);
}

TEST(EditLog, ALogThatFailsUnderneathCostsOneRequestNotTheClass) {
    // Whatever a read of the log throws (here: another process dropped the
    // table), history and a rejoin with `since` are answered, not crashed.
    const auto dir = freshDir("failing");
    ManualClock clock;
    EditLog log(dir);
    ClassSession session(config(), clock, &log);
    test::Harness h(session);
    const ConnectionId ana = h.join("Ana");
    h.send(ana, test::editFrame(1, test::classScene("sphere(0, 0, 0, 2)")));
    {
        fl::platform::SqliteDatabase other((dir / EditLog::kLogFile).string());
        other.execute("DROP TABLE versions");
    }
    h.send(ana, R"({"type":"history","version":1})");
    EXPECT_EQ(h.last(ana, "error")["code"].toString(), "server");
    const ConnectionId bo = h.join("Bo", "student", R"(,"since":1)");
    EXPECT_FALSE(h.last(bo, "welcome").isEmpty());
    std::filesystem::remove_all(dir);
}

TEST(EditLog, AnAnonymousClassSendsNoNamesInTheMissedList) {
    const auto dir = freshDir("anonymous");
    ManualClock clock;
    EditLog log(dir);
    ClassConfig c = config();
    c.instructorKey = "key";
    ClassSession session(c, clock, &log);
    test::Harness h(session);
    const ConnectionId prof = h.join("Prof", "instructor", R"(,"key":"key")");
    const ConnectionId ana = h.join("Ana");
    h.send(ana, test::editFrame(1, test::classScene("sphere(0, 0, 0, 2)")));
    h.send(prof, R"({"type":"anonymise","anonymous":true})");
    const ConnectionId bo = h.join("Bo", "student", R"(,"since":1)");
    const QJsonArray missed = h.last(bo, "welcome")["missed"].toArray();
    ASSERT_EQ(missed.size(), 1);
    EXPECT_NE(missed[0].toObject()["author"].toString(), "Ana");
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace fl::classroom
