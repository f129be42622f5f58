// libFuzzer target: bytes from a Novint Falcon's USB (hostile until
// checked). The input is read both as one packet and as a stream through
// the framer. No crash, no read out of bounds; a packet that decodes
// encodes back to the same bytes (byte 14, of unknown meaning, aside); the
// framer finds no more packets than the stream can hold.
#include "haptics/device/falcon_packet.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <span>

using namespace fl::haptics::falcon;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    if (const auto reading = decodeReading(bytes)) {
        Packet again = encodeReading(*reading);
        again[14] = bytes[14];
        if (!std::equal(again.begin(), again.end(), bytes.begin())) std::abort();
    }
    if (const auto command = decodeCommand(bytes)) {
        Packet again = encodeCommand(*command);
        again[14] = bytes[14];
        if (!std::equal(again.begin(), again.end(), bytes.begin())) std::abort();
    }
    ReadingFramer framer;
    // Split where the data says, so reads of every size are tried.
    const std::size_t cut = size ? data[0] % (size + 1) : 0;
    const std::size_t found = framer.push(bytes.first(cut)) + framer.push(bytes.subspan(cut));
    if (found > size / kPacketSize || found != framer.packets()) std::abort();
    if (found && !framer.latest()) std::abort();
    if (framer.discarded() + found * kPacketSize > size) std::abort();
    return 0;
}
