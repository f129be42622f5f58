#pragma once
// The one material every shape is drawn with (shaders/surface.*): per-vertex
// colour lit the X3D way, the shape's constant light terms as parameters.
// A pass is "opaque" or "transparent" (blended, depth kept but not written),
// so the frame graph can draw all opaque shapes before the see-through ones.
#include "mesh/scene_meshing.h" // SurfaceLook
#include "texture_image.h"

#include <Qt3DRender/QMaterial>
#include <Qt3DRender/QShaderProgram>

namespace fl::viewer {

// The filter key of the passes and its two values.
inline constexpr const char* kPassKey = "pass";
inline constexpr const char* kOpaquePass = "opaque";
inline constexpr const char* kTransparentPass = "transparent";

// The shader program, built once and shared by every material of a scene.
Qt3DRender::QShaderProgram* makeSurfaceShader(Qt3DCore::QNode* parent);

struct SurfaceOptions {
    bool transparent = false;
    bool points = false;
    float pointSize = 3;
    bool bothSides = false; // draw back faces too, whatever the look says (a cut-open scene)
    // The look's texture decoded (texture_image.h); none draws without it.
    std::optional<TextureImage> texture;
};

class SurfaceMaterial : public Qt3DRender::QMaterial {
  public:
    SurfaceMaterial(const mesh::SurfaceLook& look, const SurfaceOptions& options,
                    Qt3DRender::QShaderProgram* shader, Qt3DCore::QNode* parent = nullptr);
};

} // namespace fl::viewer
