#include "text_outliner.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGlyphRun>
#include <QGuiApplication>
#include <QPainterPath>
#include <QRawFont>
#include <QTextLayout>

namespace fl::viewer {
namespace {

// Glyphs are outlined this many pixels high and scaled to the requested
// size: curves are flattened relative to the outline's coordinates, so a
// large em keeps them smooth at any size.
constexpr double kEm = 256;

// X3D's family names are generic ("SERIF", "SANS", "TYPEWRITER"), anything
// else a font family; fontconfig resolves the generic names.
QFont fontFor(const mesh::FontRequest& request) {
    QStringList families;
    QFont::StyleHint hint = QFont::Serif;
    bool hinted = false;
    for (const std::string& f : request.family) {
        if (f == "SERIF") {
            families << QStringLiteral("serif");
            if (!hinted) hint = QFont::Serif;
        } else if (f == "SANS") {
            families << QStringLiteral("sans-serif");
            if (!hinted) hint = QFont::SansSerif;
        } else if (f == "TYPEWRITER") {
            families << QStringLiteral("monospace");
            if (!hinted) hint = QFont::TypeWriter;
        } else if (!f.empty()) {
            families << QString::fromStdString(f);
            continue;
        }
        hinted = true;
    }
    if (families.isEmpty()) families << QStringLiteral("serif");
    QFont font;
    font.setFamilies(families);
    font.setStyleHint(hint);
    font.setPixelSize(int(kEm));
    font.setBold(request.style == "BOLD" || request.style == "BOLDITALIC");
    font.setItalic(request.style == "ITALIC" || request.style == "BOLDITALIC");
    font.setKerning(true);
    return font;
}

mesh::OutlinedLine outline(const std::string& utf8, const mesh::FontRequest& request) {
    mesh::OutlinedLine out;
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance())) {
        out.problem = "no fonts here (Qt's font database needs a QGuiApplication)";
        return out;
    }
    const QFont font = fontFor(request);
    const QString text = QString::fromUtf8(utf8.data(), qsizetype(utf8.size()));
    const double scale = request.size / kEm;
    // One line laid out by Qt (shaping, kerning), then each glyph outlined
    // on its own, so the kernel can fill glyph by glyph.
    QTextLayout layout(text, font);
    layout.beginLayout();
    QTextLine line = layout.createLine();
    layout.endLayout();
    if (!line.isValid()) return out;
    const double baseline = line.ascent();
    for (const QGlyphRun& run : layout.glyphRuns()) {
        const QRawFont raw = run.rawFont();
        const QList<quint32> glyphs = run.glyphIndexes();
        const QList<QPointF> positions = run.positions();
        for (qsizetype g = 0; g < glyphs.size() && g < positions.size(); ++g) {
            QPainterPath path = raw.pathForGlyph(glyphs[g]);
            if (path.isEmpty()) continue;
            path.translate(positions[g]);
            out.glyphStarts.push_back(out.contours.size());
            // Flattened in font pixels (Qt's curve tolerance is half a unit
            // of the coordinates it flattens in), then scaled; Qt's y grows
            // downwards, X3D's upwards from the baseline.
            for (const QPolygonF& polygon : path.toSubpathPolygons()) {
                mesh::Contour2 c;
                c.reserve(std::size_t(polygon.size()));
                for (const QPointF& p : polygon)
                    c.push_back({p.x() * scale, (baseline - p.y()) * scale});
                out.contours.push_back(std::move(c));
            }
        }
    }
    const QFontMetricsF metrics(font);
    out.advance = line.naturalTextWidth() * scale;
    out.ascent = metrics.ascent() * scale;
    out.descent = metrics.descent() * scale;
    return out;
}

} // namespace

mesh::TextOutliner qtTextOutliner() {
    return outline;
}

} // namespace fl::viewer
