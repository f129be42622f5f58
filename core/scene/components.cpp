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

} // namespace

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
