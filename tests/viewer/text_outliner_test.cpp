// Glyph outlines from Qt's font engine (text_outliner.h): real fonts are
// found for X3D's generic families, glyph holes come as their own contours,
// sizes scale, and bold is heavier than plain.
#include "viewer/text_outliner.h"

#include "mesh/planar_fill.h"

#include <gtest/gtest.h>

using namespace fl;

namespace {

double filledArea(const mesh::OutlinedLine& l) {
    const mesh::PlanarFill f = mesh::fillContours(l.contours, mesh::FillRule::NonZero);
    double a = 0;
    for (const auto& t : f.triangles) {
        const auto& p = f.points[t[0]];
        const auto& q = f.points[t[1]];
        const auto& r = f.points[t[2]];
        a += ((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1])) / 2;
    }
    return a;
}

mesh::FontRequest font(const char* family, const char* style = "PLAIN", double size = 1) {
    mesh::FontRequest f;
    f.family = {family};
    f.style = style;
    f.size = size;
    return f;
}

} // namespace

TEST(TextOutliner, GenericFamiliesHaveGlyphsWithHoles) {
    const mesh::TextOutliner outline = viewer::qtTextOutliner();
    for (const char* family : {"SERIF", "SANS", "TYPEWRITER"}) {
        const mesh::OutlinedLine o = outline("O", font(family));
        ASSERT_GE(o.contours.size(), 2u) << family << ": an O has an outside and a hole";
        EXPECT_GT(o.advance, 0.3) << family;
        EXPECT_GT(o.ascent, 0.5) << family;
        EXPECT_GT(o.descent, 0.0) << family;
        const double a = filledArea(o);
        EXPECT_GT(a, 0.05) << family;
        EXPECT_LT(a, o.advance * o.ascent) << family << ": the hole is left out";
        // Glyphs stand on the baseline, y up.
        double top = -1e9;
        for (const auto& c : o.contours)
            for (const auto& p : c)
                top = std::max(top, p[1]);
        EXPECT_GT(top, 0.5) << family;
    }
}

TEST(TextOutliner, SizeScalesAndBoldIsHeavier) {
    const mesh::TextOutliner outline = viewer::qtTextOutliner();
    const mesh::OutlinedLine small = outline("Lab", font("SANS", "PLAIN", 1));
    const mesh::OutlinedLine large = outline("Lab", font("SANS", "PLAIN", 3));
    EXPECT_NEAR(large.advance, 3 * small.advance, 0.05 * large.advance);
    EXPECT_NEAR(filledArea(large), 9 * filledArea(small), 0.05 * filledArea(large));
    EXPECT_GT(filledArea(outline("Lab", font("SANS", "BOLD"))), 1.1 * filledArea(small));
    EXPECT_TRUE(outline("", font("SANS")).contours.empty());
    EXPECT_TRUE(outline(" ", font("SANS")).contours.empty());
}
