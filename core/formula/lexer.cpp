#include "lexer.h"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <string>
#include <unordered_map>

namespace fl::formula {

const char* tokenKindName(TokenKind kind) {
    switch (kind) {
    case TokenKind::End:
        return "end of formula";
    case TokenKind::Number:
        return "number";
    case TokenKind::Identifier:
        return "name";
    case TokenKind::KwFunction:
        return "'function'";
    case TokenKind::KwIf:
        return "'if'";
    case TokenKind::KwElse:
        return "'else'";
    case TokenKind::KwFor:
        return "'for'";
    case TokenKind::KwReturn:
        return "'return'";
    case TokenKind::KwParam:
        return "'param'";
    case TokenKind::KwVar:
        return "'var'";
    case TokenKind::KwIn:
        return "'in'";
    case TokenKind::LParen:
        return "'('";
    case TokenKind::RParen:
        return "')'";
    case TokenKind::LBrace:
        return "'{'";
    case TokenKind::RBrace:
        return "'}'";
    case TokenKind::LBracket:
        return "'['";
    case TokenKind::RBracket:
        return "']'";
    case TokenKind::Comma:
        return "','";
    case TokenKind::Semicolon:
        return "';'";
    case TokenKind::Question:
        return "'?'";
    case TokenKind::Colon:
        return "':'";
    case TokenKind::Assign:
        return "'='";
    case TokenKind::PlusAssign:
        return "'+='";
    case TokenKind::MinusAssign:
        return "'-='";
    case TokenKind::StarAssign:
        return "'*='";
    case TokenKind::SlashAssign:
        return "'/='";
    case TokenKind::Plus:
        return "'+'";
    case TokenKind::Minus:
        return "'-'";
    case TokenKind::Star:
        return "'*'";
    case TokenKind::Slash:
        return "'/'";
    case TokenKind::Caret:
        return "'^'";
    case TokenKind::Less:
        return "'<'";
    case TokenKind::LessEqual:
        return "'<='";
    case TokenKind::Greater:
        return "'>'";
    case TokenKind::GreaterEqual:
        return "'>='";
    case TokenKind::EqualEqual:
        return "'=='";
    case TokenKind::NotEqual:
        return "'!='";
    case TokenKind::AndAnd:
        return "'&&'";
    case TokenKind::OrOr:
        return "'||'";
    case TokenKind::Bang:
        return "'!'";
    case TokenKind::Amp:
        return "'&'";
    case TokenKind::Pipe:
        return "'|'";
    case TokenKind::Backslash:
        return "'\\'";
    case TokenKind::Tilde:
        return "'~'";
    case TokenKind::Invalid:
        return "invalid character";
    }
    return "token";
}

namespace {

class Lexer {
  public:
    Lexer(std::string_view src, std::vector<Diagnostic>& diags) : src_(src), diags_(diags) {}

    std::vector<Token> run() {
        std::vector<Token> tokens;
        const std::size_t firstDiagnostic = diags_.size();
        for (;;) {
            skipSpaceAndComments();
            Token tok = next();
            bool end = tok.kind == TokenKind::End;
            tokens.push_back(std::move(tok));
            if (end) break;
            if (diags_.size() - firstDiagnostic >= kMaxLexErrors) {
                diags_.push_back({Severity::Error, tokens.back().range,
                                  "too many bad characters; stopping here",
                                  "is this really a formula? check the file's encoding"});
                tokens.push_back(make(TokenKind::End, pos_));
                break;
            }
        }
        return tokens;
    }

  private:
    static constexpr std::size_t kMaxLexErrors = 50;
    std::string_view src_;
    std::vector<Diagnostic>& diags_;
    SourcePos pos_;

    bool atEnd() const { return pos_.offset >= src_.size(); }
    char peek(std::size_t ahead = 0) const {
        return pos_.offset + ahead < src_.size() ? src_[pos_.offset + ahead] : '\0';
    }
    void advance() {
        if (atEnd()) return;
        if (src_[pos_.offset] == '\n') {
            ++pos_.line;
            pos_.column = 1;
        } else {
            ++pos_.column;
        }
        ++pos_.offset;
    }

    void skipSpaceAndComments() {
        for (;;) {
            while (!atEnd() && std::isspace(static_cast<unsigned char>(peek())))
                advance();
            if (peek() == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n')
                    advance();
            } else if (peek() == '/' && peek(1) == '*') {
                SourcePos start = pos_;
                advance();
                advance();
                while (!atEnd() && !(peek() == '*' && peek(1) == '/'))
                    advance();
                if (atEnd()) {
                    diags_.push_back({Severity::Error,
                                      {start, pos_},
                                      "comment started here is never closed",
                                      "add '*/' to end the comment"});
                    return;
                }
                advance();
                advance();
            } else {
                return;
            }
        }
    }

    Token make(TokenKind kind, SourcePos start) {
        Token t;
        t.kind = kind;
        t.range = {start, pos_};
        t.text = std::string(src_.substr(start.offset, pos_.offset - start.offset));
        return t;
    }

