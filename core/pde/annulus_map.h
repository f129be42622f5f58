#pragma once
// A tube region of a mesh (an annulus: open at both ends) laid on a PDE
// tube's (u, v): u harmonic, 0 on one boundary loop and 1 on the other; v
// harmonic too, going once round the tube — the conjugate of u, so the
// (u, v) lines cross at right angles (the conformal map of an annulus, as
// the disk map is of a disk). v is found on the tube cut open along a path
// of faces from one loop to the other: every edge the path crosses carries
// a jump of 2π, which makes v single-valued face by face. Cotangent weights
// clamped positive, as in disk_map.h.
#include "mesh_regions.h"

#include <array>
#include <optional>
#include <unordered_map>

namespace fl::pde {

// Each face's corners' (u, v), v unwrapped within the face (it may pass 2π
// there: cos(nv) and sin(nv) do not mind).
using FaceParameters = std::unordered_map<std::uint32_t, std::array<std::array<double, 2>, 3>>;

// A conformal map's u (harmonic: it crowds where the surface is wide — on a
// sphere's band it is log tan(θ/2), on a cap tan(θ/2), profiles a cubic
// spine follows badly) made proportional to the mean length along u over
// v: on a sphere, θ itself. Increasing, 0 at 0 and 1 at 1.
class LengthParameter {
  public:
    LengthParameter(const mesh::Mesh& mesh, const FaceParameters& faces);
    double operator()(double u) const;

  private:
    std::vector<double> at_; // the new u at the start of each slice of u, then at u = 1
};

struct AnnulusMap {
    FaceParameters faces; // u by length (LengthParameter)
    // The loops at u = 0 and u = 1, each in the order v increases.
    std::vector<std::uint32_t> start, end;
};

// `start` and `end`: the region's two boundary loops (annulusBoundaries).
// Nullopt when a solve fails or the region is not connected between them.
std::optional<AnnulusMap> mapToAnnulus(const FaceGraph& graph, const Faces& region,
                                       const std::vector<std::uint32_t>& start,
                                       const std::vector<std::uint32_t>& end);

} // namespace fl::pde
