#pragma once
// An `implicit` FGeometry is the surface f = 0, whichever side is positive.
// Where it takes part in something that needs an inside — an FTransform's set
// operation, morph or formula, an FTexture3D displacement, an FDensity, or an
// FForce whose container it is — the FRep sign is read as written: f >= 0 is
// inside. A surface written the mathematician's way (x^2 + y^2 + z^2 - r^2)
// is negative inside, so there its outside would be used; these warnings find
// those and say how to write them.
#include "scene.h"

#include <vector>

namespace fl::scene {

// One warning per implicit FGeometry that looks negative inside (f > 0 over
// its whole box boundary, f < 0 somewhere within) where an inside is needed.
// Needs the scene's compiled definitions.
std::vector<SceneDiagnostic> checkImplicitSides(const Scene& scene);

} // namespace fl::scene
