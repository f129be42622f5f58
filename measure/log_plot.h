#pragma once
// One small SVG chart for the benchmarks' documentation pictures: series of
// points on log-log axes (decades as grid lines), each a coloured line with
// its points (a tooltip each) and a legend entry. Titles, labels and names
// are escaped as XML text (scene::xmlEscape).
#include <string>
#include <vector>

namespace fl::measure {

struct PlotPoint {
    double x = 0, y = 0; // both > 0 (others are left out)
    std::string label;   // the point's tooltip
};

struct PlotSeries {
    std::string name, colour; // "#1f77b4"
    std::vector<PlotPoint> points;
};

std::string logLogPlotSvg(const std::string& title, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<PlotSeries>& series);

} // namespace fl::measure
