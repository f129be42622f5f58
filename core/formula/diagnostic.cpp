#include "diagnostic.h"

#include <algorithm>

namespace fl::formula {

const char* severityName(Severity s) {
    switch (s) {
    case Severity::Error:
        return "error";
    case Severity::Warning:
        return "warning";
    case Severity::Note:
        return "note";
    }
    return "error";
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

// The source line and a caret line under the diagnostic's range.
static std::string caretLines(std::string_view text, const Diagnostic& d);

namespace {

std::string_view lineText(std::string_view source, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        std::size_t nl = source.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    std::size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    std::string_view text = source.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
}

} // namespace

std::string formatDiagnostic(const Diagnostic& d, std::string_view source,
                             std::string_view origin) {
    std::string out;
    if (!origin.empty()) {
        out += origin;
        out += ':';
    }
    out += std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.column) + ": ";
    out += severityName(d.severity);
    out += ": ";
    out += d.message;
    if (!d.suggestion.empty()) {
        out += " (";
        out += d.suggestion;
        out += ")";
    }
    out += '\n';
    std::string_view text = lineText(source, d.range.begin.line);
    if (text.empty() && source.empty()) return out;
    // Long lines are shown as a window around the column, so a diagnostic's
    // size does not grow with the line.
    constexpr int kWindow = 120;
    int col0 = std::max(1, d.range.begin.column);
    if (static_cast<int>(text.size()) > kWindow) {
        int first = std::clamp(col0 - 1 - kWindow / 2, 0, static_cast<int>(text.size()) - kWindow);
        text = text.substr(static_cast<std::size_t>(first), kWindow);
        Diagnostic shifted = d;
        shifted.range.begin.column -= first;
        shifted.range.end.column = shifted.range.end.line == d.range.begin.line
                                       ? std::min(shifted.range.end.column - first, kWindow + 1)
                                       : shifted.range.end.column;
        return out + caretLines(text, shifted);
    }
    return out + caretLines(text, d);
}

static std::string caretLines(std::string_view text, const Diagnostic& d) {
    std::string out;
    out += "  ";
    // control characters would garble a terminal: show them as '?'
    for (char c : text)
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f ? '?' : c;
    out += "\n  ";
    int col = std::max(1, d.range.begin.column);
    for (int i = 1; i < col; ++i)
        out += (i - 1 < int(text.size()) && text[i - 1] == '\t') ? '\t' : ' ';
    int width = 1;
    if (d.range.end.line == d.range.begin.line && d.range.end.column > col)
        width = d.range.end.column - col;
    else if (d.range.end.line > d.range.begin.line)
        width = std::max(1, int(text.size()) - col + 1);
    out += '^';
    for (int i = 1; i < width; ++i)
        out += '~';
    out += '\n';
    return out;
}

} // namespace fl::formula
