// libFuzzer target: HID reports from a SpaceMouse (hostile until checked).
// The input is cut into reports at lengths it names itself, as hid_read
// would hand them over. No crash, no read out of bounds; a report that
// parses says something, and the tool it drives stays finite and inside
// its workspace whatever the axes say.
#include "haptics/device/spacemouse_report.h"
#include "haptics/device/spacemouse_tool.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <span>

using namespace fl::haptics::spacemouse;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    InputState input;
    SpaceMouseTool tool;
    std::size_t at = 0;
    while (at < size) {
        // First byte: the report's length (0–63), then the report itself.
        const std::size_t length = std::min<std::size_t>(bytes[at] % 64, size - at - 1);
        const auto report = parseReport(bytes.subspan(at + 1, length));
        at += 1 + length;
        if (!report) continue;
        if (!report->translation && !report->rotation && !report->buttons) std::abort();
        input.apply(*report);
        tool.step(toDeviceFrame(input, InputSettings{}), 0.008);
        if (!fl::field::isFinite(tool.position())) std::abort();
        if (fl::field::length(tool.position()) > tool.settings().workspaceRadius * (1 + 1e-12))
            std::abort();
    }
    return 0;
}
