#include "device/falcon_firmware.h"

#include "device/falcon_ftdi.h"
#include "device/falcon_packet.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <system_error>

namespace fl::haptics::falcon {

namespace {

constexpr int kHandshakeTries = 100;
constexpr int kHandshakeTimeoutMs = 100;
constexpr int kEchoTimeoutMs = 1000;
constexpr int kRunProbeTries = 20;
constexpr int kRunProbeTimeoutMs = 10;

// The boot loader answers "\nC\r" with "\nD,\r".
constexpr std::array<std::uint8_t, 3> kHello{0x0A, 0x43, 0x0D};
constexpr std::array<std::uint8_t, 4> kHelloReply{0x0A, 0x44, 0x2C, 0x0D};
// At the fast rate it echoes an 'A'.
constexpr std::uint8_t kReady = 0x41;

bool fail(std::string* error, std::string message) {
    if (error) *error = std::move(message);
    return false;
}

std::string withCause(const std::string& what, const FalconTransport& t) {
    const std::string cause = t.lastError();
    return cause.empty() ? what : what + " (" + cause + ")";
}

const char* kReplug = ": unplug the Falcon's USB and power, plug them back in and try again";

bool slowLine(FalconTransport& t) {
    using namespace ftdi;
    return purge(t) && t.control(kLatencyTimer, 16) && t.control(kBaudRate, kBaud9600) &&
           t.control(kLineProperties, kEightDataBitsNoParityOneStop) &&
           t.control(kFlowControl, 0) && t.control(kModemControl, kRtsLow) &&
           t.control(kModemControl, kDtrLow) && t.control(kModemControl, kDtrHigh);
}

bool handshake(FalconTransport& t) {
    std::array<std::uint8_t, 64> buffer{};
    for (int i = 0; i < kHandshakeTries; ++i) {
        if (!t.write(kHello, kHandshakeTimeoutMs)) return false;
        const int n = t.read(buffer, kHandshakeTimeoutMs);
        if (n < 0) return false;
        const auto got = std::span(buffer).first(std::size_t(n));
        if (std::search(got.begin(), got.end(), kHelloReply.begin(), kHelloReply.end()) !=
            got.end())
            return true;
    }
    return false;
}

// Reads exactly `expected.size()` bytes and compares them with `expected`.
// Returns the offset of the first difference, expected.size() when equal,
// or -1 when the bytes did not come.
long readEcho(FalconTransport& t, std::span<const std::uint8_t> expected) {
    std::array<std::uint8_t, 64> buffer{};
    std::size_t got = 0;
    while (got < expected.size()) {
        const std::size_t want = std::min(buffer.size(), expected.size() - got);
        const int n = t.read(std::span(buffer).first(want), kEchoTimeoutMs);
        if (n <= 0) return -1;
        for (int i = 0; i < n; ++i)
            if (buffer[std::size_t(i)] != expected[got + std::size_t(i)]) return long(got) + i;
        got += std::size_t(n);
    }
    return long(got);
}

} // namespace

std::optional<std::vector<std::uint8_t>> readFirmwareFile(const std::filesystem::path& path,
                                                          std::string* error) {
    const std::string where = "the Falcon firmware file " + path.string();
    const char* fix = ": FunctionLab does not ship Novint's firmware; pass the path of your copy "
                      "(from Novint's Falcon driver or SDK, e.g. nvent_firmware.bin)";
    if (path.empty()) {
        fail(error, std::string("no Falcon firmware file given") + fix);
        return std::nullopt;
    }
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        fail(error, where + " does not exist" + fix);
        return std::nullopt;
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) {
        fail(error, where + " cannot be read: " + ec.message());
        return std::nullopt;
    }
    if (size == 0 || size > kMaxFirmwareBytes) {
        fail(error, where + " is " + std::to_string(size) +
                        " bytes; Falcon firmware is between 1 byte and 64 KiB (Novint's is about "
                        "8 KiB): check that this is the firmware file");
        return std::nullopt;
    }
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
        fail(error, where + " cannot be read (permissions?)");
        return std::nullopt;
    }
    return bytes;
}

bool uploadFirmware(FalconTransport& t, std::span<const std::uint8_t> image, std::string* error) {
    if (image.empty()) return fail(error, "the Falcon firmware image is empty");
    if (!slowLine(t))
        return fail(error, withCause("could not set the Falcon's serial line for the upload", t) +
                               kReplug);
    if (!handshake(t))
        return fail(error, withCause("the Falcon's boot loader did not answer the handshake", t) +
                               kReplug);
    using namespace ftdi;
    if (!t.control(kModemControl, kDtrLow) || !t.control(kBaudRate, kBaud140000))
        return fail(error,
                    withCause("could not switch the Falcon to the upload speed", t) + kReplug);
    const std::array<std::uint8_t, 1> ready{kReady};
    if (!t.write(ready, kEchoTimeoutMs) || readEcho(t, ready) != 1)
        return fail(error,
                    withCause("the Falcon's boot loader did not echo its ready byte", t) + kReplug);
    for (std::size_t offset = 0; offset < image.size(); offset += kFirmwareChunk) {
        const auto chunk = image.subspan(offset, std::min(kFirmwareChunk, image.size() - offset));
        if (!t.write(chunk, kEchoTimeoutMs))
            return fail(
                error,
                withCause("writing the firmware failed at byte " + std::to_string(offset), t) +
                    kReplug);
        const long echoed = readEcho(t, chunk);
        if (echoed < 0)
            return fail(error, withCause("the Falcon stopped echoing the firmware at byte " +
                                             std::to_string(offset),
                                         t) +
                                   kReplug);
        if (std::size_t(echoed) != chunk.size())
            return fail(error, "the Falcon echoed a different byte at " +
                                   std::to_string(offset + std::size_t(echoed)) +
                                   " of the firmware: the upload was corrupted" + kReplug);
    }
    if (!enterRunMode(t))
        return fail(error,
                    withCause("could not switch the Falcon to run mode after the upload", t) +
                        kReplug);
    return true;
}

bool loadFirmware(FalconTransport& t, std::span<const std::uint8_t> image, int attempts,
                  std::string* error) {
    std::string last = "no upload was attempted";
    for (int i = 0; i < std::max(attempts, 1); ++i) {
        if (uploadFirmware(t, image, &last)) return true;
    }
    return fail(error, last + " (" + std::to_string(std::max(attempts, 1)) + " attempts)");
}

bool firmwareAnswers(FalconTransport& t) {
    ReadingFramer framer;
    const Packet zero = encodeCommand({});
    std::array<std::uint8_t, 64> buffer{};
    for (int i = 0; i < kRunProbeTries; ++i) {
        if (!t.write(zero, kRunProbeTimeoutMs)) return false;
        const int n = t.read(buffer, kRunProbeTimeoutMs);
        if (n < 0) return false;
        framer.push(std::span(buffer).first(std::size_t(n)));
        if (framer.latest()) return true;
    }
    return false;
}

} // namespace fl::haptics::falcon
