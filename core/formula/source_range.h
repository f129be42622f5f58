#pragma once
// Where a piece of formula text lives: 1-based line and column of its first
// character and of the character just past it, plus the byte offsets.
#include <cstddef>

namespace fl::formula {

struct SourcePos {
    int line = 1;
    int column = 1;
    std::size_t offset = 0;
};

struct SourceRange {
    SourcePos begin;
    SourcePos end;

    static SourceRange span(const SourceRange& a, const SourceRange& b) { return {a.begin, b.end}; }
};

} // namespace fl::formula
