#pragma once
// Records any device: a HapticDevice that forwards to another and writes
// each state it reads as a line of a device log (docs/haptics.md, "Device
// logs"), velocity included. Commands pass through unrecorded: a log is
// what the hand did, replayed against any scene.
//
// Lines go into the stream's buffer; the stream reaches the disk when its
// buffer fills, at flush() and when the recorder is destroyed. A state
// whose time is not after the last one written (a device that repeated
// itself) or that has a value which is not finite is not written, so the
// log always reads back; skipped() counts those.
#include "device/haptic_device.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>

namespace fl::haptics {

class DeviceRecorder : public HapticDevice {
  public:
    // Records `device` into `out`; both must outlive the recorder. Writes the
    // header at once.
    DeviceRecorder(HapticDevice& device, std::ostream& out);
    // Takes `device` over and records it into a new file at `path`; none
    // with the reason in *error when the file cannot be created.
    static std::unique_ptr<DeviceRecorder> toFile(std::unique_ptr<HapticDevice> device,
                                                  const std::filesystem::path& path,
                                                  std::string* error = nullptr);
    ~DeviceRecorder() override;

    void flush();
    // False once a write to the stream failed (disk full, file closed).
    bool ok() const;
    std::uint64_t written() const { return written_; }
    std::uint64_t skipped() const { return skipped_; }
    HapticDevice& device() { return device_; }

    // HapticDevice: the recorded device's own answers.
    std::string name() const override { return device_.name(); }
    DeviceLimits limits() const override { return device_.limits(); }
    bool rendersForce() const override { return device_.rendersForce(); }
    std::optional<DeviceState> read() override;
    void command(const field::Vec3& force, const field::Vec3& torque) override;

  private:
    DeviceRecorder(std::unique_ptr<HapticDevice> device, std::unique_ptr<std::ostream> out);

    std::unique_ptr<HapticDevice> ownedDevice_;
    std::unique_ptr<std::ostream> ownedOut_;
    HapticDevice& device_;
    std::ostream& out_;
    bool anyWritten_ = false;
    double lastTime_ = 0;
    std::uint64_t written_ = 0;
    std::uint64_t skipped_ = 0;
};

} // namespace fl::haptics
