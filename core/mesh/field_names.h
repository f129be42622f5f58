#pragma once
// The mesher works in core/field's vocabulary — points, boxes, affine maps,
// the sampled field — shared with picking, haptic contact and the grader.
// These declarations only let mesh code name them without the namespace.
#include "field/affine.h"
#include "field/box3.h"
#include "field/field_sampler.h"
#include "field/vec3.h"

namespace fl::mesh {

using field::Affine;
using field::boundsOf;
using field::Box3;
using field::BoxBoundary;
using field::Displacement;
using field::EvaluationCounts;
using field::FieldSampler;
using field::ImplicitField;
using field::Matrix4;
using field::Vec3;

} // namespace fl::mesh
