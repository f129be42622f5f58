#pragma once
// Tokens of the ClassicVRML and VRML97 encodings (ISO/IEC 19776-2, 14772-1).
// Commas are white space; comments run from # to the end of the line.
#include "scene_diagnostic.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace fl::scene {

enum class ClassicToken : std::uint8_t {
    End,
    Identifier,
    Number,
    String,
    LeftBrace,
    RightBrace,
    LeftBracket,
    RightBracket,
    Period,
    Colon,
    Invalid,
};

struct ClassicTokenInfo {
    ClassicToken kind = ClassicToken::End;
    std::string_view text; // as written (strings include their quotes)
    std::size_t offset = 0;
    FilePos pos;
};

// Whether `name` can be written as a ClassicVRML name (ISO/IEC 14772-1 §5.1,
// X3D 19776-2 §5.3: no spaces, controls, quotes, '#', ',', '.', brackets,
// braces or backslash, and not starting with a digit, '+' or '-'; X3D also
// forbids ':'). Names read from X3D XML must pass it to survive conversion.
bool isClassicName(std::string_view name, bool x3d = true);

class ClassicLexer {
  public:
    // `x3d`: ':' separates tokens (X3D); in VRML97 it may be part of a name.
    ClassicLexer(std::string_view text, std::size_t startOffset, FilePos startPos, bool x3d);

    const ClassicTokenInfo& peek() const { return current_; }
    const ClassicTokenInfo& peekSecond();
    ClassicTokenInfo next();

    // Decoded content of a String token; false when an escape is malformed.
    static std::string unquote(std::string_view quoted);

    std::size_t lineCount() const { return static_cast<std::size_t>(line_); }

  private:
    ClassicTokenInfo scan();
    void skipSpace();
    char at(std::size_t i) const { return i < text_.size() ? text_[i] : '\0'; }
    void advance(std::size_t n = 1);

    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    bool x3d_ = true;
    ClassicTokenInfo current_;
    ClassicTokenInfo second_;
    bool haveSecond_ = false;
};

} // namespace fl::scene
