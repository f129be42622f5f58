#include "haptics/device/falcon_packet.h"

#include <gtest/gtest.h>

#include <string>

namespace fl::haptics::falcon {
namespace {

std::string text(const Packet& p) {
    return std::string(p.begin(), p.end());
}

Packet packetOf(std::string_view s) {
    Packet p{};
    for (std::size_t i = 0; i < kPacketSize; ++i)
        p[i] = static_cast<std::uint8_t>(s[i]);
    return p;
}

TEST(FalconPacket, IdlePacketsArePrintable) {
    EXPECT_EQ(text(encodeCommand({})), "<AAAAAAAAAAAAAA>");
    EXPECT_EQ(text(encodeReading({})), "<AAAAAAAAAAAAAA>");
}

TEST(FalconPacket, KnownEncoderValue) {
    // libnifalcon's worked example: nibbles 9, 5, A, F low first are 0xFA59,
    // which is −1447 as a signed 16-bit count.
    const auto r = decodeReading(packetOf("<JFKPAAAAAAAAAA>"));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->encoders[0], -1447);
    EXPECT_EQ(r->encoders[1], 0);
}

TEST(FalconPacket, KnownCommandBytes) {
    FalconCommand c;
    c.motors = {1, -1, 0x1234};
    c.leds = kLedRed | kLedGreen;
    c.homingMode = true;
    // 1 → B A A A; −1 = 0xFFFF → P P P P; 0x1234 → E D C B (low nibble first);
    // status 0x08 | 0x02 | 0x01 = 0x0B → 'L'.
    EXPECT_EQ(text(encodeCommand(c)), "<BAAAPPPPEDCBLA>");
}

TEST(FalconPacket, StatusByteOfAReading) {
    // 'A' + 0x5A: buttons 0xA, legs 1 and 3 homed (bits 4 and 6).
    Packet p = encodeReading({});
    p[13] = 0x41 + 0x5A;
    const auto r = decodeReading(p);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->gripButtons, 0xA);
    EXPECT_EQ(r->homedAxes, 0x5);
    EXPECT_FALSE(r->allHomed());
}

TEST(FalconPacket, EveryMotorValueRoundTripsExhaustive) {
    for (int v = -32768; v <= 32767; ++v) {
        FalconCommand c;
        c.motors = {std::int16_t(v), std::int16_t(-1 - v), std::int16_t(v ^ 0x5A5A)};
        const auto back = decodeCommand(encodeCommand(c));
        ASSERT_TRUE(back) << v;
        ASSERT_EQ(*back, c) << v;
    }
}

TEST(FalconPacket, EveryEncoderValueRoundTripsExhaustive) {
    for (int v = -32768; v <= 32767; ++v) {
        FalconReading r;
        r.encoders = {std::int16_t(v ^ 0x0F0F), std::int16_t(v), std::int16_t(-1 - v)};
        const auto back = decodeReading(encodeReading(r));
        ASSERT_TRUE(back) << v;
        ASSERT_EQ(*back, r) << v;
    }
}

TEST(FalconPacket, EveryStatusRoundTripsExhaustive) {
    for (int leds = 0; leds < 16; ++leds)
        for (int homing = 0; homing < 2; ++homing) {
            FalconCommand c;
            c.leds = std::uint8_t(leds & (kLedRed | kLedGreen | kLedBlue));
            c.homingMode = homing;
            EXPECT_EQ(decodeCommand(encodeCommand(c)), c);
        }
    for (int buttons = 0; buttons < 16; ++buttons)
        for (int homed = 0; homed < 8; ++homed) {
            FalconReading r;
            r.gripButtons = std::uint8_t(buttons);
            r.homedAxes = std::uint8_t(homed);
            EXPECT_EQ(decodeReading(encodeReading(r)), r);
        }
}

TEST(FalconPacket, BitsThatDoNotExistAreNotSent) {
    FalconCommand c;
    c.leds = 0xF1; // only red/green/blue are LEDs; 0x01 is the homing bit
    EXPECT_EQ(decodeCommand(encodeCommand(c))->leds, 0);
    EXPECT_FALSE(decodeCommand(encodeCommand(c))->homingMode);
    FalconReading r;
    r.gripButtons = 0xFF;
    r.homedAxes = 0xFF;
    EXPECT_EQ(decodeReading(encodeReading(r))->gripButtons, 0x0F);
    EXPECT_EQ(decodeReading(encodeReading(r))->homedAxes, 0x07);
}

