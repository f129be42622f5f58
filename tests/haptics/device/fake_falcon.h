#pragma once
// A Falcon behind the transport seam, for tests: its boot loader (handshake,
// ready byte, echoed upload) and its firmware (one reading packet answering
// each command packet, encoders from an arm position through the real
// inverse kinematics). The device layer's codec, kinematics, homing and
// firmware sequence all run for real against it.
#include "haptics/device/falcon_ftdi.h"
#include "haptics/device/falcon_kinematics.h"
#include "haptics/device/falcon_packet.h"
#include "haptics/device/falcon_transport.h"

#include <cmath>
#include <deque>
#include <vector>

namespace fl::haptics::falcon::testing {

struct FakeFalconState {
    bool firmwareRunning = false;
    std::vector<std::uint8_t> expectedImage; // firmware the fake accepts
    std::vector<std::uint8_t> received;      // what the upload sent
    int handshakeFailures = 0;               // handshakes to ignore first
    long corruptEchoAt = -1;                 // echo this upload byte wrongly, once
    int uploads = 0;                         // ready bytes seen

    field::Vec3 arm = kWorkspaceCentre; // kinematic frame
    std::uint8_t homedAxes = 0;
    std::uint8_t buttons = 0;
    int dropAnswers = 0; // command packets to leave unanswered
    bool broken = false; // every transfer fails
    std::vector<FalconCommand> commands;
    int badPackets = 0;

    std::uint16_t baud = 0;
    bool dtrHigh = false;
    bool handshaken = false;
    bool uploading = false;
    std::deque<std::uint8_t> toHost;
};

class FakeFalcon : public FalconTransport {
  public:
    explicit FakeFalcon(FakeFalconState& state) : s_(state) {}

    bool control(std::uint8_t request, std::uint16_t value) override {
        if (s_.broken) return false;
        if (request == ftdi::kBaudRate) {
            s_.baud = value;
            // The firmware starts when the host moves to the run rate after
            // an upload of the expected image.
            if (value == ftdi::kBaudFalconRun && s_.uploading) {
                s_.uploading = false;
                s_.handshaken = false;
                s_.firmwareRunning = s_.received == s_.expectedImage;
            }
        }
        if (request == ftdi::kModemControl && (value & 0x0100)) {
            // DTR rising resets the microcontroller into its boot loader.
            const bool high = value & 1;
            if (high && !s_.dtrHigh) {
                s_.firmwareRunning = false;
                s_.uploading = false;
                s_.handshaken = false;
            }
            s_.dtrHigh = high;
        }
        if (request == ftdi::kReset && value == ftdi::kPurgeReceive) s_.toHost.clear();
        return true;
    }

    bool write(std::span<const std::uint8_t> bytes, int) override {
        if (s_.broken) return false;
        if (s_.firmwareRunning) return answer(bytes);
        if (s_.uploading) {
            for (std::uint8_t b : bytes) {
                const long at = long(s_.received.size());
                s_.received.push_back(b);
                const bool corrupt = at == s_.corruptEchoAt;
                if (corrupt) s_.corruptEchoAt = -1;
                s_.toHost.push_back(corrupt ? std::uint8_t(b ^ 0xFF) : b);
            }
            return true;
        }
        const std::vector<std::uint8_t> hello{0x0A, 0x43, 0x0D};
        if (s_.baud == ftdi::kBaud9600 && s_.dtrHigh &&
            std::vector<std::uint8_t>(bytes.begin(), bytes.end()) == hello) {
            if (s_.handshakeFailures > 0) {
                --s_.handshakeFailures;
                return true;
            }
            for (std::uint8_t b : {0x0A, 0x44, 0x2C, 0x0D})
                s_.toHost.push_back(b);
            s_.handshaken = true;
            return true;
        }
        if (s_.handshaken && s_.baud == ftdi::kBaud140000 && bytes.size() == 1 &&
            bytes[0] == 0x41) {
            s_.toHost.push_back(0x41);
            s_.uploading = true;
            s_.received.clear();
            ++s_.uploads;
        }
        return true; // a boot loader ignores what it does not understand
    }

    int read(std::span<std::uint8_t> buffer, int) override {
        if (s_.broken) return -1;
        const std::size_t n = std::min(buffer.size(), s_.toHost.size());
        for (std::size_t i = 0; i < n; ++i) {
            buffer[i] = s_.toHost.front();
            s_.toHost.pop_front();
        }
        return int(n);
    }

    std::string lastError() const override { return s_.broken ? "cable pulled" : ""; }

  private:
    bool answer(std::span<const std::uint8_t> bytes) {
        const auto command = decodeCommand(bytes);
        if (!command) {
            ++s_.badPackets;
            return true;
        }
        s_.commands.push_back(*command);
        if (s_.dropAnswers > 0) {
            --s_.dropAnswers;
            return true;
        }
        FalconReading r;
        const auto angles = thighAngles(s_.arm);
        for (int i = 0; i < 3; ++i)
            r.encoders[i] = std::int16_t(std::lround(angleToEncoder((*angles)[i])));
        r.gripButtons = s_.buttons;
        r.homedAxes = command->homingMode ? s_.homedAxes : 0;
        const Packet p = encodeReading(r);
        s_.toHost.insert(s_.toHost.end(), p.begin(), p.end());
        return true;
    }

    FakeFalconState& s_;
};

} // namespace fl::haptics::falcon::testing
