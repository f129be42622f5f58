#pragma once
// What every part of meshing a scene reads (scene_meshing.cpp walks; the
// parts in scene_view_nodes, touch_sensor_scope, shape_appearance,
// function_composite and lent_appearance each do one concern): the scene,
// the caller's options and the one clock at the moment meshed, with the
// small questions they all ask of a node. Internal to functionlab_scene_mesh.
#include "animation/animator.h"
#include "field/affine.h"
#include "scene/function_kinds.h"
#include "scene/node_graph.h"
#include "scene_meshing.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fl::mesh {

using field::Affine;

struct SceneWalkContext {
    const scene::Scene& scene;
    const SceneMeshOptions& options;
    const animation::Animator& moment; // the one clock at the moment meshed

    // "FShape BALL (scene.x3d:4:3)", for notes and errors.
    std::string nameOf(const scene::Node& n) const;
    // The node's t at the moment asked for: the one clock's answer.
    double timeOf(const scene::Node& n) const { return moment.time(n); }
    // An unknown word was reported by the reader: such a shape is drawn as a solid.
    scene::GeometryType geometryTypeOf(const scene::Node& geometry) const;
    // None for a word the reader reported: the first child is shown.
    std::optional<scene::SetOperation> operationOf(const scene::Node& ft) const;
    // X3D Transform: T * C * R * SR * S * -SR * -C, with the moment's values.
    Affine transformOf(const scene::Node& transform) const;
    // FTransform: translation, rotationAngle about rotationAxis and scale as
    // functions of t, about center.
    Affine functionTransform(const scene::Node& ft) const;
    const scene::Node* appearanceOf(const scene::Node& shape) const;
    const scene::Node* materialOf(const scene::Node* appearance) const;
    // A mesh from the cache when there is one (a copy: colours and placement
    // are applied to it afterwards), else made now.
    MeshResult cached(const std::string& key, const std::function<MeshResult()>& make) const;
};

// The walk's guard against loops and depth, shared by every recursive part
// (the builder refuses loops; a scene changed by events may still make one).
class WalkGuard {
  public:
    explicit WalkGuard(std::vector<std::string>& notes) : notes_(notes) {}
    scene::WalkPath& path() { return path_; }
    // Whether the walk must not go into the node of `step` (noted once).
    bool refused(const scene::WalkPath::Step& step);

  private:
    std::vector<std::string>& notes_;
    scene::WalkPath path_;
    bool noted_ = false;
};

// Moves a mesh from its geometry's coordinates into the scene's, or keeps
// the placement for the viewer to apply (SceneMeshOptions::placeInScene).
void place(ShapeMesh& sm, const Affine& m, const SceneMeshOptions& options);

} // namespace fl::mesh
