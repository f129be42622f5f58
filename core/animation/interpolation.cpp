#include "interpolation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace fl::animation {
namespace {

struct Segment {
    std::size_t index = 0; // blend keyValue[index] ..
    double s = 0;          // .. towards keyValue[index + 1] by s in [0, 1]
};

// X3D: below the first key the first value, above the last the last; where
// keys repeat (a jump) the later value wins from that key on.
Segment findSegment(std::span<const double> key, double f) {
    if (key.size() < 2 || !(f > key.front())) return {0, 0};
    if (f >= key.back()) return {key.size() - 1, 0};
    const auto upper = std::upper_bound(key.begin(), key.end(), f);
    const std::size_t i = std::size_t(upper - key.begin()) - 1;
    const double span = key[i + 1] - key[i];
    return {i, span > 0 ? (f - key[i]) / span : 0};
}

double lerp(double a, double b, double s) {
    return a + (b - a) * s;
}

std::array<double, 4> toQuaternion(std::span<const double, 4> r) {
    double x = r[0], y = r[1], z = r[2];
    const double n = std::sqrt(x * x + y * y + z * z);
    if (!(n > 0)) return {0, 0, 0, 1}; // no axis: no rotation
    x /= n, y /= n, z /= n;
    const double h = r[3] / 2;
    const double s = std::sin(h);
    return {x * s, y * s, z * s, std::cos(h)};
}

std::vector<double> fromQuaternion(std::array<double, 4> q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q)
        c /= n;
    const double sinHalf = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    if (sinHalf < 1e-15) return {0, 0, 1, 0};
    const double angle = 2 * std::atan2(sinHalf, q[3]);
    return {q[0] / sinHalf, q[1] / sinHalf, q[2] / sinHalf, angle};
}

std::array<double, 3> unit(std::span<const double> v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0)) return {0, 0, 0};
    return {v[0] / n, v[1] / n, v[2] / n};
}

std::array<double, 3> slerpUnit(std::span<const double> rawA, std::span<const double> rawB,
                                double s) {
    const std::array<double, 3> a = unit(rawA), b = unit(rawB);
    const double dot = std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0);
    const double theta = std::acos(dot);
    std::array<double, 3> r{};
    if (theta < 1e-9) {
        for (int k = 0; k < 3; ++k)
            r[k] = lerp(a[k], b[k], s);
    } else {
        const double wa = std::sin((1 - s) * theta) / std::sin(theta);
        const double wb = std::sin(s * theta) / std::sin(theta);
        for (int k = 0; k < 3; ++k)
            r[k] = wa * a[k] + wb * b[k];
    }
    const double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (n > 0)
        for (double& c : r)
            c /= n;
    return r;
}

} // namespace

std::optional<InterpolatorKind> interpolatorKind(scene::NodeKind node) {
    using scene::NodeKind;
    switch (node) {
    case NodeKind::ScalarInterpolator:
        return InterpolatorKind::Scalar;
    case NodeKind::PositionInterpolator:
        return InterpolatorKind::Position;
    case NodeKind::PositionInterpolator2D:
        return InterpolatorKind::Position2D;
    case NodeKind::ColorInterpolator:
        return InterpolatorKind::Color;
    case NodeKind::OrientationInterpolator:
        return InterpolatorKind::Orientation;
    case NodeKind::NormalInterpolator:
        return InterpolatorKind::Normal;
    case NodeKind::CoordinateInterpolator:
        return InterpolatorKind::Coordinate;
    case NodeKind::CoordinateInterpolator2D:
        return InterpolatorKind::Coordinate2D;
    case NodeKind::BooleanSequencer:
        return InterpolatorKind::Boolean;
    case NodeKind::IntegerSequencer:
        return InterpolatorKind::Integer;
    default: // the other 134 kinds interpolate nothing
        return std::nullopt;
    }
}

int numbersPerKey(InterpolatorKind kind) {
    switch (kind) {
    case InterpolatorKind::Scalar:
    case InterpolatorKind::Boolean:
    case InterpolatorKind::Integer:
        return 1;
    case InterpolatorKind::Position2D:
        return 2;
    case InterpolatorKind::Position:
    case InterpolatorKind::Color:
        return 3;
    case InterpolatorKind::Orientation:
        return 4;
    case InterpolatorKind::Normal:
    case InterpolatorKind::Coordinate:
    case InterpolatorKind::Coordinate2D:
        return 0;
    }
    return 1;
}

static int componentsOf(InterpolatorKind kind) {
    return kind == InterpolatorKind::Coordinate2D ? 2 : 3; // for the n-per-key kinds
}

std::string checkKeys(InterpolatorKind kind, std::span<const double> key,
                      std::span<const double> keyValue) {
    if (key.empty()) return "key is empty: the interpolator has no values to give";
    for (std::size_t i = 0; i < key.size(); ++i) {
        if (!std::isfinite(key[i])) return "key " + std::to_string(i) + " is not a finite number";
        if (i > 0 && key[i] < key[i - 1])
            return "key must not decrease (key " + std::to_string(i) + " is less than key " +
                   std::to_string(i - 1) + ")";
    }
    for (double v : keyValue)
        if (!std::isfinite(v)) return "keyValue holds a number that is not finite";
    const int per = numbersPerKey(kind);
    if (per > 0) {
        if (keyValue.size() != key.size() * std::size_t(per))
            return "keyValue has " + std::to_string(keyValue.size() / std::size_t(per)) +
                   " values for " + std::to_string(key.size()) + " keys; give one value per key";
        return {};
    }
    const std::size_t components = std::size_t(componentsOf(kind));
    if (keyValue.size() % (key.size() * components) != 0)
        return "keyValue has " + std::to_string(keyValue.size() / components) +
               " values, not a whole number per key (" + std::to_string(key.size()) + " keys)";
    return {};
}

