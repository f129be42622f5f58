#include "device/falcon_ftdi.h"

#include <algorithm>

namespace fl::haptics::falcon::ftdi {

void appendPayload(std::span<const std::uint8_t> transfer, std::vector<std::uint8_t>& out) {
    for (std::size_t start = 0; start < transfer.size(); start += kMaxPacket) {
        const std::size_t end = std::min(start + kMaxPacket, transfer.size());
        if (end - start <= kStatusBytes) continue;
        out.insert(out.end(), transfer.begin() + std::ptrdiff_t(start + kStatusBytes),
                   transfer.begin() + std::ptrdiff_t(end));
    }
}

bool purge(FalconTransport& transport) {
    return transport.control(kReset, kPurgeReceive) && transport.control(kReset, kPurgeTransmit);
}

bool enterRunMode(FalconTransport& transport) {
    return transport.control(kLatencyTimer, 1) && transport.control(kBaudRate, kBaudFalconRun) &&
           purge(transport);
}

} // namespace fl::haptics::falcon::ftdi
