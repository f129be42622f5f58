// `functionlab haptics record FILE --out LOG (--path ... | --device N)`: a
// device session against a scene, written as a device log (docs/haptics.md,
// "Device logs") that `haptics replay` plays back.
#include "cli/commands.h"
#include "cli/haptics_options.h"
#include "platform/exit_codes.h"

#include "haptics/device/device_enumeration.h"
#include "haptics/device/device_recorder.h"
#include "haptics/device/simulated_device.h"
#include "haptics/probe.h"
#include "haptics/servo_loop.h"
#include "haptics/tangible_scene.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

namespace fl::cli {

const CommandSpec& hapticsRecordSpec() {
    static const CommandSpec spec{
        .name = "haptics record",
        .summary = "record a device session against a scene into a device log",
        .synopsis = {"haptics record FILE --out LOG --path X,Y,Z:X,Y,Z[:...] [--duration S]\n"
                     "[--time T]",
                     "haptics record FILE --out LOG --device N [--seconds S] [--firmware F]"},
        .description =
            "With --path: the simulated device walks the path on the simulated clock, as\n"
            "`haptics probe` does, and every state it reports is written to LOG. With\n"
            "--device: device N of `haptics devices` (from 1) is opened and felt in real\n"
            "time for S seconds through the servo loop, and recorded. The log is the\n"
            "documented text format; `haptics replay FILE LOG` plays it back.\n",
        .positionals = {{.name = "FILE", .help = "the scene to touch"}},
        .options = {{.name = "out",
                     .kind = OptionKind::Path,
                     .valueName = "LOG",
                     .help = "the device log to write"},
                    hapticsPathOption("the simulated tool's polyline in scene coordinates"),
                    hapticsDurationOption(),
                    hapticsTimeOption(),
                    {.name = "device",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "record device N of `haptics devices` in real time",
                     .min = 1,
                     .max = 64},
                    {.name = "seconds",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "how long to record a real device",
                     .defaultValue = "10",
                     .min = 0,
                     .max = 3600,
                     .minExclusive = true},
                    {.name = "firmware",
                     .kind = OptionKind::Path,
                     .valueName = "F",
                     .help = "a Novint Falcon's firmware file (you supply it; FunctionLab does "
                             "not ship it)"}},
        .exitStatus = "0 recorded, 1 the scene, the device or the log failed, 2 usage error",
    };
    return spec;
}

namespace {

int recordSimulated(const scene::Scene& scene, const ParsedArgs& a) {
    std::string error;
    const auto points = haptics::parsePathSpec(a.text("path"), &error);
    if (!points) return usageError(hapticsRecordSpec(), "--path: " + error, std::cerr);
    haptics::ProbeOptions o;
    o.duration = a.number("duration", 1);
    o.startTime = a.number("time", 0);
    auto path = haptics::PolylinePath::make(*points, o.duration, &error);
    if (!path) return usageError(hapticsRecordSpec(), "--path: " + error, std::cerr);
    haptics::SimulatedDevice device;
    device.followPath(std::move(*path));
    std::ofstream out(a.text("out"), std::ios::binary);
    if (!out) {
        std::cerr << "functionlab haptics record: cannot write " << a.text("out") << "\n";
        return kExitDiagnostic;
    }
    haptics::DeviceRecorder recorder(device, out);
    const auto run = haptics::runOnSimulatedClock(
        scene, recorder, [&](double t) { return device.setTime(t); }, o, &error);
    if (!run) return usageError(hapticsRecordSpec(), error, std::cerr);
    recorder.flush();
    if (!recorder.ok()) {
        std::cerr << "functionlab haptics record: writing " << a.text("out") << " failed\n";
        return kExitDiagnostic;
    }
    std::printf("recorded %llu states of the simulated device into %s\n",
                static_cast<unsigned long long>(recorder.written()), a.text("out").c_str());
    return kExitOk;
}

int recordDevice(const scene::Scene& scene, const ParsedArgs& a) {
    std::vector<std::string> notes;
    const auto devices = haptics::listDevices(&notes);
    const auto n = std::size_t(a.number("device", 1));
    if (n > devices.size()) {
        std::cerr << "functionlab haptics record: there is no device " << n << "; "
                  << devices.size() << " connected (see `functionlab haptics devices`)\n";
        return kExitDiagnostic;
    }
    haptics::OpenOptions open;
    open.falconFirmware = a.text("firmware");
    std::string error;
    auto device = haptics::openDevice(devices[n - 1], open, &error);
    if (!device) {
        std::cerr << "functionlab haptics record: " << error << "\n";
        return kExitDiagnostic;
    }
    auto recorder = haptics::DeviceRecorder::toFile(std::move(device), a.text("out"), &error);
    if (!recorder) {
        std::cerr << "functionlab haptics record: " << error << "\n";
        return kExitDiagnostic;
    }
    haptics::ServoLoop loop(*recorder, {});
    loop.setScene(std::make_shared<const haptics::TangibleScene>(
        haptics::makeTangibleScene(scene, a.number("time", 0))));
    loop.start();
    std::this_thread::sleep_for(std::chrono::duration<double>(a.number("seconds", 10)));
    loop.stop();
    recorder->flush();
    std::printf("recorded %llu states of %s into %s\n",
                static_cast<unsigned long long>(recorder->written()),
                recorder->device().name().c_str(), a.text("out").c_str());
    return recorder->ok() ? kExitOk : kExitDiagnostic;
}

} // namespace

int hapticsRecordCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(hapticsRecordSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (!a->given("out")) return usageError(hapticsRecordSpec(), "--out is required", std::cerr);
    if (a->given("path") == a->given("device"))
        return usageError(hapticsRecordSpec(), "give either --path or --device", std::cerr);
    const auto scene = hapticsSceneOrExplain(a->positionals().front(), std::cerr);
    if (!scene) return kExitDiagnostic;
    return a->given("path") ? recordSimulated(*scene, *a) : recordDevice(*scene, *a);
}

} // namespace fl::cli
