#pragma once
// Device logs (docs/haptics.md, "Device logs"): what a device said, one
// sample a line, as text a person can read and diff. DeviceRecorder writes
// them, ReplayDevice plays them back. The parser takes files from anyone:
// hostile input gets an error naming file:line:column and what to do, never
// a crash, and the sizes below bound what it will read.
#include "device/haptic_device.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::haptics {

inline constexpr std::string_view kDeviceLogMagic = "functionlab-device-log";
inline constexpr int kDeviceLogVersion = 1;
inline constexpr std::size_t kMaxDeviceLogBytes = 64u << 20;   // 64 MiB
inline constexpr std::size_t kMaxDeviceLogLine = 4096;         // bytes, without the newline
inline constexpr std::size_t kMaxDeviceLogSamples = 4'000'000; // an hour at 1 kHz
inline constexpr std::size_t kMaxDeviceNameBytes = 200;
// A recorded orientation is a unit quaternion written to round-trip
// precision; one further from unit length than this is a mistake.
inline constexpr double kQuaternionNormTolerance = 1e-3;

struct DeviceLog {
    std::string deviceName;             // from the `device` line; may be empty
    std::optional<DeviceLimits> limits; // from the `limits` line
    // True when the samples carried their velocity; otherwise it was
    // estimated from the positions (central differences) when reading.
    bool hasVelocity = false;
    std::vector<DeviceState> samples; // time strictly increasing
};

struct LogError {
    std::string file;
    int line = 0;   // 1-based
    int column = 0; // 1-based, in bytes
    std::string message;
    // "probe.log:12:7: message"
    std::string text() const;
};

struct LogRead {
    std::optional<DeviceLog> log; // exactly one of the two is set
    std::optional<LogError> error;
};

// `fileName` only names the text in errors.
LogRead parseDeviceLog(std::string_view text, std::string_view fileName);
// Refuses files over kMaxDeviceLogBytes before reading them.
LogRead readDeviceLog(const std::filesystem::path& path);

// Writing: the header (magic and version, a comment naming the columns,
// `device` and `limits` lines, each only when known), then one line per sample. Numbers are
// written in the shortest form that reads back to the same double, so
// write-then-read gives back every bit.
std::string formatLogHeader(std::string_view deviceName, const std::optional<DeviceLimits>& limits,
                            bool withVelocity);
std::string formatLogSample(const DeviceState& state, bool withVelocity);
std::string formatDeviceLog(const DeviceLog& log);

// The velocity of each sample estimated from its neighbours' positions
// (central differences; one-sided at the ends; zero for a lone sample).
void estimateVelocities(std::vector<DeviceState>& samples);

} // namespace fl::haptics
