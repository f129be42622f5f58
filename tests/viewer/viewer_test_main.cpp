// GoogleTest with a QGuiApplication (OpenGL 3.3 core asked for first, as the
// suite does), so the off-screen tests can draw.
#include "viewer/surface_format.h"
#include <QGuiApplication>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    // Listing the tests (CTest's discovery, at build time) needs no display.
    if (testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
    // Without a display the camera tests still run; the drawing tests then
    // fail with "no OpenGL" (scripts/test runs CTest under xvfb-run).
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    fl::viewer::useViewerSurfaceFormat();
    QGuiApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
