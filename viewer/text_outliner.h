#pragma once
// Glyph outlines for X3D Text from Qt's font engine (fontconfig: DejaVu on
// Debian, installed by scripts/run): the font source the kernel's text
// layout (core/mesh/text_layout.h) asks for. Needs a QGuiApplication (the
// font database); without one it outlines nothing.
#include "mesh/text_layout.h"

namespace fl::viewer {

// Safe to call from meshing worker threads.
mesh::TextOutliner qtTextOutliner();

} // namespace fl::viewer
