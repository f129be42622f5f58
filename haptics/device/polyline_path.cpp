#include "device/polyline_path.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace fl::haptics {

using field::Vec3;

namespace {

void fail(std::string* error, std::string message) {
    if (error) *error = std::move(message);
}

} // namespace

std::optional<PolylinePath> PolylinePath::make(std::vector<Vec3> points, double duration,
                                               std::string* error) {
    if (points.empty()) {
        fail(error, "a path needs at least one point");
        return std::nullopt;
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!field::isFinite(points[i])) {
            fail(error, "point " + std::to_string(i + 1) + " of the path is not finite");
            return std::nullopt;
        }
    }
    if (!(duration > 0) || !std::isfinite(duration)) {
        fail(error, "the path's duration must be a finite number of seconds above 0");
        return std::nullopt;
    }
    PolylinePath path(std::move(points), duration);
    if (!std::isfinite(path.length())) {
        fail(error, "the path is too long to measure (its length overflows)");
        return std::nullopt;
    }
    return path;
}

PolylinePath::PolylinePath(std::vector<Vec3> points, double duration)
    : points_(std::move(points)), duration_(duration) {
    cumulative_.reserve(points_.size());
    cumulative_.push_back(0);
    for (std::size_t i = 1; i < points_.size(); ++i)
        cumulative_.push_back(cumulative_.back() +
                              field::length(field::minus(points_[i], points_[i - 1])));
}

PathSample PolylinePath::at(double t) const {
    const double total = length();
    if (!(total > 0)) return {points_.front(), {}};
    if (!(t > 0)) return {points_.front(), {}};
    if (t >= duration_) return {points_.back(), {}};
    const double s = total * (t / duration_);
    // The first point whose arc length passes s ends the segment s lies on;
    // zero-length segments are stepped over because their ends are equal.
    const auto next = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const std::size_t end = std::min<std::size_t>(next - cumulative_.begin(), points_.size() - 1);
    const std::size_t begin = end - 1;
    const double segment = cumulative_[end] - cumulative_[begin];
    const Vec3 direction = field::minus(points_[end], points_[begin]);
    const double u = segment > 0 ? (s - cumulative_[begin]) / segment : 0;
    const Vec3 position = field::along(points_[begin], direction, u);
    const Vec3 velocity = segment > 0 ? field::scaled(direction, speed() / segment) : Vec3{};
    return {position, velocity};
}

std::optional<std::vector<Vec3>> parsePathSpec(std::string_view spec, std::string* error) {
    std::vector<Vec3> points;
    if (spec.empty()) {
        fail(error, "the path is empty: give points as X,Y,Z:X,Y,Z");
        return std::nullopt;
    }
    std::size_t start = 0;
    while (start <= spec.size()) {
        const std::size_t colon = std::min(spec.find(':', start), spec.size());
        const std::string_view point = spec.substr(start, colon - start);
        const std::string where = "point " + std::to_string(points.size() + 1);
        Vec3 p{};
        std::size_t pos = 0;
        for (int k = 0; k < 3; ++k) {
            const std::size_t comma =
                k < 2 ? std::min(point.find(',', pos), point.size()) : point.size();
            const std::string_view text = point.substr(pos, comma - pos);
            if (k < 2 && comma == point.size()) {
                fail(error, where + " \"" + std::string(point) +
                                "\" needs three coordinates X,Y,Z separated by commas");
                return std::nullopt;
            }
            const char* first = text.data();
            const char* last = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(first, last, p[k]);
            if (text.empty() || ec != std::errc() || ptr != last || !std::isfinite(p[k])) {
                fail(error, where + ": coordinate " + std::to_string(k + 1) + " \"" +
                                std::string(text) + "\" is not a finite number");
                return std::nullopt;
            }
            pos = comma + 1;
        }
        points.push_back(p);
        if (colon == spec.size()) break;
        start = colon + 1;
    }
    return points;
}

} // namespace fl::haptics
