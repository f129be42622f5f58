#include "field_text_edit.h"

#include "scene_writer.h"
#include "source_map.h"

#include <cctype>

namespace fl::scene {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

// The byte offset of line:column (columns count characters) in `text`.
std::optional<std::size_t> offsetOf(std::string_view text, FilePos pos) {
    if (pos.line < 1 || pos.column < 1) return std::nullopt;
    std::size_t i = 0;
    for (int line = 1; line < pos.line; ++line) {
        while (i < text.size() && text[i] != '\n' && text[i] != '\r')
            ++i;
        if (i >= text.size()) return std::nullopt;
        i += text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n' ? 2 : 1;
    }
    for (int column = 1; column < pos.column; ++column) {
        if (i >= text.size()) return std::nullopt;
        ++i; // past the character's first byte, then its continuation bytes
        while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80)
            ++i;
    }
    return i;
}

bool startsWithName(std::string_view text, std::size_t at, std::string_view name) {
    if (text.substr(at, name.size()) != name) return false;
    const std::size_t end = at + name.size();
    return end >= text.size() ||
           !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_');
}

// XML: the reader places an attribute at its value's first character, just
// after the opening quote: the value runs to the matching quote.
std::optional<TextEdit> xmlValue(std::string_view text, std::size_t at, std::string_view value) {
    if (at == 0 || at > text.size() || (text[at - 1] != '"' && text[at - 1] != '\''))
        return std::nullopt;
    const std::size_t close = text.find(text[at - 1], at);
    if (close == std::string_view::npos) return std::nullopt;
    return TextEdit{at, close - at, std::string(value)};
}

// Classic: name n1 n2 ... — the numbers after the name (as many as it has).
std::optional<TextEdit> classicValue(std::string_view text, std::size_t at, std::string_view name,
                                     std::string_view value, std::size_t count) {
    std::size_t i = at + name.size();
    std::size_t start = std::string_view::npos, end = i;
    for (std::size_t k = 0; k < count; ++k) {
        while (i < text.size() && isSpace(text[i]))
            ++i;
        const std::size_t first = i;
        while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) ||
                                   text[i] == '.' || text[i] == '-' || text[i] == '+'))
            ++i;
        if (i == first) return std::nullopt;
        if (start == std::string_view::npos) start = first;
        end = i;
    }
    return TextEdit{start, end - start, std::string(value)};
}

void say(std::string* why, std::string text) {
    if (why) *why = std::move(text);
}

} // namespace

