#pragma once
// X3D Text (19775-1, 15 Text component) as flat filled glyphs in the z = 0
// plane: lines placed by FontStyle (size, spacing, justify, horizontal,
// leftToRight, topToBottom), squeezed to `length` and `maxExtent`.
//
// The kernel has no fonts: a TextOutliner (the suite's, from Qt's font
// engine: viewer/text_outliner.h) turns one line of text into outlines along
// a baseline; this file lays the lines out and fills them (planar_fill.h).
#include "mesh.h"
#include "planar_fill.h"

#include <functional>
#include <string>
#include <vector>

namespace fl::mesh {

// What FontStyle asks of the font.
struct FontRequest {
    std::vector<std::string> family{"SERIF"}; // "SERIF", "SANS", "TYPEWRITER" or names
    std::string style = "PLAIN";              // PLAIN, BOLD, ITALIC, BOLDITALIC
    double size = 1;                          // the nominal glyph height, scene units
};

// One line of text outlined along its baseline: x from 0 rightwards, y up,
// in scene units (already scaled to the requested size).
struct OutlinedLine {
    std::vector<Contour2> contours; // filled by the non-zero rule (TrueType, CFF)
    // Where each glyph's contours start in `contours`: glyphs are filled one
    // by one (kerned and italic neighbours overlap; filling a whole line as
    // one would cost its edge count squared). Empty: one glyph.
    std::vector<std::size_t> glyphStarts;
    double advance = 0;             // where the next character would start
    double ascent = 0, descent = 0; // of the font, both positive
    std::string problem;            // set when no font could be used
};

// A font source. An empty function: Text is not drawn (a note says so).
using TextOutliner = std::function<OutlinedLine(const std::string& utf8, const FontRequest&)>;

struct TextLayout {
    std::vector<std::string> lines; // Text.string, UTF-8
    std::vector<double> length;     // per line: > 0 squeezes or stretches it to this
    double maxExtent = 0;           // > 0: lines longer than this are squeezed to it
    FontRequest font;
    double spacing = 1; // between lines, in multiples of size
    std::string justifyMajor = "BEGIN", justifyMinor = "FIRST";
    // Vertical text (horizontal FALSE) stacks each string's characters in a
    // column; `length`, `maxExtent` and minor justification apply to
    // horizontal text only.
    bool horizontal = true, leftToRight = true, topToBottom = true;
};

// At most this many characters of one Text node are drawn (a warning says so).
inline constexpr std::size_t kMaxTextCharacters = 20000;

// The filled text, facing +z, normals (0, 0, 1). What could not be drawn
// (no fonts, too much text) is said in `warnings`.
Mesh textMesh(const TextLayout& layout, const TextOutliner& outliner,
              std::vector<std::string>* warnings = nullptr);

} // namespace fl::mesh
