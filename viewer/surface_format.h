#pragma once
// The OpenGL the viewer's shaders are written for (3.3 core, a 24-bit depth
// buffer), as Qt's default surface format. Set before the QGuiApplication is
// made: by the window, `render` and every test that draws.
namespace fl::viewer {

// `samples`: multisampling (the window asks for 4; off-screen tests for none,
// so their pictures are the same on every driver).
void useViewerSurfaceFormat(int samples = 0);

} // namespace fl::viewer
