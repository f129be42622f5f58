#pragma once
// Reads the ClassicVRML (.x3dv) and VRML97 (.wrl) encodings into a Scene.
#include "scene_builder.h"

#include <string_view>

namespace fl::scene {

// Reads scene.files[file].text; the header line decides VRML97 or ClassicVRML.
// Errors and warnings go to the builder's diagnostics.
void readClassic(SceneBuilder& builder);

// True when the text starts like a ClassicVRML or VRML97 file ("#VRML", "#X3D").
bool looksLikeClassic(std::string_view text);

} // namespace fl::scene
