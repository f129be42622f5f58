#include "text_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace fl::mesh {
namespace {

// A UTF-8 line split into its characters (a malformed byte stays one).
std::vector<std::string> codePoints(const std::string& s) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const std::size_t n = std::min<std::size_t>(b >= 0xF0   ? 4
                                                    : b >= 0xE0 ? 3
                                                    : b >= 0xC0 ? 2
                                                                : 1,
                                                    s.size() - i);
        out.push_back(s.substr(i, n));
        i += n;
    }
    return out;
}

// Right-to-left text: the characters in reverse order.
std::string reversedCodePoints(const std::string& s) {
    const auto chars = codePoints(s);
    std::string out;
    for (auto it = chars.rbegin(); it != chars.rend(); ++it)
        out += *it;
    return out;
}

// Fills each glyph's contours and appends the triangles at z = 0.
void appendFilled(const OutlinedLine& line, Mesh& m, std::string& problem) {
    std::vector<std::size_t> starts = line.glyphStarts;
    if (starts.empty() || starts.front() != 0) starts.insert(starts.begin(), 0);
    starts.push_back(line.contours.size());
    for (std::size_t g = 0; g + 1 < starts.size(); ++g) {
        const std::size_t begin = std::min(starts[g], line.contours.size());
        const std::size_t end = std::clamp(starts[g + 1], begin, line.contours.size());
        if (begin == end) continue;
        const std::vector<Contour2> glyph(line.contours.begin() + std::ptrdiff_t(begin),
                                          line.contours.begin() + std::ptrdiff_t(end));
        const PlanarFill f = fillContours(glyph, FillRule::NonZero);
        if (!f.problem.empty()) problem = f.problem;
        const auto base = std::uint32_t(m.positions.size());
        for (const Point2& p : f.points) {
            m.positions.push_back({float(p[0]), float(p[1]), 0});
            m.normals.push_back({0, 0, 1});
        }
        for (const Triangle& t : f.triangles)
            m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    }
}

// Moves and scales contours: x' = x * sx + dx, y' = y + dy.
void place(std::vector<Contour2>& contours, double sx, double dx, double dy) {
    for (Contour2& c : contours)
        for (Point2& p : c) {
            p[0] = p[0] * sx + dx;
            p[1] += dy;
        }
}

// The strings, cut to kMaxTextCharacters characters in all.
std::vector<std::string> limitedLines(const std::vector<std::string>& lines, bool& cut) {
    std::vector<std::string> out;
    std::size_t left = kMaxTextCharacters;
    cut = false;
    for (const std::string& line : lines) {
        auto chars = codePoints(line);
        if (chars.size() > left) {
            chars.resize(left);
            cut = true;
        }
        left -= chars.size();
        std::string kept;
        for (const std::string& c : chars)
            kept += c;
        out.push_back(std::move(kept));
        if (cut) break;
    }
    return out;
}

} // namespace

Mesh textMesh(const TextLayout& layout, const TextOutliner& outliner,
              std::vector<std::string>* warnings) {
    Mesh m;
    if (!outliner || !(layout.font.size > 0) || !std::isfinite(layout.font.size)) return m;
    const double size = layout.font.size;
    const double lineStep = size * layout.spacing;
    const auto& major = layout.justifyMajor;
    const auto& minor = layout.justifyMinor;
    bool cut = false;
    const std::vector<std::string> lines = limitedLines(layout.lines, cut);
    std::string problem;
    auto report = [&] {
        if (!warnings) return;
        if (cut)
            warnings->push_back("Text: only the first " + std::to_string(kMaxTextCharacters) +
                                " characters are drawn");
        if (!problem.empty()) warnings->push_back("Text: " + problem);
    };

    if (!layout.horizontal) {
        // Columns of characters, one per string, read downwards (or
        // upwards), the columns going right (or left). Each character is
        // outlined once.
        std::map<std::string, OutlinedLine> glyphs;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const double x = (layout.leftToRight ? 1.0 : -1.0) * double(i) * lineStep;
            const auto chars = codePoints(lines[i]);
            const double columnLength = double(chars.size()) * size;
            // Where the column's top is: major BEGIN/FIRST start it at y = 0
            // (downwards) or end it there (upwards), MIDDLE centres it.
            double top = 0;
            if (major == "MIDDLE") top = columnLength / 2;
            if (major == "END") top = columnLength;
            if (!layout.topToBottom) top = columnLength - top;
            for (std::size_t k = 0; k < chars.size(); ++k) {
                auto found = glyphs.find(chars[k]);
                if (found == glyphs.end())
                    found = glyphs.emplace(chars[k], outliner(chars[k], layout.font)).first;
                OutlinedLine glyph = found->second;
                if (!glyph.problem.empty()) problem = glyph.problem;
                const double row = layout.topToBottom ? double(k) : double(chars.size() - 1 - k);
                place(glyph.contours, 1, x - glyph.advance / 2,
                      top - (row + 1) * size + glyph.descent);
                appendFilled(glyph, m, problem);
            }
        }
        report();
        return m;
    }

    std::vector<OutlinedLine> outlined;
    double ascent = 0, descent = 0, widest = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string text = layout.leftToRight ? lines[i] : reversedCodePoints(lines[i]);
        OutlinedLine l = outliner(text, layout.font);
        if (!l.problem.empty()) problem = l.problem;
        if (i < layout.length.size() && layout.length[i] > 0 && l.advance > 0) {
            place(l.contours, layout.length[i] / l.advance, 0, 0);
            l.advance = layout.length[i];
        }
        ascent = std::max(ascent, l.ascent);
        descent = std::max(descent, l.descent);
        widest = std::max(widest, l.advance);
        outlined.push_back(std::move(l));
    }
    const double squeeze =
        layout.maxExtent > 0 && widest > layout.maxExtent ? layout.maxExtent / widest : 1.0;

    // Minor justification: where the block sits across the lines.
    const double block = double(outlined.empty() ? 0 : outlined.size() - 1) * lineStep;
    const double direction = layout.topToBottom ? -1.0 : 1.0; // from one baseline to the next
    double firstBaseline = 0;                                 // FIRST
    const double top = layout.topToBottom ? ascent : ascent + block;
    const double bottom = layout.topToBottom ? -(block + descent) : -descent;
    if (minor == "BEGIN") firstBaseline = layout.topToBottom ? -ascent : descent;
    if (minor == "END") firstBaseline = layout.topToBottom ? block + descent : -(block + ascent);
    if (minor == "MIDDLE") firstBaseline = -(top + bottom) / 2;

    for (std::size_t i = 0; i < outlined.size(); ++i) {
        OutlinedLine& l = outlined[i];
        const double width = l.advance * squeeze;
        // Major justification: BEGIN (and FIRST) start at x = 0 in the
        // reading direction; END ends there; MIDDLE centres on it.
        double x = 0;
        if (major == "MIDDLE")
            x = -width / 2;
        else if (major == "END")
            x = layout.leftToRight ? -width : 0;
        else
            x = layout.leftToRight ? 0 : -width;
        place(l.contours, squeeze, x, firstBaseline + direction * double(i) * lineStep);
        appendFilled(l, m, problem);
    }
    report();
    return m;
}

} // namespace fl::mesh
