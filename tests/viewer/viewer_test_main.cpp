// GoogleTest with a QGuiApplication (OpenGL 3.3 core asked for first, as the
// suite does), so the off-screen tests can draw.
#include <QGuiApplication>
#include <QSurfaceFormat>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QGuiApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
