// `functionlab render` as a user runs it, judged by what the picture shows:
// the watermelon's red flesh and green rind where the scene puts them, and
// the shark's tail in another place at another --time. (The CMake test checks
// exit codes, messages and the PNG's size.)
#include <QCoreApplication>
#include <QDir>
#include <QImage>
#include <QProcess>

#include "picture_measures.h"

#include <gtest/gtest.h>

namespace {

QImage render(const QStringList& arguments, const QString& name) {
    QDir().mkpath(FUNCTIONLAB_RENDER_OUT_DIR);
    const QString out = QStringLiteral(FUNCTIONLAB_RENDER_OUT_DIR "/") + name + ".png";
    QFile::remove(out);
    QProcess p;
    p.start(QStringLiteral(FUNCTIONLAB_EXE), QStringList{"render"} << arguments << "-o" << out);
    EXPECT_TRUE(p.waitForFinished(120000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
    return QImage(out);
}

const QString kExamples = QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/");

} // namespace

TEST(RenderCommand, TheWatermelonIsRedInsideAndGreenOutside) {
    const QImage image = render({kExamples + "watermelon.x3d", "--size", "200x150"}, "melon");
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.size(), QSize(200, 150));
    const auto red = [](const QColor& c) { return c.redF() > 0.5 && c.greenF() < 0.35; };
    const auto green = [](const QColor& c) { return c.greenF() > c.redF() + 0.15; };
    using fl::testing::share;
    EXPECT_GT(share(image, 0, 200, red), 0.03);
    EXPECT_GT(share(image, 0, 200, green), 0.01);
    // The melon stands in the middle: its left and right margins are background.
    const QColor corner = image.pixelColor(0, 0);
    const auto shape = [&](const QColor& c) { return c != corner; };
    EXPECT_LT(share(image, 0, 20, shape), 0.01);
    EXPECT_LT(share(image, 180, 200, shape), 0.01);
    EXPECT_GT(share(image, 80, 120, shape), 0.3);
}

TEST(RenderCommand, TimeMovesTheSharksTailNotItsBody) {
    const QImage a = render({kExamples + "shark.x3d", "--size", "320x240", "--time", "1.25"},
                            "shark-1.25"),
                 b = render({kExamples + "shark.x3d", "--size", "320x240", "--time", "3.75"},
                            "shark-3.75");
    ASSERT_FALSE(a.isNull() || b.isNull());
    EXPECT_GT(fl::testing::movedShare(a, b, 0, 320 / 3), 0.003) << "the tail did not move";
    EXPECT_LT(fl::testing::movedShare(a, b, 160, 320), 0.0005) << "the body moved";
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
