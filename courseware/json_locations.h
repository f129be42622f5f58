#pragma once
// Where each value of a JSON text is: its JSON pointer ("/requirements/2/points")
// to the line and column it starts at, so a manifest's errors say
// manifest.json:LINE:COL. Qt's JSON reader checks the syntax and holds the
// values; it keeps no positions, so this scan adds them.
#include <map>
#include <string>
#include <string_view>

namespace fl::courseware {

struct TextPosition {
    int line = 1;
    int column = 1;
};

class JsonLocations {
  public:
    // `text` must be JSON Qt has accepted; a malformed text yields what was
    // found before the fault (positions are a help, never a second check).
    explicit JsonLocations(std::string_view text);
    // The value at `pointer`, else the nearest enclosing one found, else 1:1.
    TextPosition of(const std::string& pointer) const;
    // The line and column of a byte offset (for Qt's parse errors).
    TextPosition at(std::size_t offset) const;

  private:
    std::string_view text_;
    std::map<std::string, std::size_t> offsets_;
};

} // namespace fl::courseware