// Every single-byte change of a valid packet either is refused or decodes
// to a reading that encodes back to exactly the changed packet (byte 14,
// whose meaning is unknown, is the one byte that may differ).
TEST(FalconPacket, EverySingleByteCorruptionIsRefusedOrExactExhaustive) {
    FalconReading base;
    base.encoders = {123, -4567, 8};
    base.gripButtons = 5;
    base.homedAxes = 3;
    const Packet good = encodeReading(base);
    int refused = 0;
    for (std::size_t i = 0; i < kPacketSize; ++i)
        for (int b = 0; b < 256; ++b) {
            Packet p = good;
            p[i] = std::uint8_t(b);
            const auto r = decodeReading(p);
            if (!r) {
                ++refused;
                continue;
            }
            Packet again = encodeReading(*r);
            if (i == 14) again[14] = p[14];
            ASSERT_EQ(again, p) << "byte " << i << " = " << b;
        }
    // Frame bytes take one value, nibbles 16, the status 128.
    EXPECT_EQ(refused, 2 * 255 + 12 * 240 + 128);
}

TEST(FalconPacket, WrongSizesAndFramesAreRefused) {
    const Packet good = encodeCommand({});
    EXPECT_FALSE(decodeCommand(std::span(good).first(15)));
    EXPECT_FALSE(decodeReading(std::span<const std::uint8_t>()));
    std::array<std::uint8_t, 17> longer{};
    std::copy(good.begin(), good.end(), longer.begin());
    EXPECT_FALSE(decodeReading(longer));
    FalconCommand c;
    c.leds = kLedBlue;
    Packet withStrayBit = encodeCommand(c);
    withStrayBit[13] += 0x10; // a bit the host never sends
    EXPECT_FALSE(decodeCommand(withStrayBit));
}

TEST(ReadingFramer, FindsPacketsHoweverTheStreamIsSplit) {
    FalconReading a;
    a.encoders = {1, 2, 3};
    FalconReading b;
    b.encoders = {-4, 5, -6};
    b.homedAxes = 7;
    std::vector<std::uint8_t> stream;
    for (const Packet& p : {encodeReading(a), encodeReading(b)})
        stream.insert(stream.end(), p.begin(), p.end());
    for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
        ReadingFramer framer;
        const std::size_t first = framer.push(std::span(stream).first(cut));
        const std::size_t second = framer.push(std::span(stream).subspan(cut));
        EXPECT_EQ(first + second, 2u) << cut;
        EXPECT_EQ(framer.latest(), b) << cut;
        EXPECT_EQ(framer.discarded(), 0u);
    }
}

TEST(ReadingFramer, ResynchronisesAfterGarbage) {
    FalconReading a;
    a.encoders = {100, 200, 300};
    const Packet p = encodeReading(a);
    // Garbage with a false start '<' and a '>' in it, then a packet cut in
    // half by another false start, then a good packet.
    std::vector<std::uint8_t> stream = {'x', '<', 'A', '>', 0, 0xFF};
    stream.insert(stream.end(), p.begin(), p.begin() + 7);
    stream.push_back('<');
    stream.insert(stream.end(), p.begin(), p.end());
    ReadingFramer framer;
    EXPECT_EQ(framer.push(stream), 1u);
    EXPECT_EQ(framer.latest(), a);
    EXPECT_EQ(framer.discarded(), stream.size() - kPacketSize);
}

TEST(ReadingFramer, KeepsAtMostOnePartialFrame) {
    ReadingFramer framer;
    std::vector<std::uint8_t> junk(10000, '<');
    EXPECT_EQ(framer.push(junk), 0u);
    EXPECT_FALSE(framer.latest());
    EXPECT_GE(framer.discarded(), junk.size() - ReadingFramer::kMaxBuffered);
    const Packet p = encodeReading({});
    EXPECT_EQ(framer.push(p), 1u);
    framer.clear();
    EXPECT_FALSE(framer.latest());
}

} // namespace
} // namespace fl::haptics::falcon
