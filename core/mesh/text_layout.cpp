#include "text_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

struct Bounds {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
};

Bounds boundsOf(const Contour2& c) {
    Bounds b;
    for (const Point2& p : c) {
        b.x0 = std::min(b.x0, p[0]);
        b.x1 = std::max(b.x1, p[0]);
        b.y0 = std::min(b.y0, p[1]);
        b.y1 = std::max(b.y1, p[1]);
    }
    return b;
}

// Fills the contours and appends the triangles at z = 0. Contours are
// filled in groups whose x ranges overlap (in practice a glyph each), which
// keeps the fill's edge-crossing search small on long lines.
void appendFilled(std::vector<Contour2> contours, Mesh& m) {
    std::sort(contours.begin(), contours.end(),
              [](const Contour2& a, const Contour2& b) { return boundsOf(a).x0 < boundsOf(b).x0; });
    std::size_t start = 0;
    while (start < contours.size()) {
        double reach = boundsOf(contours[start]).x1;
        std::size_t end = start + 1;
        while (end < contours.size() && boundsOf(contours[end]).x0 <= reach)
            reach = std::max(reach, boundsOf(contours[end++]).x1);
        const std::vector<Contour2> group(contours.begin() + std::ptrdiff_t(start),
                                          contours.begin() + std::ptrdiff_t(end));
        const PlanarFill f = fillContours(group, FillRule::NonZero);
        const auto base = std::uint32_t(m.positions.size());
        for (const Point2& p : f.points) {
            m.positions.push_back({float(p[0]), float(p[1]), 0});
            m.normals.push_back({0, 0, 1});
        }
        for (const Triangle& t : f.triangles)
            m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        start = end;
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

} // namespace

Mesh textMesh(const TextLayout& layout, const TextOutliner& outliner) {
    Mesh m;
    if (!outliner || layout.font.size <= 0 || !std::isfinite(layout.font.size)) return m;
    const double size = layout.font.size;
    const double lineStep = size * layout.spacing;
    const auto& major = layout.justifyMajor;
    const auto& minor = layout.justifyMinor;

    if (!layout.horizontal) {
        // Columns of characters, one per string, read downwards (or
        // upwards), the columns going right (or left).
        for (std::size_t i = 0; i < layout.lines.size(); ++i) {
            const double x = (layout.leftToRight ? 1.0 : -1.0) * double(i) * lineStep;
            const auto chars = codePoints(layout.lines[i]);
            const double columnLength = double(chars.size()) * size;
            double top = 0; // major BEGIN/FIRST: the column starts at y = 0
            if (major == "MIDDLE") top = columnLength / 2;
            if (major == "END") top = columnLength;
            if (!layout.topToBottom) top -= columnLength;
            for (std::size_t k = 0; k < chars.size(); ++k) {
                OutlinedLine glyph = outliner(chars[k], layout.font);
                const double row = layout.topToBottom ? double(k) : double(chars.size() - 1 - k);
                place(glyph.contours, 1, x - glyph.advance / 2,
                      top - (row + 1) * size + glyph.descent);
                appendFilled(std::move(glyph.contours), m);
            }
        }
        return m;
    }

    std::vector<OutlinedLine> lines;
    double ascent = 0, descent = 0, widest = 0;
    for (std::size_t i = 0; i < layout.lines.size(); ++i) {
        const std::string text =
            layout.leftToRight ? layout.lines[i] : reversedCodePoints(layout.lines[i]);
        OutlinedLine l = outliner(text, layout.font);
        if (i < layout.length.size() && layout.length[i] > 0 && l.advance > 0) {
            place(l.contours, layout.length[i] / l.advance, 0, 0);
            l.advance = layout.length[i];
        }
        ascent = std::max(ascent, l.ascent);
        descent = std::max(descent, l.descent);
        widest = std::max(widest, l.advance);
        lines.push_back(std::move(l));
    }
    const double squeeze =
        layout.maxExtent > 0 && widest > layout.maxExtent ? layout.maxExtent / widest : 1.0;

    // Minor justification: where the block sits across the lines.
    const double block = double(lines.empty() ? 0 : lines.size() - 1) * lineStep;
    const double direction = layout.topToBottom ? -1.0 : 1.0; // from one baseline to the next
    double firstBaseline = 0;                                 // FIRST
    const double top = layout.topToBottom ? ascent : ascent + block;
    const double bottom = layout.topToBottom ? -(block + descent) : -descent;
    if (minor == "BEGIN") firstBaseline = layout.topToBottom ? -ascent : descent;
    if (minor == "END") firstBaseline = layout.topToBottom ? block + descent : -(block + ascent);
    if (minor == "MIDDLE") firstBaseline = -(top + bottom) / 2;

    for (std::size_t i = 0; i < lines.size(); ++i) {
        OutlinedLine& l = lines[i];
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
        appendFilled(std::move(l.contours), m);
    }
    return m;
}

} // namespace fl::mesh
