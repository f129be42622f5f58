#include "touch_sensor_scope.h"

#include "animation/animator.h"
#include "scene/node_graph.h"

#include <utility>

namespace fl::mesh {

TouchSensorScope::TouchSensorScope(std::vector<const scene::Node*>& current,
                                   const scene::Node& group, const animation::Animator& moment)
    : current_(current) {
    if (!group.spec || !scene::findFieldSpec(*group.spec, "children")) return;
    std::vector<const scene::Node*> here;
    for (const scene::Node* child : moment.nodes(group, "children")) {
        const scene::Node* sensor = scene::effectiveNode(child);
        if (sensor && sensor->kind() == scene::NodeKind::TouchSensor &&
            moment.flag(*sensor, "enabled"))
            here.push_back(sensor);
    }
    if (here.empty()) return;
    outer_ = std::exchange(current_, std::move(here));
    shadowing_ = true;
}

TouchSensorScope::~TouchSensorScope() {
    if (shadowing_) current_ = std::move(outer_);
}

} // namespace fl::mesh
