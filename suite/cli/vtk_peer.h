#pragma once
// bench mesh's VTK peer (issue 31 §3): what a VTK user does instead of
// FunctionLab's mesher — the formula sampled into a grid (here by
// FunctionLab's own batch evaluator, machine code, on the shared pool: the
// fastest sampling there is, so the peer is not handicapped), contoured by
// vtkFlyingEdges3D with VTK's defaults in Debian's python3-vtk9
// (bench/peers/vtk_flying_edges.py, a separate process: nothing of VTK is
// linked into functionlab). Same box, same cells as dense marching cubes;
// its triangles are read back and measured by the same error code.
#include "cli/mesh_peer.h"
#include "field/field_sampler.h"

#include <optional>
#include <string>

namespace fl::cli {

// None with `why` (what to install) when the peer cannot run.
std::optional<MeshPeerRow> runVtkPeer(const field::ImplicitField& field, double resolution,
                                      int threads, std::string& why);

} // namespace fl::cli
