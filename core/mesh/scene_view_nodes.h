#pragma once
// The nodes that say how a scene is seen rather than what is in it: lights,
// viewpoints, Background and NavigationInfo, gathered into SceneView in
// scene coordinates as the walk meets them.
#include "field/affine.h"
#include "scene_meshing.h"

namespace fl::animation {
class Animator;
}

namespace fl::mesh {

// Adds `n` to `view` when it is one of them, placed by `m`; returns whether
// it was (the walk then goes no further into it).
bool collectViewNode(const scene::Node& n, const field::Affine& m,
                     const animation::Animator& moment, SceneView& view);

} // namespace fl::mesh
