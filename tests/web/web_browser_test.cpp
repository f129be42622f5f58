// Every example exported with `functionlab export-web` and opened from the
// file system in headless Chromium (page_shot.cjs), as a reader would:
//   * the page says it is ready and the picture is not blank;
//   * at the scene's moment 0 (?still) its silhouette matches
//     `functionlab render` of the same viewpoint: intersection over union
//     of the pixels unlike the background at least 0.9. Both draw a copy of
//     the example with one more light, from above: with the headlight alone
//     a face it grazes is black in X_ITE (X3D's lighting: the headlight has
//     no ambient term) and grey in FunctionLab's view, and a silhouette
//     should not depend on that;
//   * playing, two screenshots a quarter cycle apart differ exactly when
//     FunctionLab's own renders of those two moments differ.
// Screenshots land in out/ beside the test (NAME-page.png, NAME-render.png,
// NAME-play-0.png, NAME-play-1.png): look at them. Needs node, chromium and
// X_ITE (scripts/test installs them); without one the test skips, or fails
// where FUNCTIONLAB_REQUIRE_TOOLS is set (CI). CTest label: interop.
// The class's live page (LiveClassPage) is opened from `functionlab serve`
// and must show an edit sent over the protocol within 2 s.
#include "../common/example_files.h"
#include "../common/required_tool.h"
#include "../common/tool_run.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QWebSocket>

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {

const QString kFunctionLab = QStringLiteral(FUNCTIONLAB_EXE);
const QString kExamples = QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR);
const QString kOutDir = QStringLiteral(FUNCTIONLAB_WEB_OUT_DIR);
const QString kShotScript = QStringLiteral(FUNCTIONLAB_PAGE_SHOT_SCRIPT);
const QString kXite = QStringLiteral(FUNCTIONLAB_X_ITE_DIR);
constexpr int kWidth = 640, kHeight = 480;

using fl::test::run;
using fl::test::ToolRun;

std::vector<std::string> examples() {
    return fl::test::exampleFiles(kExamples);
}

std::string testName(const std::string& file) {
    return fl::test::exampleTestName(file);
}

// Pixels unlike the background, which fills the image's corner.
std::vector<bool> silhouette(const QImage& image) {
    const QImage im = image.convertToFormat(QImage::Format_RGB32);
    const QRgb background = im.pixel(2, im.height() - 3);
    std::vector<bool> mask(std::size_t(im.width()) * std::size_t(im.height()));
    for (int y = 0; y < im.height(); ++y)
        for (int x = 0; x < im.width(); ++x) {
            const QRgb p = im.pixel(x, y);
            const int d = std::max({std::abs(qRed(p) - qRed(background)),
                                    std::abs(qGreen(p) - qGreen(background)),
                                    std::abs(qBlue(p) - qBlue(background))});
            mask[std::size_t(y) * std::size_t(im.width()) + std::size_t(x)] = d > 24;
        }
    return mask;
}

double intersectionOverUnion(const std::vector<bool>& a, const std::vector<bool>& b) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / double(either) : 1.0;
}

// The share of pixels that differ between two pictures of one size.
double changed(const QImage& a, const QImage& b) {
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size()) return 1;
    std::size_t n = 0;
    for (int r = 0; r < x.height(); ++r)
        for (int c = 0; c < x.width(); ++c) {
            const QRgb p = x.pixel(c, r), q = y.pixel(c, r);
            n += std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                           std::abs(qBlue(p) - qBlue(q))}) > 24;
        }
    return double(n) / double(x.width() * x.height());
}

// X_ITE's own page error when a wasm helper it never needs here cannot be
// fetched from a file: not the scene's.
QJsonObject shoot(const QString& url, const QStringList& files, std::string& failure) {
    const ToolRun r =
        run("node", QStringList{kShotScript, url, QString("%1x%2").arg(kWidth).arg(kHeight)}
                        << files << "--timeout"
                        << "150");
    const QJsonObject report = QJsonDocument::fromJson(r.out.trimmed().toUtf8()).object();
    if (r.exitCode != 0 || report.value("ready").toString() != "yes")
        failure = "the page did not become ready: " + r.describe();
    return report;
}

