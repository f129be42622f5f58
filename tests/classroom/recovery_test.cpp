// Crash recovery with a real server process: a client edits through
// `functionlab serve --data DIR`, the server is killed with SIGKILL and
// started again on the same DIR, and every version it had announced is
// still there. SIGTERM stops it cleanly.
#include "classroom/client.h"

#include "scenes.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTest>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fl::classroom {
namespace {

constexpr int kWaitMs = 20'000;

class ServerProcess {
  public:
    explicit ServerProcess(const std::filesystem::path& data) {
        process_.setProgram(FUNCTIONLAB_EXECUTABLE);
        process_.setArguments({"serve", "--port", "0", "--class", "LAB7", "--data",
                               QString::fromStdString(data.string())});
        process_.start();
    }
    ~ServerProcess() {
        if (process_.state() != QProcess::NotRunning) {
            process_.kill();
            process_.waitForFinished(5000);
        }
    }
    // The url from `listening on ws://ADDR:P`, or empty.
    QUrl url() {
        QString out;
        const QRegularExpression line(R"(listening on (ws://[0-9.]+:[0-9]+)\n)");
        QRegularExpressionMatch m;
        (void)QTest::qWaitFor(
            [&] {
                out += QString::fromUtf8(process_.readAllStandardOutput());
                m = line.match(out);
                return m.hasMatch() || process_.state() == QProcess::NotRunning;
            },
            kWaitMs);
        if (!m.hasMatch()) {
            ADD_FAILURE() << "no listening line; stdout: " << out.toStdString()
                          << " stderr: " << process_.readAllStandardError().toStdString();
            return {};
        }
        return QUrl(m.captured(1));
    }
    QProcess& process() { return process_; }

  private:
    QProcess process_;
};

std::unique_ptr<ClassroomClient> joinedClient(const QUrl& url, const QString& name) {
    auto c = std::make_unique<ClassroomClient>();
    ClassroomClient::JoinOptions o;
    o.url = url;
    o.classCode = "LAB7";
    o.name = name;
    o.reconnect = false;
    c->join(o);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return c->state() == ClassroomClient::State::Joined; }, kWaitMs));
    return c;
}

TEST(ClassroomRecovery, NothingAppliedIsLostToSigkill) {
    const auto data = std::filesystem::temp_directory_path() /
                      ("functionlab-recovery-" + std::to_string(::getpid()));
    std::filesystem::remove_all(data);
    QString finalScene;
    {
        ServerProcess server(data);
        const QUrl url = server.url();
        ASSERT_FALSE(url.isEmpty());
        auto ana = joinedClient(url, "Ana");
        ASSERT_EQ(ana->version(), 1);
        for (int i = 2; i <= 4; ++i) {
            ana->submitEdit(QString::fromStdString(
                test::classScene("sphere(0, 0, 0, " + std::to_string(i) + ")")));
            ASSERT_TRUE(QTest::qWaitFor([&] { return ana->version() == i; }, kWaitMs));
        }
        ana->sendChat("/add box(0.5, 0.5, 3) difference");
        ASSERT_TRUE(QTest::qWaitFor([&] { return ana->version() == 5; }, kWaitMs));
        finalScene = ana->scene();
        server.process().kill(); // SIGKILL: no chance to flush or close anything
        ASSERT_TRUE(server.process().waitForFinished(5000));
        EXPECT_EQ(server.process().exitStatus(), QProcess::CrashExit);
    }
    ServerProcess again(data);
    const QUrl url = again.url();
    ASSERT_FALSE(url.isEmpty());
    auto bo = joinedClient(url, "Bo");
    EXPECT_EQ(bo->version(), 5);
    EXPECT_EQ(bo->scene(), finalScene);

    again.process().terminate(); // SIGTERM: a clean stop
    ASSERT_TRUE(again.process().waitForFinished(10'000));
    EXPECT_EQ(again.process().exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(again.process().exitCode(), 0);
    EXPECT_TRUE(
        QString::fromUtf8(again.process().readAllStandardError()).contains("stopped at version 5"));
    std::filesystem::remove_all(data);
}

TEST(ClassroomServe, ASceneWithAnInlineIsRefusedWithItsLine) {
    const auto file = std::filesystem::temp_directory_path() /
                      ("functionlab-serve-inline-" + std::to_string(::getpid()) + ".x3d");
    {
        std::ofstream out(file);
        out << "<X3D profile='Immersive' version='3.3'><Scene>\n"
               "<Inline url='\"elsewhere.x3d\"'/>\n</Scene></X3D>\n";
    }
    QProcess serve;
    serve.start(FUNCTIONLAB_EXECUTABLE,
                {"serve", QString::fromStdString(file.string()), "--port", "0", "--class", "C"});
    ASSERT_TRUE(serve.waitForFinished(kWaitMs));
    EXPECT_EQ(serve.exitCode(), 1);
    const QString err = QString::fromUtf8(serve.readAllStandardError());
    EXPECT_TRUE(err.contains(QString::fromStdString(file.string()) + ":2:")) << err.toStdString();
    EXPECT_TRUE(err.contains("Inline")) << err.toStdString();
    std::filesystem::remove(file);
}

TEST(ClassroomServe, PortAndClassAreRequired) {
    QProcess serve;
    serve.start(FUNCTIONLAB_EXECUTABLE, {"serve", "--port", "0"});
    ASSERT_TRUE(serve.waitForFinished(kWaitMs));
    EXPECT_EQ(serve.exitCode(), 2);
    EXPECT_TRUE(QString::fromUtf8(serve.readAllStandardError()).contains("--class"));
}

} // namespace
} // namespace fl::classroom
