#pragma once
// What a student cannot see but can feel, shown as colour (issue 16 §3): the
// friction or the density a tangible shape has at each vertex of its mesh,
// from blue (0) through green to red (1 and more), read through the effect's
// own domain box exactly as the servo loop reads it.
#include "tangible_scene.h"

#include "mesh/scene_meshing.h"

#include <memory>

namespace fl::haptics {

// The colour of a value in [0, 1] (clamped; not finite: grey).
std::array<float, 4> effectColour(double value);

// `frame` with every tangible shape that has an effect of `kind` coloured by
// it (the others as they were). Shapes are matched by their node; vertices
// are in each shape's own coordinates, as the viewer keeps them.
std::shared_ptr<const mesh::SceneMeshes> colouredByEffect(const mesh::SceneMeshes& frame,
                                                          const TangibleScene& tangible,
                                                          scene::TangibleKind kind);

} // namespace fl::haptics