// The example, in a copy of the examples' folder of its own (its files
// beside it; tests run in parallel), with a light from above added at the
// end of the scene.
QString litCopy(const std::string& example) {
    const QString folder = kOutDir + "/examples-" + QString::fromStdString(testName(example));
    QDir().mkpath(folder);
    for (const QString& f : QDir(kExamples).entryList(QDir::Files)) {
        QFile::remove(folder + "/" + f);
        QFile::copy(kExamples + "/" + f, folder + "/" + f);
    }
    const QString path = folder + "/" + QString::fromStdString(example);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QString text = QString::fromUtf8(file.readAll());
    file.close();
    if (path.endsWith(".x3d")) {
        const auto end = text.lastIndexOf("</Scene>");
        if (end < 0) return {};
        text.insert(
            end,
            "<DirectionalLight direction='0.2 -1 -0.6' intensity='0.8' ambientIntensity='0.5'/>\n");
    } else {
        text += "\nDirectionalLight { direction 0.2 -1 -0.6 intensity 0.8 ambientIntensity 0.5 }\n";
    }
    QFile::remove(path);
    if (!file.open(QIODevice::WriteOnly)) return {};
    file.write(text.toUtf8());
    return path;
}

// What a page in a browser needs and is not here; empty when all is.
std::string missingBrowserTool() {
    if (QStandardPaths::findExecutable("node").isEmpty() ||
        QStandardPaths::findExecutable("chromium").isEmpty())
        return "node and chromium are not installed (Debian: nodejs chromium)";
    if (!QFileInfo::exists(kXite + "/x_ite.min.js"))
        return "X_ITE is not installed: run scripts/run or scripts/test";
    return {};
}

class WebPage : public testing::TestWithParam<std::string> {};

} // namespace

TEST_P(WebPage, ShowsTheSceneAsFunctionLabDrawsItAndPlaysItsTime) {
    if (const std::string missing = missingBrowserTool(); !missing.empty())
        FUNCTIONLAB_SKIP_WITHOUT_TOOL(missing);
    const std::string example = GetParam();
    const QString scene = litCopy(example);
    ASSERT_FALSE(scene.isEmpty()) << "cannot copy " << example;
    const QString name = QString::fromStdString(testName(example));
    QDir().mkpath(kOutDir);
    const QString folder = kOutDir + "/" + name;
    QDir(folder).removeRecursively();

    const ToolRun exported = run(kFunctionLab, {"export-web", scene, "-o", folder});
    ASSERT_EQ(exported.exitCode, 0) << exported.describe();
    const QString page = "file://" + QFileInfo(folder + "/index.html").absoluteFilePath();

    // Moment 0, against FunctionLab's own picture of it.
    std::string failure;
    const QString still = kOutDir + "/" + name + "-page.png";
    shoot(page + "?shot&still", {still}, failure);
    ASSERT_TRUE(failure.empty()) << failure;
    const QString rendered = kOutDir + "/" + name + "-render.png";
    const ToolRun render = run(kFunctionLab, {"render", scene, "-o", rendered, "--size",
                                              QString("%1x%2").arg(kWidth).arg(kHeight)});
    ASSERT_EQ(render.exitCode, 0) << render.describe();
    const std::vector<bool> pageShape = silhouette(QImage(still));
    const std::vector<bool> renderShape = silhouette(QImage(rendered));
    const auto drawn = std::count(pageShape.begin(), pageShape.end(), true);
    EXPECT_GT(drawn, kWidth * kHeight / 200) << "the page is blank: " << still.toStdString();
    EXPECT_GE(intersectionOverUnion(pageShape, renderShape), 0.9)
        << still.toStdString() << " against " << rendered.toStdString();

    // Playing: a quarter and 0.4 of the shortest cycle apart (a bounce is
    // symmetric in time: its pictures a quarter cycle apart can be the same
    // at the moment the first is taken, not at both gaps).
    const QString play0 = kOutDir + "/" + name + "-play-0.png";
    const QString play1 = kOutDir + "/" + name + "-play-1.png";
    const QString play2 = kOutDir + "/" + name + "-play-2.png";
    const QJsonObject played = shoot(page + "?shot", {play0, play1, play2}, failure);
    ASSERT_TRUE(failure.empty()) << failure;
    // The wait before the second picture: a quarter of the shortest cycle.
    const double quarter = played.value("waitedMs").toDouble() / 1000;
    const QString later = kOutDir + "/" + name + "-render-later.png";
    const ToolRun renderLater = run(kFunctionLab, {"render", scene, "-o", later, "--size",
                                                   QString("%1x%2").arg(kWidth).arg(kHeight),
                                                   "--time", QString::number(quarter)});
    ASSERT_EQ(renderLater.exitCode, 0) << renderLater.describe();
    const bool animated = changed(QImage(rendered), QImage(later)) > 0.002;
    const double pageChange =
        std::max(changed(QImage(play0), QImage(play1)), changed(QImage(play0), QImage(play2)));
    if (animated)
        EXPECT_GT(pageChange, 0.002) << "FunctionLab's picture changes in " << quarter
                                     << " s, the page's does not: " << play0.toStdString();
    else
        EXPECT_LT(pageChange, 0.0005)
            << "the page changes where FunctionLab's picture does not: " << play0.toStdString();
}

