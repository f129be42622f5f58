// `functionlab haptics devices [--json]`: the haptic devices connected, and
// for each one present but not accessible what to do (docs/haptics.md).
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "haptics/device/device_enumeration.h"

#include <iostream>

namespace fl::cli {

const CommandSpec& hapticsDevicesSpec() {
    static const CommandSpec spec{
        .name = "haptics devices",
        .summary = "list the haptic devices connected, and how to reach those that are not",
        .synopsis = {"haptics devices [--json]"},
        .description =
            "Lists the SpaceMouse (hidapi) and Novint Falcon (libusb) devices connected. A\n"
            "device present but not accessible says why and what to do (usually the udev\n"
            "rule haptics/device/70-functionlab-haptics.rules). No device: an empty list.\n",
        .options = {{.name = "json",
                     .help = "print one object: {\"devices\": [{\"kind\", \"name\", \"vendor_id\", "
                             "\"product_id\", \"path\", \"accessible\", \"message\"}], "
                             "\"notes\": [...]}"}},
        .exitStatus = "0 listed (devices or none), 2 usage error",
    };
    return spec;
}

int hapticsDevicesCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(hapticsDevicesSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    std::vector<std::string> notes;
    const auto devices = haptics::listDevices(&notes);
    if (a->flag("json"))
        std::cout << haptics::deviceListingJson(devices, notes) << "\n";
    else
        std::cout << haptics::formatDeviceListing(devices, notes);
    return kExitOk;
}

} // namespace fl::cli
