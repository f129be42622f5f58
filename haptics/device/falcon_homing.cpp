#include "device/falcon_homing.h"

namespace fl::haptics::falcon {

void FalconHoming::update(const FalconReading& reading, double time) {
    if (!started_) {
        started_ = true;
        since_ = time;
    }
    now_ = time;
    homedAxes_ = reading.homedAxes & 7;
    if (phase_ == HomingPhase::Homing && reading.allHomed()) {
        phase_ = HomingPhase::Homed;
        afterLoss_ = false;
    } else if (phase_ == HomingPhase::Homed && !reading.allHomed()) {
        phase_ = HomingPhase::Homing;
        since_ = time;
        ++losses_;
        afterLoss_ = true;
    }
}

std::string FalconHoming::instruction() const {
    if (homed()) return {};
    std::string missing;
    int count = 0;
    for (int leg = 0; leg < 3; ++leg) {
        if (homedAxes_ & (1 << leg)) continue;
        if (count++) missing += " and ";
        missing += std::to_string(leg + 1);
    }
    std::string text =
        afterLoss_ ? "The Falcon lost its homing (a power or USB reset?). " : std::string();
    text += "Home the Falcon: move the grip slowly all the way in and out, then around its "
            "whole range, until the light turns green (leg" +
            std::string(count > 1 ? "s " : " ") + missing + " still to find " +
            (count > 1 ? "their" : "its") + " index).";
    if (started_ && now_ - since_ >= kPatienceSeconds)
        text += " Still not homed after " + std::to_string(int(kPatienceSeconds)) +
                " s: push the grip fully in until it stops, pull it fully out, and check that "
                "the Falcon's power supply is plugged in (homing needs the motors).";
    return text;
}

} // namespace fl::haptics::falcon
