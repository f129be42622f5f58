#pragma once
// bench mesh's libfive peer (issue 31 §3): libfive's dual contouring, the
// engine FunctionLab's adaptive mesher is closest to, built from source as a
// benchmark-only program (bench/peers/libfive_peer.cpp; configure with
// -DFUNCTIONLAB_LIBFIVE_SOURCE=DIR) next to functionlab. Same box, cells of
// the same size (libfive's octree halves the box, so the resolution is a
// power of two), the formula rebuilt in libfive's operations; its triangles
// are read back and measured by the same error code.
#include "cli/mesh_peer.h"
#include "field/field_sampler.h"
#include "formula/compiler.h"

#include <optional>
#include <string>

namespace fl::cli {

// Whether the peer program is built (else `why` says how to build it).
bool libfivePeerBuilt(std::string& why);

// `formula` is the shape's source (f >= 0 inside), compiled by the peer on its
// own with `setOperations`. `resolution` a power of two (libfive's octree
// halves its box). None with `why` (how to build the peer, what libfive lacks).
std::optional<MeshPeerRow> runLibfivePeer(const field::ImplicitField& field,
                                          const std::string& formula,
                                          const formula::SetOperationMode& setOperations,
                                          double resolution, int threads, std::string& why);

} // namespace fl::cli
