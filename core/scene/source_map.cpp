#include "source_map.h"

#include <algorithm>

namespace fl::scene {

LineIndex::LineIndex(std::string_view text) : text_(text) {
    lineStarts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n')
            lineStarts_.push_back(i + 1);
        else if (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))
            lineStarts_.push_back(i + 1);
    }
}

FilePos LineIndex::position(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(it - lineStarts_.begin());
    const std::size_t start = lineStarts_[line - 1];
    int column = 1;
    for (std::size_t i = start; i < offset; ++i)
        if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;
    return {static_cast<int>(line), column};
}

namespace {

// Bytes of UTF-8 a character reference produces.
std::size_t utf8Length(unsigned long cp) {
    return cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
}

// One decoded unit at raw[i]: how many raw bytes it spans and how many
// decoded bytes it yields.
std::pair<std::size_t, std::size_t> step(std::string_view raw, std::size_t i, bool entities,
                                         bool backslashes) {
    if (entities && raw[i] == '&') {
        const std::size_t semi = raw.find(';', i);
        if (semi != std::string_view::npos && semi - i <= 12) {
            std::string_view ent = raw.substr(i + 1, semi - i - 1);
            std::size_t produced = 1;
            if (ent.size() > 1 && ent[0] == '#') {
                unsigned long cp = 0;
                const bool hex = ent[1] == 'x' || ent[1] == 'X';
                for (char c : ent.substr(hex ? 2 : 1))
                    cp = cp * (hex ? 16 : 10) +
                         static_cast<unsigned long>(c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10);
                produced = utf8Length(cp);
            }
            return {semi - i + 1, produced};
        }
    }
    if (entities && raw[i] == '\r' && i + 1 < raw.size() && raw[i + 1] == '\n')
        return {2, 1}; // attribute normalisation turns \r\n into one space
    if (backslashes && raw[i] == '\\' && i + 1 < raw.size()) return {2, 1};
    return {1, 1};
}

} // namespace

std::size_t fileOffsetOf(std::string_view fileText, const StringOrigin& origin,
                         std::size_t decodedOffset) {
    const bool entities = origin.escapes == StringEscapes::XmlAttribute ||
                          origin.escapes == StringEscapes::XmlAttributeQuoted;
    const bool backslashes = origin.escapes == StringEscapes::Classic ||
                             origin.escapes == StringEscapes::XmlAttributeQuoted;
    std::size_t i = std::min(origin.offset, fileText.size());
    std::size_t decoded = 0;
    while (i < fileText.size() && decoded < decodedOffset) {
        auto [rawBytes, produced] = step(fileText, i, entities, backslashes);
        if (decoded + produced > decodedOffset)
            break; // inside a multi-byte entity: point at the entity
        decoded += produced;
        i += rawBytes;
    }
    return i;
}

const LineIndex& LineIndexes::of(int file) {
    auto it = indexes_.find(file);
    if (it == indexes_.end())
        it = indexes_.emplace(file, LineIndex(scene_.files[std::size_t(file)].text)).first;
    return it->second;
}

std::string formulaText(const Field& field) {
    std::string source;
    for (std::size_t i = 0; i < field.value.strings.size(); ++i) {
        if (i) source += '\n';
        source += field.value.strings[i];
    }
    return source;
}

FilePos formulaTextPosition(const Field& field, std::size_t offset, LineIndexes& lines) {
    const FieldValue& v = field.value;
    std::size_t i = 0, start = 0;
    // The string the offset falls in: each is followed by one joining newline.
    while (i + 1 < v.strings.size() && start + v.strings[i].size() + 1 <= offset) {
        start += v.strings[i].size() + 1;
        ++i;
    }
    if (i >= v.stringOrigins.size() || v.stringOrigins[i].file < 0) return field.where;
    const StringOrigin& origin = v.stringOrigins[i];
    const std::size_t within = std::min(offset - start, v.strings[i].size());
    return lines.of(origin.file).position(fileOffsetOf(lines.text(origin.file), origin, within));
}

} // namespace fl::scene
