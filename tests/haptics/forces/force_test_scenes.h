#pragma once
// Small tangible scenes for the force-model tests, in ClassicVRML: one
// FShape with a definition and whatever physics a test needs.
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace fl::haptics::test {

struct Physics {
    std::string friction = {}; // formulas; empty: not there
    std::string tension = {};
    std::string density = {};
    std::string force = {}; // "fx = ...; fy = ...; fz = ...;"
};

inline std::string tangibleScene(const std::string& definition, const Physics& p, double box = 2) {
    const std::string b = std::to_string(box);
    const std::string domain =
        " domainMin -" + b + " -" + b + " -" + b + " domainMax " + b + " " + b + " " + b + " ";
    auto node = [&](const char* type, const std::string& formula) {
        return std::string(type) + " { definition \"" + formula + "\"" + domain + "}";
    };
    std::string physics = "FPhysics { ";
    if (!p.friction.empty() || !p.tension.empty()) {
        physics += "surface FSurface { ";
        if (!p.friction.empty()) physics += "friction " + node("FFriction", p.friction) + " ";
        if (!p.tension.empty()) physics += "tension " + node("FTension", p.tension) + " ";
        physics += "} ";
    }
    if (!p.density.empty()) physics += "density " + node("FDensity", p.density) + " ";
    if (!p.force.empty()) physics += "force " + node("FForce", p.force) + " ";
    physics += "}";
    return "#X3D V3.3 utf8\nPROFILE Immersive\nDEF S FShape {\n  geometry FGeometry { "
           "definition \"" +
           definition + "\"" + domain + "}\n  physics " + physics + "\n}\n";
}

inline std::shared_ptr<const scene::Scene> readScene(const std::string& text) {
    scene::ReadResult r = scene::readSceneBytes(text, "test.x3dv");
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << d.message << " in\n" << text;
    EXPECT_TRUE(r.ok());
    return std::shared_ptr<const scene::Scene>(std::move(r.scene));
}

} // namespace fl::haptics::test
