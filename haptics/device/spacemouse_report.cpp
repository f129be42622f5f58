#include "device/spacemouse_report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fl::haptics::spacemouse {

namespace {

constexpr std::uint8_t kTranslationReport = 1;
constexpr std::uint8_t kRotationReport = 2;
constexpr std::uint8_t kButtonReport = 3;
constexpr std::size_t kAxesReportSize = 7;      // id + 3 × int16
constexpr std::size_t kCombinedReportSize = 13; // id + 6 × int16

Axes axesAt(std::span<const std::uint8_t> bytes) {
    Axes axes{};
    for (std::size_t i = 0; i < 3; ++i)
        axes[i] = static_cast<std::int16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
    return axes;
}

} // namespace

std::optional<Report> parseReport(std::span<const std::uint8_t> report) {
    if (report.empty()) return std::nullopt;
    Report r;
    switch (report[0]) {
    case kTranslationReport:
        if (report.size() >= kCombinedReportSize) {
            r.translation = axesAt(report.subspan(1, 6));
            r.rotation = axesAt(report.subspan(7, 6));
        } else if (report.size() >= kAxesReportSize) {
            r.translation = axesAt(report.subspan(1, 6));
        } else {
            return std::nullopt;
        }
        return r;
    case kRotationReport:
        if (report.size() < kAxesReportSize) return std::nullopt;
        r.rotation = axesAt(report.subspan(1, 6));
        return r;
    case kButtonReport: {
        if (report.size() < 2) return std::nullopt;
        std::uint32_t mask = 0;
        const std::size_t bytes = std::min<std::size_t>(report.size() - 1, 4);
        for (std::size_t i = 0; i < bytes; ++i)
            mask |= std::uint32_t(report[1 + i]) << (8 * i);
        r.buttons = mask;
        return r;
    }
    default:
        return std::nullopt;
    }
}

double normalizedAxis(int counts, const InputSettings& settings) {
    const double dead = std::max(0, settings.deadZone);
    const double magnitude = std::abs(double(counts));
    if (magnitude <= dead) return 0;
    const double span = settings.fullScale - dead;
    if (!(span > 0)) return counts > 0 ? 1 : -1;
    const double value = std::min(1.0, (magnitude - dead) / span);
    return counts > 0 ? value : -value;
}

void InputState::apply(const Report& report) {
    if (report.translation) translation_ = *report.translation;
    if (report.rotation) rotation_ = *report.rotation;
    if (report.buttons) buttons_ = *report.buttons;
}

} // namespace fl::haptics::spacemouse
