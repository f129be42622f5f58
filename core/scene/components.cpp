#include "components.h"

#include <array>
#include <utility>

namespace fl::scene {
namespace {

// ISO/IEC 19775-1 (X3D 3.3 and 4.0) component levels; "VRML97" is the
// component OpenVRML and others accept for the VRML97 node set, and
// "FunctionLab" is ours (docs/nodes.md).
constexpr std::array<std::pair<std::string_view, int>, 44> kComponents = {{
    {"CADGeometry", 2},
    {"Core", 2},
    {"CubeMapTexturing", 3},
    {"DIS", 2},
    {"EnvironmentalEffects", 4},
    {"EnvironmentalSensor", 3},
    {"EventUtilities", 1},
    {"Followers", 1},
    {"FunctionLab", 1},
    {"Geometry2D", 2},
    {"Geometry3D", 4},
    {"Geospatial", 2},
    {"Grouping", 3},
    {"H-Anim", 1},
    {"HAnim", 2},
    {"Interpolation", 5},
    {"KeyDeviceSensor", 2},
    {"Layering", 1},
    {"Layout", 2},
    {"Lighting", 3},
    {"NURBS", 4},
    {"Navigation", 3},
    {"Networking", 4},
    {"ParticleSystems", 3},
    {"Picking", 3},
    {"PointingDeviceSensor", 1},
    {"Rendering", 5},
    {"RigidBodyPhysics", 2},
    {"Scripting", 1},
    {"Shaders", 1},
    {"Shape", 4},
    {"Sound", 3},
    {"Text", 1},
    {"TextureProjection", 2},
    {"Texturing", 3},
    {"Texturing3D", 2},
    {"Time", 2},
    {"VRML97", 1},
    {"VolumeRendering", 4},
    {"xj3d_RenderTexture", 1},
    {"xj3d_IODevice", 2},
    {"xj3d_ParticleSystems", 1},
    {"xj3d_RigidBodyPhysics", 2},
    {"xj3d_Layering", 1},
}};

constexpr std::array<std::string_view, 9> kProfiles = {
    "Core",           "Interchange",      "Interactive",        "Immersive",     "Full",
    "CADInterchange", "MPEG4Interactive", "MedicalInterchange", "CADInterchange"};

struct ProfileLevel {
    std::string_view profile;
    std::string_view component;
    int level;
};

// ISO/IEC 19775-1 annexes A (Core), B (Interchange), C (Interactive) and
// E (Immersive).
constexpr ProfileLevel kProfileLevels[] = {
    {"Core", "Core", 1},
    {"Interchange", "Core", 1},
    {"Interchange", "Time", 1},
    {"Interchange", "Networking", 1},
    {"Interchange", "Grouping", 1},
    {"Interchange", "Rendering", 3},
    {"Interchange", "Shape", 1},
    {"Interchange", "Geometry3D", 2},
    {"Interchange", "Lighting", 1},
    {"Interchange", "Texturing", 2},
    {"Interchange", "Interpolation", 2},
    {"Interchange", "Navigation", 1},
    {"Interchange", "EnvironmentalEffects", 1},
    {"Interactive", "Core", 1},
    {"Interactive", "Time", 1},
    {"Interactive", "Networking", 2},
    {"Interactive", "Grouping", 2},
    {"Interactive", "Rendering", 3},
    {"Interactive", "Shape", 1},
    {"Interactive", "Geometry3D", 3},
    {"Interactive", "Lighting", 2},
    {"Interactive", "Texturing", 2},
    {"Interactive", "Interpolation", 2},
    {"Interactive", "PointingDeviceSensor", 1},
    {"Interactive", "KeyDeviceSensor", 1},
    {"Interactive", "EnvironmentalSensor", 1},
    {"Interactive", "Navigation", 1},
    {"Interactive", "EnvironmentalEffects", 1},
    {"Interactive", "EventUtilities", 1},
    {"Immersive", "Core", 2},
    {"Immersive", "Time", 1},
    {"Immersive", "Networking", 3},
    {"Immersive", "Grouping", 2},
    {"Immersive", "Rendering", 3},
    {"Immersive", "Shape", 2},
    {"Immersive", "Geometry3D", 4},
    {"Immersive", "Geometry2D", 1},
    {"Immersive", "Text", 1},
    {"Immersive", "Sound", 1},
    {"Immersive", "Lighting", 2},
    {"Immersive", "Texturing", 3},
    {"Immersive", "Interpolation", 2},
    {"Immersive", "PointingDeviceSensor", 1},
    {"Immersive", "KeyDeviceSensor", 2},
    {"Immersive", "EnvironmentalSensor", 2},
    {"Immersive", "Navigation", 2},
    {"Immersive", "EnvironmentalEffects", 2},
    {"Immersive", "Scripting", 1},
    {"Immersive", "EventUtilities", 1},
};

} // namespace

std::optional<int> profileComponentLevel(std::string_view profile, std::string_view component) {
    if (profile == "Full") return componentMaxLevel(component).value_or(1);
    if (profile != "Core" && profile != "Interchange" && profile != "Interactive" &&
        profile != "Immersive")
        return std::nullopt;
    for (const ProfileLevel& p : kProfileLevels)
        if (p.profile == profile && p.component == component) return p.level;
    return 0;
}

std::optional<int> componentMaxLevel(std::string_view component) {
    for (const auto& [name, level] : kComponents)
        if (name == component) return level;
    return std::nullopt;
}

bool isKnownProfile(std::string_view profile) {
    for (std::string_view p : kProfiles)
        if (p == profile) return true;
    return false;
}

bool isKnownX3dVersion(std::string_view v) {
    return v == "3.0" || v == "3.1" || v == "3.2" || v == "3.3" || v == "4.0" || v == "4.1";
}

} // namespace fl::scene
