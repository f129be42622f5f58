#include "xml_syntax_help.h"

#include <cctype>
#include <vector>

namespace fl::scene {

namespace {

// Where each character of `text` lies: line, column (characters) and
// whether it is inside an attribute's quoted value — a small scan of the
// XML's structure (text, tags, quoted values, comments, CDATA, processing
// instructions), enough to tell a formula's `&` from markup.
struct Scan {
    std::size_t offset = 0;
    FilePos pos{1, 1};
    bool inAttributeValue = false;
};

bool continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// The offset of line:column, and for each offset up to it whether it lies in
// an attribute value. Stops at `limit` (the reported place).
std::vector<Scan> scanUpTo(std::string_view text, FilePos limit) {
    enum class State { Text, Tag, Value, Comment, CData, Instruction } state = State::Text;
    char quote = 0;
    std::vector<Scan> out;
    FilePos pos{1, 1};
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (continuation(c)) continue; // one entry per character
        if (pos.line > limit.line || (pos.line == limit.line && pos.column > limit.column)) break;
        if (out.size() >= 1024) // only the last characters before the error matter
            out.erase(out.begin(), out.begin() + 512);
        out.push_back({i, pos, state == State::Value});
        const std::string_view rest = text.substr(i);
        switch (state) {
        case State::Text:
            if (rest.starts_with("<!--"))
                state = State::Comment;
            else if (rest.starts_with("<![CDATA["))
                state = State::CData;
            else if (rest.starts_with("<?"))
                state = State::Instruction;
            else if (c == '<')
                state = State::Tag;
            break;
        case State::Tag:
            if (c == '"' || c == '\'') {
                quote = c;
                state = State::Value;
            } else if (c == '>') {
                state = State::Text;
            }
            break;
        case State::Value:
            if (c == quote) state = State::Tag;
            break;
        case State::Comment:
            if (rest.starts_with("-->")) state = State::Text;
            break;
        case State::CData:
            if (rest.starts_with("]]>")) state = State::Text;
            break;
        case State::Instruction:
            if (rest.starts_with("?>")) state = State::Text;
            break;
        }
        if (c == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if (c != '\r') {
            ++pos.column;
        }
    }
    return out;
}

// Whether `&` at `at` starts a reference XML knows: &name; or &#...;.
bool startsReference(std::string_view text, std::size_t at) {
    std::size_t i = at + 1;
    if (i < text.size() && text[i] == '#') ++i;
    const std::size_t nameStart = i;
    while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
        ++i;
    return i > nameStart && i < text.size() && text[i] == ';';
}

} // namespace

std::optional<XmlSyntaxHelp> explainXmlSyntaxError(std::string_view text, FilePos reported) {
    const std::vector<Scan> scanned = scanUpTo(text, reported);
    // The parser stops a few characters past the cause (after `& `, or after
    // the name of an unfinished `&amp b`): look back a little on its line.
    constexpr std::size_t kLookBack = 40;
    for (std::size_t k = 0; k < scanned.size() && k < kLookBack; ++k) {
        const Scan& s = scanned[scanned.size() - 1 - k];
        if (s.pos.line + 1 < reported.line) break; // its line, or the one before
        if (!s.inAttributeValue) continue;
        const char c = text[s.offset];
        if (c == '&' && !startsReference(text, s.offset)) {
            // `&&` (logical and) is two: the fix takes the whole run.
            std::size_t first = scanned.size() - 1 - k;
            while (first > 0 && text[scanned[first - 1].offset] == '&' &&
                   scanned[first - 1].inAttributeValue)
                --first;
            std::size_t run = 0;
            while (scanned[first].offset + run < text.size() &&
                   text[scanned[first].offset + run] == '&')
                ++run;
            std::string escaped;
            for (std::size_t r = 0; r < run; ++r)
                escaped += "&amp;";
            const FilePos at = scanned[first].pos;
            const std::string both = escaped + " for " + std::string(run, '&');
            return XmlSyntaxHelp{
                at, "write " + both + " inside an XML attribute (a bare & starts a reference)",
                "or use the ClassicVRML encoding (.x3dv), where a formula is written as it is",
                DiagnosticFix{at, int(run), escaped, "write " + both}};
        }
        if (c == '<')
            return XmlSyntaxHelp{
                s.pos, "write &lt; for < inside an XML attribute (< starts a tag)",
                "or use the ClassicVRML encoding (.x3dv), where a formula is written as it is",
                DiagnosticFix{s.pos, 1, "&lt;", "write &lt; for <"}};
    }
    return std::nullopt;
}

} // namespace fl::scene
