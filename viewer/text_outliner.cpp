#include "text_outliner.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QPainterPath>

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
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance())) return out;
    const QFont font = fontFor(request);
    const QString text = QString::fromUtf8(utf8.data(), qsizetype(utf8.size()));
    QPainterPath path;
    path.addText(0, 0, font, text);
    const double scale = request.size / kEm;
    // Flattened in font pixels (Qt's curve tolerance is half a unit of the
    // coordinates it flattens in), then scaled; Qt's y grows downwards from
    // the baseline, X3D's upwards.
    for (const QPolygonF& polygon : path.toSubpathPolygons()) {
        mesh::Contour2 c;
        c.reserve(std::size_t(polygon.size()));
        for (const QPointF& p : polygon)
            c.push_back({p.x() * scale, -p.y() * scale});
        out.contours.push_back(std::move(c));
    }
    const QFontMetricsF metrics(font);
    out.advance = metrics.horizontalAdvance(text) * scale;
    out.ascent = metrics.ascent() * scale;
    out.descent = metrics.descent() * scale;
    return out;
}

} // namespace

mesh::TextOutliner qtTextOutliner() {
    return outline;
}

} // namespace fl::viewer
