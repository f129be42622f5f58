#pragma once
// Where things are in a rendered picture, for tests that judge motion and
// colour by pixels rather than by "the images differ" (issue 18). Header
// only; the viewer, window and command-line tests share it.
#include <QColor>
#include <QImage>

#include <algorithm>
#include <array>
#include <cstddef>

namespace fl::testing {

// The share of pixels in columns [x0, x1) for which `test` holds.
template <class Test>
double share(const QImage& image, int x0, int x1, Test test) {
    std::size_t n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = x0; x < x1; ++x)
            n += test(image.pixelColor(x, y)) ? 1 : 0;
    return double(n) / double(image.height() * (x1 - x0));
}

template <class Test>
double share(const QImage& image, Test test) {
    return share(image, 0, image.width(), test);
}

// Pixels covered in one picture and not in the other (the background is the
// top-left corner's colour), within columns [x0, x1).
inline double movedShare(const QImage& a, const QImage& b, int x0, int x1) {
    const QColor background = a.pixelColor(0, 0);
    std::size_t moved = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = x0; x < x1; ++x)
            moved += (a.pixelColor(x, y) != background) != (b.pixelColor(x, y) != background);
    return double(moved) / double(a.height() * (x1 - x0));
}

// The centre (x, y) and count of the pixels coloured red-to-green rather
// than grey or blue: where a green-to-red shape (the bouncing sphere) is.
inline std::array<double, 3> colouredCentre(const QImage& image) {
    double sx = 0, sy = 0, n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::max(c.redF(), c.greenF()) > c.blueF() + 0.25) sx += x, sy += y, ++n;
        }
    return {n > 0 ? sx / n : 0, n > 0 ? sy / n : 0, n};
}

} // namespace fl::testing
