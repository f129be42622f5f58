#include "haptics/device/spacemouse_report.h"

#include <gtest/gtest.h>

#include <vector>

namespace fl::haptics::spacemouse {
namespace {

std::vector<std::uint8_t> axesReport(std::uint8_t id, std::initializer_list<int> values) {
    std::vector<std::uint8_t> bytes{id};
    for (int v : values) {
        const auto u = static_cast<std::uint16_t>(std::int16_t(v));
        bytes.push_back(std::uint8_t(u & 0xFF));
        bytes.push_back(std::uint8_t(u >> 8));
    }
    return bytes;
}

TEST(SpaceMouseReport, TranslationReport) {
    const std::vector<std::uint8_t> bytes{1, 0x10, 0x00, 0xF0, 0xFF, 0x5E, 0x01};
    const auto r = parseReport(bytes);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->translation, (Axes{16, -16, 350}));
    EXPECT_FALSE(r->rotation);
    EXPECT_FALSE(r->buttons);
}

TEST(SpaceMouseReport, RotationReport) {
    // As captured from a SpaceNavigator: rotation about the second axis.
    const std::vector<std::uint8_t> bytes{0x02, 0x00, 0x00, 0xE2, 0xFF, 0x00, 0x00};
    const auto r = parseReport(bytes);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->rotation, (Axes{0, -30, 0}));
    EXPECT_FALSE(r->translation);
}

TEST(SpaceMouseReport, CombinedReportOfNewerModels) {
    const auto r = parseReport(axesReport(1, {-350, 0, 12, 1, -2, 32767}));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->translation, (Axes{-350, 0, 12}));
    EXPECT_EQ(r->rotation, (Axes{1, -2, 32767}));
}

TEST(SpaceMouseReport, ButtonReports) {
    EXPECT_EQ(parseReport(std::vector<std::uint8_t>{3, 0x01, 0x00})->buttons, 1u);
    EXPECT_EQ(parseReport(std::vector<std::uint8_t>{3, 0x02})->buttons, 2u);
    EXPECT_EQ(parseReport(std::vector<std::uint8_t>{3, 0x03, 0x00})->buttons, 3u);
    EXPECT_EQ(parseReport(std::vector<std::uint8_t>{3, 1, 2, 3, 4})->buttons, 0x04030201u);
    // Bytes past the 32 buttons a state holds are ignored.
    EXPECT_EQ(parseReport(std::vector<std::uint8_t>{3, 1, 2, 3, 4, 5, 6})->buttons, 0x04030201u);
}

TEST(SpaceMouseReport, ShortAndUnknownReportsAreIgnoredExhaustive) {
    EXPECT_FALSE(parseReport({}));
    const std::vector<std::uint8_t> full(64, 0x7F);
    for (std::size_t size = 1; size < 7; ++size) {
        std::vector<std::uint8_t> r(full.begin(), full.begin() + std::ptrdiff_t(size));
        r[0] = 1;
        EXPECT_FALSE(parseReport(r)) << size;
        r[0] = 2;
        EXPECT_FALSE(parseReport(r)) << size;
    }
    EXPECT_FALSE(parseReport(std::vector<std::uint8_t>{3}));
    for (int id = 0; id < 256; ++id) {
        if (id >= 1 && id <= 3) continue;
        std::vector<std::uint8_t> r = full;
        r[0] = std::uint8_t(id);
        EXPECT_FALSE(parseReport(r)) << id;
    }
    // Between the two motion sizes, report 1 is translation only.
    for (std::size_t size = 7; size < 13; ++size) {
        std::vector<std::uint8_t> r(full.begin(), full.begin() + std::ptrdiff_t(size));
        r[0] = 1;
        const auto p = parseReport(r);
        ASSERT_TRUE(p) << size;
        EXPECT_TRUE(p->translation);
        EXPECT_FALSE(p->rotation);
    }
}

TEST(SpaceMouseReport, EveryAxisValueReadsBackExhaustive) {
    for (int v = -32768; v <= 32767; ++v) {
        const auto r = parseReport(axesReport(1, {v, -1 - v, v ^ 0x3C3C, v, 7, -v - 1}));
        ASSERT_TRUE(r);
        ASSERT_EQ((*r->translation)[0], v);
        ASSERT_EQ((*r->translation)[1], -1 - v);
        ASSERT_EQ((*r->translation)[2], std::int16_t(v ^ 0x3C3C));
        ASSERT_EQ((*r->rotation)[0], v);
        ASSERT_EQ((*r->rotation)[2], std::int16_t(-v - 1));
    }
}

TEST(SpaceMouseReport, DeadZoneAndScale) {
    const InputSettings s; // dead zone 8, full scale 350
    EXPECT_EQ(normalizedAxis(0, s), 0.0);
    EXPECT_EQ(normalizedAxis(8, s), 0.0);
    EXPECT_EQ(normalizedAxis(-8, s), 0.0);
    EXPECT_DOUBLE_EQ(normalizedAxis(9, s), 1.0 / 342);
    EXPECT_DOUBLE_EQ(normalizedAxis(179, s), 0.5);
    EXPECT_DOUBLE_EQ(normalizedAxis(350, s), 1.0);
    EXPECT_DOUBLE_EQ(normalizedAxis(-350, s), -1.0);
    EXPECT_DOUBLE_EQ(normalizedAxis(32767, s), 1.0);
    EXPECT_DOUBLE_EQ(normalizedAxis(-32768, s), -1.0);
    const InputSettings broken{400, 100};
    EXPECT_EQ(normalizedAxis(300, broken), 0.0);
    EXPECT_EQ(normalizedAxis(500, broken), 1.0);
}

TEST(SpaceMouseReport, NormalisedAxisIsOddAndMonotoneProperty) {
    for (const InputSettings s : {InputSettings{}, InputSettings{0, 350}, InputSettings{20, 500}}) {
        double previous = -2;
        for (int c = -32768; c <= 32767; ++c) {
            const double v = normalizedAxis(c, s);
            ASSERT_GE(v, previous) << c;
            ASSERT_LE(std::abs(v), 1.0);
            if (c > -32768) {
                ASSERT_EQ(v, -normalizedAxis(-c, s)) << c;
            }
            previous = v;
        }
    }
}

TEST(SpaceMouseReport, OlderModelsUpdateThePartsSeparately) {
    InputState input;
    input.apply(*parseReport(axesReport(1, {10, 20, 30})));
    input.apply(*parseReport(axesReport(2, {-1, -2, -3})));
    input.apply(*parseReport(std::vector<std::uint8_t>{3, 2, 0}));
    EXPECT_EQ(input.translation(), (Axes{10, 20, 30}));
    EXPECT_EQ(input.rotation(), (Axes{-1, -2, -3}));
    EXPECT_EQ(input.buttons(), 2u);
    input.apply(*parseReport(axesReport(1, {0, 0, 0})));
    EXPECT_EQ(input.rotation(), (Axes{-1, -2, -3})) << "a translation report keeps the rotation";
}

} // namespace
} // namespace fl::haptics::spacemouse
