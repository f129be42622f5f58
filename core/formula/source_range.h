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
    // Which text the positions are in: 0, the tape's own definition; a tape
    // composed of others (an FTransform's) numbers the texts it inlined
    // (formula::inlineTape's sourceTag), so every instruction still says
    // where a student wrote it.
    int source = 0;

    static SourceRange span(const SourceRange& a, const SourceRange& b) { return {a.begin, b.end}; }
};

} // namespace fl::formula
