#include "classic_lexer.h"

#include <algorithm>

namespace fl::scene {
namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == '\f' || c == '\v';
}

// ISO/IEC 14772-1 §5.1: characters that may not appear in a name.
bool isNameChar(char c, bool x3d) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u == 0x7f) return false;
    switch (c) {
    case '"':
    case '#':
    case '\'':
    case ',':
    case '.':
    case '[':
    case '\\':
    case ']':
    case '{':
    case '}':
        return false;
    case ':':
        return !x3d;
    default:
        return true;
    }
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isHexDigit(char c) {
    return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

} // namespace

bool isClassicName(std::string_view name, bool x3d) {
    if (name.empty() || isDigit(name[0]) || name[0] == '+' || name[0] == '-') return false;
    return std::all_of(name.begin(), name.end(), [&](char c) { return isNameChar(c, x3d); });
}

ClassicLexer::ClassicLexer(std::string_view text, std::size_t startOffset, FilePos startPos,
                           bool x3d)
    : text_(text), pos_(startOffset), line_(startPos.line), column_(startPos.column), x3d_(x3d) {
    current_ = scan();
}

void ClassicLexer::advance(std::size_t n) {
    for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_) {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else if (text_[pos_] == '\r') {
            // \r\n counts once; a lone \r ends a line too
            if (at(pos_ + 1) != '\n') {
                ++line_;
                column_ = 1;
            }
        } else if ((static_cast<unsigned char>(text_[pos_]) & 0xC0) != 0x80) {
            ++column_; // columns count characters, not UTF-8 continuation bytes
        }
    }
}

void ClassicLexer::skipSpace() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (isSpace(c)) {
            advance();
        } else if (c == '#') {
            while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r')
                advance();
        } else {
            break;
        }
    }
}

const ClassicTokenInfo& ClassicLexer::peekSecond() {
    if (!haveSecond_) {
        second_ = scan();
        haveSecond_ = true;
    }
    return second_;
}

ClassicTokenInfo ClassicLexer::next() {
    ClassicTokenInfo t = current_;
    if (haveSecond_) {
        current_ = second_;
        haveSecond_ = false;
    } else {
        current_ = scan();
    }
    return t;
}

ClassicTokenInfo ClassicLexer::scan() {
    skipSpace();
    ClassicTokenInfo t;
    t.offset = pos_;
    t.pos = {line_, column_};
    if (pos_ >= text_.size()) {
        t.kind = ClassicToken::End;
        return t;
    }
    const std::size_t start = pos_;
    const char c = text_[pos_];
    auto single = [&](ClassicToken kind) {
        advance();
        t.kind = kind;
    };
    switch (c) {
    case '{':
        single(ClassicToken::LeftBrace);
        break;
    case '}':
        single(ClassicToken::RightBrace);
        break;
    case '[':
        single(ClassicToken::LeftBracket);
        break;
    case ']':
        single(ClassicToken::RightBracket);
        break;
    case '.':
        if (isDigit(at(pos_ + 1))) goto number;
        single(ClassicToken::Period);
        break;
    case ':':
        if (!x3d_) goto name;
        single(ClassicToken::Colon);
        break;
    case '"': {
        advance();
        while (pos_ < text_.size() && text_[pos_] != '"') {
            if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) advance();
            advance();
        }
        if (pos_ >= text_.size()) {
            t.kind = ClassicToken::Invalid; // unterminated string
        } else {
            advance();
            t.kind = ClassicToken::String;
        }
        break;
    }
    case '+':
    case '-':
        if (!(isDigit(at(pos_ + 1)) || (at(pos_ + 1) == '.' && isDigit(at(pos_ + 2))))) {
            // "-inf"/"+inf" are not VRML; a lone sign is an error
            single(ClassicToken::Invalid);
            break;
        }
        [[fallthrough]];
    case '0':
    case '1':
    case '2':
    case '3':
    case '4':
    case '5':
    case '6':
    case '7':
    case '8':
    case '9':
    number : {
        std::size_t i = pos_;
        if (text_[i] == '+' || text_[i] == '-') ++i;
        if (at(i) == '0' && (at(i + 1) == 'x' || at(i + 1) == 'X') && isHexDigit(at(i + 2))) {
            i += 2;
            while (isHexDigit(at(i)))
                ++i;
        } else {
            while (isDigit(at(i)))
                ++i;
            if (at(i) == '.') {
                ++i;
                while (isDigit(at(i)))
                    ++i;
            }
            if ((at(i) == 'e' || at(i) == 'E') &&
                (isDigit(at(i + 1)) ||
                 ((at(i + 1) == '+' || at(i + 1) == '-') && isDigit(at(i + 2))))) {
                i += 2;
                while (isDigit(at(i)))
                    ++i;
            }
        }
        advance(i - pos_);
        t.kind = ClassicToken::Number;
        break;
    }
    default:
    name:
        if (!isNameChar(c, x3d_)) {
            single(ClassicToken::Invalid);
            break;
        }
        while (pos_ < text_.size() && isNameChar(text_[pos_], x3d_))
            advance();
        t.kind = ClassicToken::Identifier;
        break;
    }
    t.text = text_.substr(start, pos_ - start);
    return t;
}

std::string ClassicLexer::unquote(std::string_view quoted) {
    std::string out;
    out.reserve(quoted.size());
    for (std::size_t i = 1; i + 1 < quoted.size(); ++i) {
        if (quoted[i] == '\\' && i + 2 < quoted.size())
            ++i; // \" and \\ ; any other escaped character stands for itself
        out += quoted[i];
    }
    return out;
}

} // namespace fl::scene