INSTANTIATE_TEST_SUITE_P(Examples, WebPage, testing::ValuesIn(examples()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             return testName(info.param);
                         });

namespace {

// Waits (running Qt's events) until `done` or `ms` pass.
bool waitFor(const std::function<bool()>& done, int ms) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return done();
}

const char* kEditedScene = R"(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'><head><component name='FunctionLab' level='1'/></head>
<Scene><Background skyColor='0.1 0.1 0.2'/><Viewpoint position='0 0 7'/>
<FShape><FGeometry type='implicit' definition='1 - (x-1.5)^2/3 - y^2 - z^2'
 domainMin='-0.3 -1.1 -1.1' domainMax='3.3 1.1 1.1'/></FShape></Scene></X3D>
)";

} // namespace

TEST(LiveClassPage, FollowsAnEditMadeOverTheProtocolWithinTwoSeconds) {
    if (const std::string missing = missingBrowserTool(); !missing.empty())
        FUNCTIONLAB_SKIP_WITHOUT_TOOL(missing);
    int argc = 1;
    char name[] = "web_browser_tests";
    char* argv[] = {name, nullptr};
    QCoreApplication app(argc, argv);
    QDir().mkpath(kOutDir);

    QProcess server;
    server.start(kFunctionLab, {"serve", "--port", "0", "--class", "WEB1"});
    ASSERT_TRUE(server.waitForStarted(10000));
    QString page;
    static const QRegularExpression web("web page on (http://\\S+)");
    ASSERT_TRUE(waitFor(
        [&] {
            if (const auto m = web.match(QString::fromUtf8(server.peek(4096))); m.hasMatch())
                page = m.captured(1);
            return !page.isEmpty();
        },
        15000))
        << server.readAllStandardError().toStdString();
    const QString ws = QString(page).replace("http://", "ws://");

    QProcess browser;
    const QString before = kOutDir + "/live-before.png", after = kOutDir + "/live-after.png";
    browser.start("node", {kShotScript, page + "?shot", QString("%1x%2").arg(kWidth).arg(kHeight),
                           before, after, "--follow", "--timeout", "120"});
    ASSERT_TRUE(browser.waitForStarted(10000));
    ASSERT_TRUE(waitFor(
        [&] { return browser.canReadLine() || browser.state() != QProcess::Running; }, 150000));
    const QJsonObject ready = QJsonDocument::fromJson(browser.readLine()).object();
    ASSERT_EQ(ready.value("ready").toString(), "yes")
        << browser.readAllStandardOutput().toStdString();

    // A student edits the class's scene over the protocol.
    QWebSocket student;
    QJsonObject welcome;
    QObject::connect(&student, &QWebSocket::textMessageReceived, [&](const QString& text) {
        const QJsonObject m = QJsonDocument::fromJson(text.toUtf8()).object();
        if (m.value("type") == "welcome") welcome = m;
    });
    student.open(QUrl(ws));
    ASSERT_TRUE(waitFor([&] { return student.state() == QAbstractSocket::ConnectedState; }, 10000));
    student.sendTextMessage(R"({"type":"join","class":"WEB1","name":"Ana"})");
    ASSERT_TRUE(waitFor([&] { return !welcome.isEmpty(); }, 10000));
    QJsonObject edit;
    edit["type"] = "edit";
    edit["version"] = welcome.value("version");
    edit["scene"] = QString::fromUtf8(kEditedScene);
    student.sendTextMessage(QString::fromUtf8(QJsonDocument(edit).toJson(QJsonDocument::Compact)));
    browser.write("edited\n");

    ASSERT_TRUE(waitFor([&] { return browser.state() != QProcess::Running; }, 60000));
    const QJsonObject followed =
        QJsonDocument::fromJson(browser.readAllStandardOutput().trimmed()).object();
    EXPECT_EQ(browser.exitCode(), 0) << browser.readAllStandardError().toStdString();
    EXPECT_GT(followed.value("version").toInt(), ready.value("version").toInt());
    std::cout << "the live page showed the edit " << followed.value("followMs").toDouble()
              << " ms after it was sent\n";
    EXPECT_LE(followed.value("followMs").toDouble(), 2000)
        << "the live page took " << followed.value("followMs").toDouble() << " ms";
    EXPECT_GT(changed(QImage(before), QImage(after)), 0.01)
        << before.toStdString() << " and " << after.toStdString() << " look alike";
    server.terminate();
    server.waitForFinished(10000);
}
