#pragma once
// The image of a shape's texture (mesh::SurfaceTexture) as a QImage: an
// ImageTexture's file decoded by Qt's image readers (PNG, JPEG, GIF, BMP ...),
// a PixelTexture's pixels turned top row first; with X3D's component count,
// which decides whether the image colours or only brightens the surface.
#include "mesh/scene_texture.h"

#include <QImage>

#include <map>
#include <optional>
#include <string>

namespace fl::viewer {

struct TextureImage {
    QImage image;            // RGBA8888, top row first
    int components = 3;      // 1 grey, 2 grey + alpha, 3 colour, 4 colour + alpha
    bool seeThrough = false; // some pixel's alpha is below 1: drawn in the transparent pass
};

// Decoded files, kept by path: scenes reuse one image on many shapes, and a
// playing scene re-makes shapes often.
class TextureImages {
  public:
    // None when the file cannot be read or decoded.
    std::optional<TextureImage> get(const mesh::SurfaceTexture& texture);

  private:
    std::map<std::string, std::optional<TextureImage>> files_;
};

} // namespace fl::viewer
