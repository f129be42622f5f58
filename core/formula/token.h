#pragma once
#include "source_range.h"

#include <string>

namespace fl::formula {

enum class TokenKind {
    End,
    Number,
    Identifier,
    // keywords
    KwFunction,
    KwIf,
    KwElse,
    KwFor,
    KwReturn,
    KwParam,
    KwVar,
    KwIn,
    // punctuation and operators
    LParen,
    RParen,
    LBrace,
    RBrace,
    LBracket,
    RBracket,
    Comma,
    Semicolon,
    Question,
    Colon,
    Assign,
    PlusAssign,
    MinusAssign,
    StarAssign,
    SlashAssign,
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    EqualEqual,
    NotEqual,
    AndAnd,
    OrOr,
    Bang,
    Amp,       // set intersection
    Pipe,      // set union
    Backslash, // set difference
    Tilde,     // set complement
    Invalid,
};

struct Token {
    TokenKind kind = TokenKind::End;
    SourceRange range;
    std::string text; // identifier spelling, number spelling or the offending character
    double number = 0.0;
};

const char* tokenKindName(TokenKind kind);

} // namespace fl::formula