std::vector<double> rgbToHsv(std::span<const double, 3> c) {
    const double mx = std::max({c[0], c[1], c[2]});
    const double mn = std::min({c[0], c[1], c[2]});
    const double d = mx - mn;
    double h = 0;
    if (d > 0) {
        if (mx == c[0])
            h = std::fmod((c[1] - c[2]) / d + 6, 6);
        else if (mx == c[1])
            h = (c[2] - c[0]) / d + 2;
        else
            h = (c[0] - c[1]) / d + 4;
        h /= 6; // hue in [0, 1)
    }
    return {h, mx > 0 ? d / mx : 0, mx};
}

std::vector<double> hsvToRgb(std::span<const double, 3> hsv) {
    const double h = (hsv[0] - std::floor(hsv[0])) * 6, s = hsv[1], v = hsv[2];
    const int sector = std::min(5, int(h));
    const double f = h - sector;
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (sector) {
    case 0:
        return {v, t, p};
    case 1:
        return {q, v, p};
    case 2:
        return {p, v, t};
    case 3:
        return {p, q, v};
    case 4:
        return {t, p, v};
    default:
        return {v, p, q};
    }
}

std::vector<double> slerpRotation(std::span<const double, 4> a, std::span<const double, 4> b,
                                  double s) {
    const std::array<double, 4> qa = toQuaternion(a);
    std::array<double, 4> qb = toQuaternion(b);
    double dot = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
    if (dot < 0) { // q and -q are the same rotation: take the shorter arc
        for (double& c : qb)
            c = -c;
        dot = -dot;
    }
    std::array<double, 4> q{};
    if (dot > 1 - 1e-12) {
        for (int k = 0; k < 4; ++k)
            q[k] = lerp(qa[k], qb[k], s);
    } else {
        const double theta = std::acos(std::min(dot, 1.0));
        const double wa = std::sin((1 - s) * theta) / std::sin(theta);
        const double wb = std::sin(s * theta) / std::sin(theta);
        for (int k = 0; k < 4; ++k)
            q[k] = wa * qa[k] + wb * qb[k];
    }
    return fromQuaternion(q);
}

std::vector<double> interpolate(InterpolatorKind kind, std::span<const double> key,
                                std::span<const double> keyValue, double fraction) {
    if (!checkKeys(kind, key, keyValue).empty()) return {};
    if (std::isnan(fraction)) fraction = 0;
    const int per = numbersPerKey(kind);
    const std::size_t width = per > 0 ? std::size_t(per) : keyValue.size() / key.size();
    const auto value = [&](std::size_t i) { return keyValue.subspan(i * width, width); };

    if (kind == InterpolatorKind::Boolean || kind == InterpolatorKind::Integer) {
        // Sequencers: the value of the last key at or before the fraction.
        const auto upper = std::upper_bound(key.begin(), key.end(), fraction);
        const std::size_t i = upper == key.begin() ? 0 : std::size_t(upper - key.begin()) - 1;
        return {keyValue[i]};
    }
    const Segment seg = findSegment(key, fraction);
    const auto a = value(seg.index);
    if (seg.s == 0 || seg.index + 1 >= key.size()) return {a.begin(), a.end()};
    const auto b = value(seg.index + 1);
    std::vector<double> out(width);
    switch (kind) {
    case InterpolatorKind::Color: {
        std::vector<double> ha = rgbToHsv(a.first<3>());
        std::vector<double> hb = rgbToHsv(b.first<3>());
        // A grey has no hue: take the other colour's so the blend does not
        // wander through unrelated hues.
        if (ha[1] == 0) ha[0] = hb[0];
        if (hb[1] == 0) hb[0] = ha[0];
        double dh = hb[0] - ha[0];
        if (dh > 0.5) dh -= 1; // the shorter way round the hue circle
        if (dh < -0.5) dh += 1;
        const std::array<double, 3> h{ha[0] + dh * seg.s, lerp(ha[1], hb[1], seg.s),
                                      lerp(ha[2], hb[2], seg.s)};
        return hsvToRgb(h);
    }
    case InterpolatorKind::Orientation:
        return slerpRotation(a.first<4>(), b.first<4>(), seg.s);
    case InterpolatorKind::Normal:
        for (std::size_t i = 0; i + 2 < width; i += 3) {
            const auto n = slerpUnit(a.subspan(i, 3), b.subspan(i, 3), seg.s);
            std::copy(n.begin(), n.end(), out.begin() + std::ptrdiff_t(i));
        }
        return out;
    default:
        for (std::size_t i = 0; i < width; ++i)
            out[i] = lerp(a[i], b[i], seg.s);
        return out;
    }
}

} // namespace fl::animation