namespace {

// Classic: name "s" or name [ "s1", "s2" ] — the value after the name, with
// strings (and their escapes) and # comments skipped over.
std::optional<TextEdit> classicStrings(std::string_view text, std::size_t at, std::string_view name,
                                       std::string_view value) {
    std::size_t i = at + name.size();
    auto skipBlank = [&] {
        while (i < text.size()) {
            if (isSpace(text[i])) {
                ++i;
            } else if (text[i] == '#') {
                while (i < text.size() && text[i] != '\n' && text[i] != '\r')
                    ++i;
            } else {
                return;
            }
        }
    };
    auto skipString = [&] { // at the opening quote
        for (++i; i < text.size(); ++i) {
            if (text[i] == '\\') {
                ++i;
            } else if (text[i] == '"') {
                ++i;
                return true;
            }
        }
        return false;
    };
    skipBlank();
    const std::size_t start = i;
    if (i < text.size() && text[i] == '"') {
        if (!skipString()) return std::nullopt;
        return TextEdit{start, i - start, std::string(value)};
    }
    if (i >= text.size() || text[i] != '[') return std::nullopt;
    for (++i;;) {
        skipBlank();
        if (i >= text.size()) return std::nullopt;
        if (text[i] == ']') return TextEdit{start, i + 1 - start, std::string(value)};
        if (text[i] != '"' || !skipString()) return std::nullopt;
    }
}

// The one edit that writes `field` of `node`: where its value is written,
// `replace(text, offset of the field, xml)` gives the edit; where it is not,
// the field is added at the start of the node with `xmlValue` (already
// escaped for an attribute) or `classicValue`.
template <class Replace>
std::optional<TextEdit> fieldEdit(const Scene& scene, const Node& node, std::string_view field,
                                  Replace replace, const std::string& xmlValue,
                                  const std::string& classicValue, std::string* why) {
    if (node.file != 0 || scene.files.empty()) {
        say(why, node.file < 0
                     ? "the node was not read from a file"
                     : "the node is written in another file (" + scene.pathOf(node.file) + ")");
        return std::nullopt;
    }
    if (node.inProtoBody || node.instance) {
        say(why, "the node is part of a PROTO: change the PROTO's interface instead");
        return std::nullopt;
    }
    const std::string_view text = scene.files[0].text;
    const bool xml = scene.encoding == Encoding::Xml;
    if (const Field* f = node.field(field)) {
        if (f->file != 0 || !f->isReferences.empty()) {
            say(why, "the field's value comes from elsewhere (IS or another file)");
            return std::nullopt;
        }
        const auto at = offsetOf(text, f->where);
        std::optional<TextEdit> edit;
        if (at) edit = replace(text, *at, xml, *f);
        if (!edit) say(why, "the text at the field's position does not hold its value");
        return edit;
    }
    const auto at = offsetOf(text, node.where);
    if (!at) {
        say(why, "the node's position is not in the text");
        return std::nullopt;
    }
    if (xml) {
        // After the element's name: <FGeometry resolution='48' ...
        std::size_t i = *at;
        if (i >= text.size() || text[i] != '<') {
            say(why, "the text at the node's position is not its element");
            return std::nullopt;
        }
        ++i;
        while (i < text.size() && !isSpace(text[i]) && text[i] != '>' && text[i] != '/')
            ++i;
        return TextEdit{i, 0, " " + std::string(field) + "='" + xmlValue + "'"};
    }
    // Just inside the node's brace: FGeometry { resolution 48 ...
    const std::size_t brace = text.find('{', *at);
    if (brace == std::string_view::npos) {
        say(why, "the node's opening brace is not in the text");
        return std::nullopt;
    }
    return TextEdit{brace + 1, 0, " " + std::string(field) + " " + classicValue};
}

} // namespace

std::optional<TextEdit> setNumbersFieldEdit(const Scene& scene, const Node& node,
                                            std::string_view field, std::string_view value,
                                            std::string* why) {
    auto replace = [&](std::string_view text, std::size_t at, bool xml, const Field& f) {
        if (xml) return xmlValue(text, at, value);
        if (!startsWithName(text, at, field)) return std::optional<TextEdit>{};
        return classicValue(text, at, field, value, f.value.numbers.size());
    };
    return fieldEdit(scene, node, field, replace, std::string(value), std::string(value), why);
}

std::optional<TextEdit> setStringsFieldEdit(const Scene& scene, const Node& node,
                                            std::string_view field,
                                            const std::vector<std::string>& strings,
                                            std::string* why) {
    std::string quoted;
    for (const std::string& s : strings)
        quoted += (quoted.empty() ? "" : " ") + quotedString(s);
    const std::string classic = strings.size() == 1 ? quoted : "[ " + quoted + " ]";
    auto replace = [&](std::string_view text, std::size_t at, bool isXml, const Field&) {
        if (isXml) {
            if (at == 0 || at > text.size()) return std::optional<TextEdit>{};
            return xmlValue(text, at, xmlAttributeText(quoted, text[at - 1]));
        }
        if (!startsWithName(text, at, field)) return std::optional<TextEdit>{};
        return classicStrings(text, at, field, classic);
    };
    return fieldEdit(scene, node, field, replace, xmlAttributeText(quoted, '\''), classic, why);
}

std::string applied(std::string_view text, const TextEdit& edit) {
    std::string out(text.substr(0, edit.offset));
    out += edit.text;
    out += text.substr(std::min(edit.offset + edit.length, text.size()));
    return out;
}

} // namespace fl::scene
