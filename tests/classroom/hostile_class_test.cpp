// The class survives any one member (issue 26 §2-§6), on a ManualClock:
// names that pass for others or reorder text, edits that cost too much work,
// joins that fill the class, guesses at the instructor key, connections that
// never join, locks held by heartbeats, and the small holes. Each test is an
// attack that worked before its fix.
#include "class_session.h"

#include "scenes.h"
#include "session_harness.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

using test::chatFrame;
using test::classScene;
using test::editFrame;

std::string joinFrame(const QString& name, const QString& role = QStringLiteral("student"),
                      const QJsonObject& extra = {}) {
    QJsonObject o{{"type", "join"}, {"class", "C1"}, {"name", name}, {"role", role}};
    for (auto it = extra.begin(); it != extra.end(); ++it)
        o[it.key()] = it.value();
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

class HostileClass : public ::testing::Test {
  protected:
    static ClassConfig config() {
        ClassConfig c;
        c.classCode = "C1";
        c.instructorKey = "a-long-instructor-key";
        c.initialScene = classScene("sphere(0, 0, 0, 1)");
        return c;
    }
    ConnectionId join(const QString& name, const std::string& peer = "127.0.0.1",
                      const QString& role = QStringLiteral("student"),
                      const QJsonObject& extra = {}) {
        const ConnectionId c = h.connect(peer);
        h.send(c, joinFrame(name, role, extra));
        return c;
    }
    bool welcomed(ConnectionId c) const { return !h.last(c, "welcome").isEmpty(); }
    QString errorCode(ConnectionId c) const { return h.last(c, "error")["code"].toString(); }

    ManualClock clock{1'000'000};
    ClassSession session{config(), clock, nullptr};
    test::Harness h{session};
};

// ---- §2 names --------------------------------------------------------------

TEST_F(HostileClass, MarkupInANameIsJustCharacters) {
    const ConnectionId c = join(QStringLiteral("<img src=/dev/zero>"));
    ASSERT_TRUE(welcomed(c));
    EXPECT_EQ(h.last(c, "welcome")["name"].toString(), "<img src=/dev/zero>");
}

TEST_F(HostileClass, NamesThatReorderTextOrHideAreRefused) {
    for (const QString& name :
         {QStringLiteral("\u202Eadmin"), QStringLiteral(" Ada"), QStringLiteral("\u200B"),
          QStringLiteral("Instructor"), QStringLiteral("Learner 2"), QStringLiteral("Ada\u2066")}) {
        const ConnectionId c = join(name);
        EXPECT_FALSE(welcomed(c)) << name.toStdString();
        EXPECT_EQ(errorCode(c), "bad-name") << name.toStdString();
    }
}

TEST_F(HostileClass, ANameIsTakenWhateverItsCaseOrNormalForm) {
    ASSERT_TRUE(welcomed(join(QStringLiteral("Jos\u00e9"))));
    for (const QString& same : {QStringLiteral("JOS\u00c9"), QStringLiteral("Jose\u0301")}) {
        const ConnectionId c = join(same);
        EXPECT_FALSE(welcomed(c));
        EXPECT_EQ(errorCode(c), "bad-name");
    }
    EXPECT_TRUE(welcomed(join(QStringLiteral("Josef"))));
}

TEST_F(HostileClass, AResumedSeatKeepsItsOwnName) {
    const ConnectionId ana = join(QStringLiteral("Ana"));
    const QString token = h.last(ana, "welcome")["token"].toString();
    h.drop(ana);
    const ConnectionId back = join(QStringLiteral("Ana"), "127.0.0.1", QStringLiteral("student"),
                                   QJsonObject{{"resume", token}});
    EXPECT_TRUE(welcomed(back));
    EXPECT_TRUE(h.last(back, "welcome")["resumed"].toBool());
}

} // namespace
} // namespace fl::classroom
