// libFuzzer target: a device log from anyone (`haptics replay FILE`). No
// crash, no hang; every error names a line of the text and a column on it;
// a log that reads has finite samples in increasing time order, and writing
// it back reads back to the very same text (write-then-read identity).
#include "haptics/device/device_log.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto read = fl::haptics::parseDeviceLog(text, "fuzz.log");
    if (read.log.has_value() == read.error.has_value()) std::abort();
    if (read.error) {
        int lines = 1;
        for (char c : text)
            lines += c == '\n';
        if (read.error->line < 1 || read.error->line > lines || read.error->column < 1)
            std::abort();
        return 0;
    }
    const auto& samples = read.log->samples;
    if (samples.empty()) std::abort();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (!std::isfinite(samples[i].time) || !fl::field::isFinite(samples[i].position) ||
            !fl::field::isFinite(samples[i].velocity))
            std::abort();
        if (i > 0 && !(samples[i].time > samples[i - 1].time)) std::abort();
    }
    const std::string written = fl::haptics::formatDeviceLog(*read.log);
    const auto again = fl::haptics::parseDeviceLog(written, "again.log");
    if (!again.log || fl::haptics::formatDeviceLog(*again.log) != written) std::abort();
    return 0;
}