    Token lexNumber(SourcePos start) {
        while (std::isdigit(static_cast<unsigned char>(peek())))
            advance();
        if (peek() == '.') {
            advance();
            while (std::isdigit(static_cast<unsigned char>(peek())))
                advance();
        }
        if (peek() == 'e' || peek() == 'E') {
            std::size_t ahead = 1;
            if (peek(1) == '+' || peek(1) == '-') ahead = 2;
            if (std::isdigit(static_cast<unsigned char>(peek(ahead)))) {
                for (std::size_t i = 0; i < ahead; ++i)
                    advance();
                while (std::isdigit(static_cast<unsigned char>(peek())))
                    advance();
            }
        }
        Token t = make(TokenKind::Number, start);
        // strtod accepts what we lexed; it returns ±HUGE_VAL on overflow, which
        // we report rather than silently turning into infinity.
        t.number = std::strtod(t.text.c_str(), nullptr);
        if (std::abs(t.number) > 1.7976931348623157e308) {
            diags_.push_back({Severity::Error, t.range,
                              "number '" + t.text + "' is too large for double precision",
                              "use a value below 1.7e308"});
        }
        return t;
    }

    Token next() {
        SourcePos start = pos_;
        if (atEnd()) return make(TokenKind::End, start);
        char c = peek();
        if (std::isdigit(static_cast<unsigned char>(c)) ||
            (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
            return lexNumber(start);
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_')
                advance();
            Token t = make(TokenKind::Identifier, start);
            static const std::unordered_map<std::string, TokenKind> keywords = {
                {"function", TokenKind::KwFunction},
                {"if", TokenKind::KwIf},
                {"else", TokenKind::KwElse},
                {"for", TokenKind::KwFor},
                {"return", TokenKind::KwReturn},
                {"param", TokenKind::KwParam},
                {"var", TokenKind::KwVar},
                {"let", TokenKind::KwVar},
                {"in", TokenKind::KwIn},
            };
            if (auto it = keywords.find(t.text); it != keywords.end()) t.kind = it->second;
            return t;
        }
        advance();
        auto two = [&](char second, TokenKind yes, TokenKind no) {
            if (peek() == second) {
                advance();
                return make(yes, start);
            }
            return make(no, start);
        };
        switch (c) {
        case '(':
            return make(TokenKind::LParen, start);
        case ')':
            return make(TokenKind::RParen, start);
        case '{':
            return make(TokenKind::LBrace, start);
        case '}':
            return make(TokenKind::RBrace, start);
        case '[':
            return make(TokenKind::LBracket, start);
        case ']':
            return make(TokenKind::RBracket, start);
        case ',':
            return make(TokenKind::Comma, start);
        case ';':
            return make(TokenKind::Semicolon, start);
        case '?':
            return make(TokenKind::Question, start);
        case ':':
            return make(TokenKind::Colon, start);
        case '^':
            return make(TokenKind::Caret, start);
        case '~':
            return make(TokenKind::Tilde, start);
        case '\\':
            return make(TokenKind::Backslash, start);
        case '=':
            return two('=', TokenKind::EqualEqual, TokenKind::Assign);
        case '!':
            return two('=', TokenKind::NotEqual, TokenKind::Bang);
        case '<':
            return two('=', TokenKind::LessEqual, TokenKind::Less);
        case '>':
            return two('=', TokenKind::GreaterEqual, TokenKind::Greater);
        case '&':
            return two('&', TokenKind::AndAnd, TokenKind::Amp);
        case '|':
            return two('|', TokenKind::OrOr, TokenKind::Pipe);
        case '*':
            return two('=', TokenKind::StarAssign, TokenKind::Star);
        case '/':
            return two('=', TokenKind::SlashAssign, TokenKind::Slash);
        // `++`/`--` are not tokens: `1--x` means 1 - (-x); the parser reads a
        // loop's `i++` as two adjacent pluses.
        case '+':
            return two('=', TokenKind::PlusAssign, TokenKind::Plus);
        case '-':
            return two('=', TokenKind::MinusAssign, TokenKind::Minus);
        default:
            break;
        }
        if (static_cast<unsigned char>(c) >= 0x80) {
            // one diagnostic for a whole UTF-8 sequence, not one per byte
            while ((static_cast<unsigned char>(peek()) & 0xC0) == 0x80)
                advance();
        }
        Token t = make(TokenKind::Invalid, start);
        // (appending rather than "literal" + temporary avoids GCC 12's false -Wrestrict, PR105329)
        std::string shown;
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) >= 127) {
            shown = "byte 0x";
            shown += toHex(static_cast<unsigned char>(c));
        } else {
            shown = {'\'', c, '\''};
        }
        std::string hint = c == '#'   ? "comments start with '//'"
                           : c == '%' ? "use mod(a, b) for the remainder"
                                      : "remove it";
        diags_.push_back({Severity::Error, t.range, "unexpected character " + shown, hint});
        return t;
    }

    static std::string toHex(unsigned v) {
        const char* digits = "0123456789abcdef";
        return {digits[(v >> 4) & 15], digits[v & 15]};
    }
};

} // namespace

std::vector<Token> tokenize(std::string_view source, std::vector<Diagnostic>& diagnostics) {
    return Lexer(source, diagnostics).run();
}

} // namespace fl::formula
