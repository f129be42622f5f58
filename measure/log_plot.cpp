#include "log_plot.h"

#include "scene/scene_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fl::measure {
namespace {

std::string num(double v, const char* format = "%.4g") {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

} // namespace

std::string logLogPlotSvg(const std::string& title, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<PlotSeries>& series) {
    const double W = 640, H = 420, left = 70, right = 20, top = 40, bottom = 50;
    double xLo = 1e300, xHi = 0, yLo = 1e300, yHi = 0;
    for (const PlotSeries& s : series)
        for (const PlotPoint& p : s.points) {
            if (!(p.x > 0 && p.y > 0)) continue;
            xLo = std::min(xLo, p.x), xHi = std::max(xHi, p.x);
            yLo = std::min(yLo, p.y), yHi = std::max(yHi, p.y);
        }
    if (xHi <= 0) return "<svg xmlns='http://www.w3.org/2000/svg'/>\n";
    const double x0 = std::floor(std::log10(xLo)),
                 x1 = std::max(x0 + 1, std::ceil(std::log10(xHi)));
    const double y0 = std::floor(std::log10(yLo)),
                 y1 = std::max(y0 + 1, std::ceil(std::log10(yHi)));
    auto X = [&](double v) { return left + (std::log10(v) - x0) / (x1 - x0) * (W - left - right); };
    auto Y = [&](double v) {
        return H - bottom - (std::log10(v) - y0) / (y1 - y0) * (H - top - bottom);
    };
    std::string s = "<svg xmlns='http://www.w3.org/2000/svg' width='" + num(W) + "' height='" +
                    num(H) +
                    "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' "
                    "fill='white'/>\n";
    s += "<text x='" + num(W / 2) + "' y='22' text-anchor='middle' font-size='14'>" +
         scene::xmlEscape(title) + "</text>\n";
    for (double d = x0; d <= x1; ++d) {
        const double x = X(std::pow(10, d));
        s += "<line x1='" + num(x) + "' y1='" + num(top) + "' x2='" + num(x) + "' y2='" +
             num(H - bottom) + "' stroke='#ddd'/><text x='" + num(x) + "' y='" +
             num(H - bottom + 16) + "' text-anchor='middle'>1e" + num(d) + "</text>\n";
    }
    for (double d = y0; d <= y1; ++d) {
        const double y = Y(std::pow(10, d));
        s += "<line x1='" + num(left) + "' y1='" + num(y) + "' x2='" + num(W - right) + "' y2='" +
             num(y) + "' stroke='#ddd'/><text x='" + num(left - 6) + "' y='" + num(y + 4) +
             "' text-anchor='end'>1e" + num(d) + "</text>\n";
    }
    s += "<text x='" + num((left + W - right) / 2) + "' y='" + num(H - 12) +
         "' text-anchor='middle'>" + scene::xmlEscape(xLabel) + "</text>\n";
    s += "<text transform='translate(16 " + num((top + H - bottom) / 2) +
         ") rotate(-90)' text-anchor='middle'>" + scene::xmlEscape(yLabel) + "</text>\n";
    int legend = 0;
    for (const PlotSeries& se : series) {
        std::string points;
        for (const PlotPoint& p : se.points) {
            if (!(p.x > 0 && p.y > 0)) continue;
            points += num(X(p.x)) + "," + num(Y(p.y)) + " ";
            s += "<circle cx='" + num(X(p.x)) + "' cy='" + num(Y(p.y)) + "' r='3' fill='" +
                 se.colour + "'><title>" + scene::xmlEscape(p.label) + "</title></circle>\n";
        }
        s += "<polyline fill='none' stroke='" + se.colour + "' stroke-width='2' points='" + points +
             "'/>\n";
        const double ly = top + 14 + 18 * legend++;
        s += "<line x1='" + num(W - right - 190) + "' y1='" + num(ly - 4) + "' x2='" +
             num(W - right - 165) + "' y2='" + num(ly - 4) + "' stroke='" + se.colour +
             "' stroke-width='2'/><text x='" + num(W - right - 160) + "' y='" + num(ly) + "'>" +
             scene::xmlEscape(se.name) + "</text>\n";
    }
    return s + "</svg>\n";
}

} // namespace fl::measure
