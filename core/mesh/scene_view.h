#pragma once
// What a scene says about how it is seen, gathered while it is meshed (with
// the transforms above each node applied): lights, viewpoints, the first
// Background and the first NavigationInfo. Plain data, in scene coordinates.
#include <array>
#include <string>
#include <vector>

namespace fl::mesh {

struct ViewLight {
    enum class Kind { Directional, Point, Spot } kind = Kind::Directional;
    std::array<float, 3> colour{1, 1, 1};
    float intensity = 1;
    float ambientIntensity = 0;
    std::array<double, 3> direction{0, 0, -1}; // unit, in the scene (directional, spot)
    std::array<double, 3> location{0, 0, 0};   // in the scene (point, spot)
    std::array<float, 3> attenuation{1, 0, 0};
    double radius = 100;
    double beamWidth = 1.570796, cutOffAngle = 0.785398; // spot, radians
};

struct ViewPoint {
    std::string name; // description, else DEF name, else "Viewpoint N"
    std::array<double, 3> position{0, 0, 10};
    std::array<double, 3> direction{0, 0, -1}; // unit, where it looks
    std::array<double, 3> up{0, 1, 0};         // unit
    std::array<double, 3> centerOfRotation{0, 0, 0};
    double fieldOfView = 0.785398; // radians, of the smaller side of the view
};

struct ViewNavigation {
    std::vector<std::string> types{"EXAMINE", "ANY"};
    bool headlight = true;
    double speed = 1;
    std::array<double, 3> avatarSize{0.25, 1.6, 0.75};
};

struct SceneView {
    std::vector<ViewLight> lights;
    std::vector<ViewPoint> viewpoints; // in file order; the first is bound at load
    // The viewpoint bound at this moment (set_bind events through the one
    // clock; 0, the first, when no event has bound another); -1 without any.
    int boundViewpoint = -1;
    std::array<float, 3> background{0, 0, 0}; // the bound Background's sky (else the first's)
    bool hasBackground = false;
    ViewNavigation navigation; // the bound NavigationInfo (else the first)
    bool hasNavigation = false;
};

} // namespace fl::mesh
