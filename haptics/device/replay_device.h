#pragma once
// Plays a device log back (docs/haptics.md, "Device logs") on a clock the
// caller advances, like the simulated device. Replay time 0 is the log's
// first sample; between two samples position and velocity are interpolated
// linearly and the orientation along the shorter great arc (slerp), while
// buttons hold the earlier sample's value (a button is pressed or not). After
// the last sample the replay has nothing more to say: read() gives none.
// A replay moves no motors: rendersForce() is false and commands are only
// remembered (lastForce) so tests can see what the servo loop asked for.
#include "device/device_log.h"
#include "device/haptic_device.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace fl::haptics {

class ReplayDevice : public HapticDevice {
  public:
    // `source` names the replay: "Replay of <source>". A log without samples
    // replays nothing (read() gives none).
    explicit ReplayDevice(DeviceLog log, std::string source = "device log");
    // Reads and checks the log; none with the parser's file:line:column
    // message in *error when it is not a valid log.
    static std::unique_ptr<ReplayDevice> open(const std::filesystem::path& path,
                                              std::string* error = nullptr);

    // The clock, in seconds from the first sample; forwards only (an earlier
    // time, a negative step or a value that is not finite is ignored and
    // returns false).
    bool setTime(double t);
    bool advance(double dt);
    double time() const { return time_; }
    // From the first sample to the last, s.
    double duration() const;
    bool finished() const { return time_ > duration(); }

    const DeviceLog& log() const { return log_; }
    const field::Vec3& lastForce() const { return lastForce_; }

    // HapticDevice. limits() are the recorded device's when the log has a
    // `limits` line, otherwise the simulated device's.
    std::string name() const override { return "Replay of " + source_; }
    DeviceLimits limits() const override;
    bool rendersForce() const override { return false; }
    // The state at the clock's time; its `time` is the log's own time stamp
    // for that moment (first sample's time + clock).
    std::optional<DeviceState> read() override;
    void command(const field::Vec3& force, const field::Vec3& torque) override;

  private:
    DeviceLog log_;
    std::string source_;
    double time_ = 0;
    std::size_t cursor_ = 0; // the sample at or before the clock, found forwards
    field::Vec3 lastForce_{};
};

// The interpolation ReplayDevice uses, for tests and for tools that resample
// logs: the state at log time t with a.time <= t <= b.time.
DeviceState interpolate(const DeviceState& a, const DeviceState& b, double t);

} // namespace fl::haptics
