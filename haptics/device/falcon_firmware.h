#pragma once
// Loading Novint's firmware into a Falcon. A Falcon boots with only a boot
// loader; the firmware that speaks the 16-byte packets has to be uploaded
// after every power-on. That firmware is Novint's, under its non-commercial
// licence: FunctionLab never ships it; the user points us at their copy
// (from Novint's driver or SDK). The sequence (wave2.md; studied from
// libnifalcon, our own code): slow serial line, a handshake with the boot
// loader, the fast line, then the image in small chunks, each echoed back
// and compared byte for byte. Uploads are flaky, so the whole sequence is
// retried.
#include "device/falcon_transport.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fl::haptics::falcon {

inline constexpr std::size_t kMaxFirmwareBytes = 64 * 1024; // Novint's files are about 8 KiB
// Data bytes per chunk: a full-speed USB packet holds 64 bytes, and the
// echo comes back in packets that each lose two bytes to FTDI status.
inline constexpr std::size_t kFirmwareChunk = 62;

// The user's firmware file, or none with what to do in *error (missing,
// unreadable, empty, too large).
std::optional<std::vector<std::uint8_t>> readFirmwareFile(const std::filesystem::path& path,
                                                          std::string* error);

// One upload; leaves the chip in run mode on success.
bool uploadFirmware(FalconTransport& transport, std::span<const std::uint8_t> image,
                    std::string* error);
// Up to `attempts` uploads; *error is the last failure's.
bool loadFirmware(FalconTransport& transport, std::span<const std::uint8_t> image, int attempts,
                  std::string* error);

// True when firmware is running: a zero-force packet gets a well-formed
// packet back (a few tries, a few milliseconds each). The chip must be in
// run mode (ftdi::enterRunMode).
bool firmwareAnswers(FalconTransport& transport);

} // namespace fl::haptics::falcon
