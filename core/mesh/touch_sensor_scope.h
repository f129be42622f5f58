#pragma once
// Which TouchSensors sense a shape: those among the children of the lowest
// group above it that has any (X3D 19775-1 §20.2.1: the lowest sensors are
// activated, and they shadow those above). The walk opens a scope at each
// group; a scope with sensors of its own shadows the outer ones until it
// closes.
#include "scene/scene.h"

#include <vector>

namespace fl::animation {
class Animator;
}

namespace fl::mesh {

class TouchSensorScope {
  public:
    // `current`: the sensors in force, replaced while this scope is open if
    // `group` holds enabled TouchSensors among its children.
    TouchSensorScope(std::vector<const scene::Node*>& current, const scene::Node& group,
                     const animation::Animator& moment);
    ~TouchSensorScope();
    TouchSensorScope(const TouchSensorScope&) = delete;
    TouchSensorScope& operator=(const TouchSensorScope&) = delete;

  private:
    std::vector<const scene::Node*>& current_;
    std::vector<const scene::Node*> outer_;
    bool shadowing_ = false;
};

} // namespace fl::mesh
