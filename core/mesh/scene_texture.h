#pragma once
// Image textures of an Appearance (X3D 19775-1, 18 Texturing): which image
// an ImageTexture's url names (resolved next to the scene file; the viewer
// decodes it), a PixelTexture's pixels, repeatS/T, and TextureTransform
// applied to a mesh's texture coordinates.
#include "mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fl::mesh {

struct SurfaceTexture {
    std::string file; // ImageTexture: the first url found, as an absolute path
    // PixelTexture: RGBA bytes, rows from the bottom (X3D's SFImage order).
    int width = 0, height = 0;
    int components = 0; // 1 intensity, 2 + alpha, 3 RGB, 4 RGBA; 0 until decoded
    std::vector<std::uint8_t> rgba;
    bool repeatS = true, repeatT = true;

    bool operator==(const SurfaceTexture&) const = default;
};

// The appearance's texture, or none (no texture, a movie, nothing found);
// what could not be used is said in `warnings`.
std::optional<SurfaceTexture> textureOf(const scene::Scene& scene, const scene::Node* appearance,
                                        std::vector<std::string>& warnings);

// Applies the appearance's TextureTransform to the mesh's texture
// coordinates (X3D 18.4.10: Tc' = -C x S x R x C x T x Tc).
void applyTextureTransform(const scene::Node* appearance, Mesh& mesh);

} // namespace fl::mesh
