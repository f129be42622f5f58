#pragma once
// From byte offsets in a scene file to line:column, and from an offset inside
// a decoded string value back to the file (so a formula error inside
// definition "..." is reported where the student typed it).
#include "scene.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

class LineIndex {
  public:
    explicit LineIndex(std::string_view text);
    // Line and column (1-based; columns count characters) of a byte offset.
    FilePos position(std::size_t offset) const;

  private:
    std::string_view text_;
    std::vector<std::size_t> lineStarts_;
};

// The byte offset in `fileText` of the character at `decodedOffset` of a
// string whose content begins at `origin.offset`, undoing the encoding's
// escapes (\" \\ in Classic strings; entities and character references in XML
// attributes; both inside an MFString in an XML attribute).
std::size_t fileOffsetOf(std::string_view fileText, const StringOrigin& origin,
                         std::size_t decodedOffset);

// The line indexes of a scene's files, made when first asked for.
class LineIndexes {
  public:
    explicit LineIndexes(const Scene& scene) : scene_(scene) {}
    const LineIndex& of(int file);
    std::string_view text(int file) const { return scene_.files[std::size_t(file)].text; }

  private:
    const Scene& scene_;
    std::map<int, LineIndex> indexes_;
};

// A formula field's text as it is compiled: its strings joined by newlines.
std::string formulaText(const Field& field);
// Where in its file the character at `offset` of that text was written (the
// field's own position when its strings are not from a file).
FilePos formulaTextPosition(const Field& field, std::size_t offset, LineIndexes& lines);

} // namespace fl::scene
