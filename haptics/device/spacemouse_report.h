#pragma once
// 3Dconnexion SpaceMouse HID input reports (wave2.md: OCCT, MeshLib and
// spacenavd read them the same way). hidapi hands a report over with its
// report id first:
//   id 1, 7 bytes:  translation x, y, z as little-endian int16
//   id 1, 13 bytes: translation, then rotation (newer models: one report)
//   id 2, 7 bytes:  rotation about x, y, z
//   id 3, 2+ bytes: buttons, a little-endian bit mask (up to 32 buttons)
// Axes read about ±350 at full deflection. The device's own axes: x to the
// right, y towards the user, z down; rotations about those axes.
// Reports are hostile until checked: a short or unknown report is ignored,
// never read past its end.
#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace fl::haptics::spacemouse {

using Axes = std::array<std::int16_t, 3>;

struct Report {
    std::optional<Axes> translation;
    std::optional<Axes> rotation;
    std::optional<std::uint32_t> buttons;
};

// None for a report that carries no motion or buttons, or is too short.
std::optional<Report> parseReport(std::span<const std::uint8_t> report);

struct InputSettings {
    int deadZone = 8;       // counts around zero that read as zero (a puck never rests at 0)
    double fullScale = 350; // counts that read as full deflection (±1)
};

// A raw axis as −1…1: zero inside the dead zone, then rising linearly from
// the dead zone's edge so small motions start smoothly; clamped at ±1.
double normalizedAxis(int counts, const InputSettings& settings);

// What the SpaceMouse says now: reports update parts of it (translation,
// rotation and buttons come separately on older models).
class InputState {
  public:
    void apply(const Report& report);
    const Axes& translation() const { return translation_; }
    const Axes& rotation() const { return rotation_; }
    std::uint32_t buttons() const { return buttons_; }

  private:
    Axes translation_{};
    Axes rotation_{};
    std::uint32_t buttons_ = 0;
};

} // namespace fl::haptics::spacemouse
