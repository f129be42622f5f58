#include "dual_contouring.h"

#include "block_arena.h"

#include "parallel/work_pool.h"

#include "formula/nonfinite_report.h"
#include "marching_cubes.h" // edgeGroups: the pieces of surface in a cell
#include "qef.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory_resource>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace fl::mesh {
namespace {

constexpr int kB = 8;      // cells along a block's edge
constexpr int kC = kB + 1; // corners along a block's edge (the far ones shared with the next block)
constexpr int kCorners = kC * kC * kC;
constexpr int kCells = kB * kB * kB;
// How far outside its cell (in cells) a vertex may be placed (buildVertices).
constexpr double kVertexRoom = 0.5;
// The same for a vertex held on a closed box's face (onBoxFaces).
constexpr double kFaceVertexRoom = 1.5;
// A quad whose diagonals' ends' normals turn by more than acos(kCreaseTurn)
// (37 degrees) holds a crease (appendQuad).
constexpr double kCreaseTurn = 0.8;
// Smooth patches' vertices (balancedOnSurface): lifted this many times the
// crossings' mean curvature term above the surface, not moved where that
// term is over kMaxCurvatureTerm cells, moved at most kMaxShift cells. A cell
// whose crossings' normals disagree (smoothAround) counts as a curved patch
// when they spread by under kMaxSpread (1 - |mean normal|) and the normal at
// its vertex is kCreaseTest times closer to their mean than they are.
constexpr double kSurfaceLift = 0.25, kMaxCurvatureTerm = 0.25, kMaxShift = 0.1, kMaxSpread = 0.05,
                 kCreaseTest = 0.1;
// The QEF's cutoff at a crease whose sides turn by under 37 degrees (which
// the mesher's 0.1 cannot resolve): its direction's eigenvalue is about
// tan^2(turn / 2) of the largest, 0.0077 at 10 degrees.
constexpr double kShallowCreaseCutoff = 0.003, kCreaseOnSurface = 0.1;
// Where a crossing's gradient is taken: this fraction of its edge inside it
// when the crossing lies at a corner (computeCrossings says why).
constexpr double kIntoTheEdge = 1e-4;

// FRep: f >= 0 is the solid, f = 0 its boundary. The mesher meshes the
// boundary of the interior f > 0, which is the same surface for every regular
// solid, and nothing for f = -g^2, whose "solid" is only the surface itself.
bool inside(double f) {
    return f > 0;
}

using BlockCoord = std::array<int, 3>;

struct Grid {
    Vec3 origin{};
    Vec3 h{};
    std::array<int, 3> cells{};
    std::array<int, 3> blocks{};

    // The lattice's i-th coordinate along axis a (every corner is made so:
    // the mesher relies on equal corners having equal bits).
    double coordinate(std::size_t a, long i) const { return origin[a] + double(i) * h[a]; }
    Vec3 corner(long i, long j, long k) const {
        return {coordinate(0, i), coordinate(1, j), coordinate(2, k)};
    }
    // The box of the blocks [lo, hi) and one cell around it: where the
    // mesher evaluates for those blocks (a vertex may sit half a cell out of
    // its cell), so what a formula narrowed to it decides holds there.
    std::array<Vec3, 2> blocksAndACell(const BlockCoord& lo, const BlockCoord& hi) const {
        return {corner(long(lo[0]) * kB - 1, long(lo[1]) * kB - 1, long(lo[2]) * kB - 1),
                corner(long(hi[0]) * kB + 1, long(hi[1]) * kB + 1, long(hi[2]) * kB + 1)};
    }
};

std::uint64_t keyOf(const BlockCoord& b) {
    return (std::uint64_t(b[0]) << 42) | (std::uint64_t(b[1]) << 21) | std::uint64_t(b[2]);
}

int cornerIndex(int ci, int cj, int ck) {
    return (ck * kC + cj) * kC + ci;
}
// The block-local lattice coordinates of corner index c (from a table: the
// divisions by 9 and 81 were a twentieth of the mesher's instructions).
std::array<int, 3> cornerAt(int c) {
    static constexpr auto table = [] {
        std::array<std::array<std::uint8_t, 3>, kCorners> t{};
        for (int n = 0; n < kCorners; ++n)
            t[std::size_t(n)] = {std::uint8_t(n % kC), std::uint8_t(n / kC % kC),
                                 std::uint8_t(n / (kC * kC))};
        return t;
    }();
    const std::array<std::uint8_t, 3>& at = table[std::size_t(c)];
    return {at[0], at[1], at[2]};
}
int cellIndex(int ci, int cj, int ck) {
    return (ck * kB + cj) * kB + ci;
}

// A block's 2x2x2-cell sub-blocks are numbered 0..63 (x fastest); a
// sub-block is named by its lowest cell, whose coordinates are even.
std::uint8_t subBlockIndex(const int s0[3]) {
    return std::uint8_t((s0[2] / 2 * 4 + s0[1] / 2) * 4 + s0[0] / 2);
}
std::array<int, 3> subBlockOrigin(std::uint8_t sub) {
    return {(sub % 4) * 2, (sub / 4 % 4) * 2, (sub / 16) * 2};
}

// An edge on a block's lower faces (from corner `corner` along `axis`, its
// first corner inside or not), packed for the connect phase: sorting packed
// values puts the edges in the order of a walk over the kept sub-blocks
// (octant, sub-block in it, cell in that, axis) — the order in which the
// connect phase once found them, so the mesh's triangles keep their order.
std::uint32_t packLowerFaceEdge(int corner, int axis, bool lowerIn) {
    const auto [i, j, k] = cornerAt(corner);
    const int octant = int(i >= 4) | int(j >= 4) << 1 | int(k >= 4) << 2;
    const int sub = (i >> 1 & 1) | (j >> 1 & 1) << 1 | (k >> 1 & 1) << 2;
    const int cell = (i & 1) | (j & 1) << 1 | (k & 1) << 2;
    const auto order = std::uint32_t(((octant * 8 + sub) * 8 + cell) * 3 + axis);
    static_assert(kCorners <= 1024, "a corner index fits in 10 bits");
    return order << 11 | std::uint32_t(lowerIn) << 10 | std::uint32_t(corner);
}
struct LowerFaceEdge {
    std::array<int, 3> local; // its first corner in the block
    int axis = 0;
    bool lowerIn = false;
};
LowerFaceEdge lowerFaceEdge(std::uint32_t packed) {
    return {cornerAt(int(packed & 1023u)), int((packed >> 11) % 3), (packed >> 10 & 1u) != 0};
}

// A cell holds at most four separate pieces of surface (the marching-cubes
// cases); each gets its own vertex, so two sheets passing through one cell do
// not share a vertex (which would make edges with four triangles).
constexpr int kPieces = 4;

// The edge of a cell that starts at the cell's corner offset (du, dv) across
// axis a, in the numbering of marching_cubes.h.
int cubeEdge(int a, int du, int dv) {
    switch (a) {
    case 0:
        return du + 2 * dv; // along x at (y, z) = (du, dv)
    case 1:
        return 4 + dv + 2 * du; // along y at (x, z) = (dv, du)
    default:
        return 8 + du + 2 * dv; // along z at (x, y) = (du, dv)
    }
}

// One bit per corner of a block (bit c % 64 of word c / 64).
using CornerBits = std::array<std::uint64_t, (kCorners + 63) / 64>;

// Bit c of the result is bit c + s of `bits` (zero past the last corner).
CornerBits shiftedDown(const CornerBits& bits, int s) {
    CornerBits out{};
    const std::size_t words = std::size_t(s) / 64, shift = std::size_t(s) % 64;
    for (std::size_t w = 0; w + words < out.size(); ++w) {
        out[w] = bits[w + words] >> shift;
        if (shift != 0 && w + words + 1 < out.size()) out[w] |= bits[w + words + 1] << (64 - shift);
    }
    return out;
}

// The corners an edge along `axis` can start from: all but the block's far
// face on that axis.
const CornerBits& edgeStarts(int axis) {
    static const std::array<CornerBits, 3> masks = [] {
        std::array<CornerBits, 3> m{};
        for (int c = 0; c < kCorners; ++c) {
            const std::array<int, 3> at = cornerAt(c);
            for (std::size_t a = 0; a < 3; ++a)
                if (at[a] < kB) m[a][std::size_t(c / 64)] |= std::uint64_t(1) << (c % 64);
        }
        return m;
    }();
    return masks[std::size_t(axis)];
}

// The 27 corners of each 2x2x2-cell sub-block as bits of a block's corner
// rows: they span at most 183 bits, so four words from `first` hold them.
struct SubBlockCorners {
    std::size_t first = 0;
    std::array<std::uint64_t, 4> mask{};
};
const std::array<SubBlockCorners, 64>& subBlockCorners() {
    static const auto table = [] {
        std::array<SubBlockCorners, 64> t{};
        for (int sub = 0; sub < 64; ++sub) {
            const auto [si, sj, sk] = subBlockOrigin(std::uint8_t(sub));
            SubBlockCorners& m = t[std::size_t(sub)];
            m.first = std::size_t(cornerIndex(si, sj, sk)) / 64;
            for (int dk = 0; dk <= 2; ++dk)
                for (int dj = 0; dj <= 2; ++dj)
                    for (int di = 0; di <= 2; ++di) {
                        const std::size_t c =
                            std::size_t(cornerIndex(si + di, sj + dj, sk + dk)) - 64 * m.first;
                        m.mask[c / 64] |= std::uint64_t(1) << (c % 64);
                    }
        }
        return t;
    }();
    return table;
}

// Bits c, c + 1 and c + 2 of a corner row, as bits 0, 1 and 2.
unsigned threeBits(const CornerBits& row, int c) {
    const std::size_t w = std::size_t(c) / 64, s = std::size_t(c) % 64;
    std::uint64_t bits = row[w] >> s;
    if (s > 61 && w + 1 < row.size()) bits |= row[w + 1] << (64 - s);
    return unsigned(bits & 7u);
}

struct Crossing {
    Vec3 point{};
    Vec3 normal{}; // unit gradient direction (the sign does not matter to the QEF)
};

// An edge crossing being refined: the bracket [pa, pb] with f at its ends.
struct PendingCrossing {
    PendingCrossing() = default;
    // Every field from its value, none zeroed first (see computeCrossings).
    PendingCrossing(int found, int axis, const Vec3& pa, const Vec3& pb, double fa, double fb,
                    double t = 0.5)
        : found(found), axis(axis), pa(pa), pb(pb), fa(fa), fb(fb), t(t) {}
    int found = 0; // its index in the block's found edges (and crossings)
    int axis = 0;
    Vec3 pa{}, pb{};
    double fa = 0, fb = 0;
    double ta = 0, tb = 1, t = 0.5;
    bool done = false;
    int kept = 0; // which end the last step kept: +1 b, -1 a (Illinois)
};

// What a vertex costs from sampling to the finished mesh: in its block (its
// position, normal, cell's share and its share of the lower-face edges: a
// third of the crossings, 4 bytes each) and later (about two triangles in
// the block, then its position, normal and triangles again in the mesh).
constexpr std::size_t kBlockBytesPerVertex = 2 * sizeof(Vec3f) + 8 + 2;
constexpr std::size_t kLaterBytesPerVertex = 2 * sizeof(Vec3f) + 4 * sizeof(Triangle);
constexpr std::size_t kBytesPerVertex = kBlockBytesPerVertex + kLaterBytesPerVertex;

// A cell with vertices: its corner configuration (which piece of surface
// an edge is on), its first vertex (block-local; a cell's vertices are
// consecutive) and which pieces have one (bit p: piece p). Most of a block's
// 512 cells hold no surface, so only these are kept: a block costs about
// its vertices, not its volume, which is what lets fine resolutions fit.
struct SurfaceCell {
    std::uint16_t cell = 0;
    std::int16_t config = -1; // -1: unknown
    std::uint16_t firstVertex = 0;
    std::uint8_t pieceMask = 0;
};

// What phase 1 leaves for each active block.
struct Block {
    BlockCoord coord{};
    // The formula as the octree narrowed it to this block and a cell around
    // it (null: nothing to drop), until the block is sampled.
    std::shared_ptr<const field::NarrowedTape> tape;
    bool narrowed = false; // tape is the octree's (blocks found later narrow themselves)
    // The arrays live in the mesh call's BlockArena (block_arena.h).
    std::pmr::vector<SurfaceCell> cells; // sorted by cell
    std::pmr::vector<Vec3f> positions;   // single precision, as the mesh keeps them
    std::pmr::vector<Vec3f> normals;
    std::uint32_t offset = 0; // first global vertex id
    // Quads around edges whose four cells are all in this block, made while
    // sampling (block-local vertex ids: the offset is known only later).
    std::pmr::vector<Triangle> interior;
    // Quads around the edges on the block's lower faces, which need the
    // neighbouring blocks' vertices (global ids, made by the connect phase).
    std::pmr::vector<Triangle> triangles;
    // Those edges, found while sampling, in the order the connect phase
    // makes their quads (see packLowerFaceEdge).
    std::pmr::vector<std::uint32_t> lowerFaceEdges;

    explicit Block(std::pmr::memory_resource* memory = std::pmr::get_default_resource())
        : cells(memory), positions(memory), normals(memory), interior(memory), triangles(memory),
          lowerFaceEdges(memory) {}

    // Which cells have an entry in `cells` (bit c % 64 of word c / 64), and
    // how many entries the words before hold: a cell's entry is then found
    // by counting bits (the connect phase looks up about one and a half
    // cells per vertex; a binary search of `cells` was a tenth of the
    // mesher's time), in 80 bytes a block.
    std::array<std::uint64_t, kCells / 64> occupied{};
    std::array<std::uint16_t, kCells / 64> before{};

    const SurfaceCell* surfaceCell(int cell) const {
        const std::size_t word = std::size_t(cell) / 64;
        const std::uint64_t bit = std::uint64_t(1) << (std::size_t(cell) % 64);
        if (!(occupied[word] & bit)) return nullptr;
        return &cells[before[word] + std::size_t(std::popcount(occupied[word] & (bit - 1)))];
    }
    // What the block holds in memory (its share of the mesh included).
    std::size_t bytes() const {
        return lowerFaceEdges.capacity() * sizeof(std::uint32_t) +
               cells.capacity() * sizeof(SurfaceCell) +
               (positions.capacity() + normals.capacity()) * sizeof(Vec3f) +
               (interior.capacity() + triangles.capacity()) * sizeof(Triangle);
    }
};

// What sampling saw, for the warnings. The threads take blocks in no fixed
// order, so each point is chosen by a rule that does not depend on which
// thread saw what first: of equal candidates, the one first in z, then y,
// then x (within a block that is the first in corner order). Otherwise a
// warning could name a different point from one run to the next (the
// maximum of f = -y^2 is every point with y = 0).
bool zyxBefore(const Vec3& a, const Vec3& b) {
    if (a[2] != b[2]) return a[2] < b[2];
    if (a[1] != b[1]) return a[1] < b[1];
    return a[0] < b[0];
}
struct Observations {
    bool sawNaN = false;
    Vec3 nanPoint{};
    double maxValue = -std::numeric_limits<double>::infinity();
    Vec3 maxPoint{};
    double maxAbs = 0;
    std::optional<Vec3> undefinedCandidate; // a sub-block f may be undefined in
    void offerNaN(const Vec3& p) {
        if (!sawNaN || zyxBefore(p, nanPoint)) nanPoint = p;
        sawNaN = true;
    }
    void offerMax(double v, const Vec3& p) {
        if (v > maxValue || (v == maxValue && zyxBefore(p, maxPoint))) {
            maxValue = v;
            maxPoint = p;
        }
    }
    void offerUndefinedCandidate(const Vec3& p) {
        if (!undefinedCandidate || zyxBefore(p, *undefinedCandidate)) undefinedCandidate = p;
    }
    void merge(const Observations& o) {
        if (o.undefinedCandidate) offerUndefinedCandidate(*o.undefinedCandidate);
        if (o.sawNaN) offerNaN(o.nanPoint);
        if (o.maxValue > -std::numeric_limits<double>::infinity()) offerMax(o.maxValue, o.maxPoint);
        maxAbs = std::max(maxAbs, o.maxAbs);
    }
};

// From the highest sample, Newton steps towards f = 0, each 1 % longer than
// Newton's: does f become positive somewhere (a solid thinner than a cell:
// the longer steps cross its surface instead of creeping up to it from
// outside, which only rounding could decide), or only touch zero (no inside
// at all, as f = -g^2: the steps still shrink towards g = 0)? Returns the
// highest value reached.
double climbTowardsZero(FieldSampler& sampler, Vec3 p) {
    double best = sampler.value(p);
    for (int step = 0; step < 60 && best < 0; ++step) {
        const formula::Dual d = sampler.gradient(p);
        const double g2 = d.d[0] * d.d[0] + d.d[1] * d.d[1] + d.d[2] * d.d[2];
        if (!(g2 > 0) || !std::isfinite(d.v)) break;
        for (std::size_t a = 0; a < 3; ++a)
            p[a] -= 1.01 * d.v * d.d[a] / g2;
        const double f = sampler.value(p);
        if (!std::isfinite(f)) break;
        best = std::max(best, f);
    }
    return best;
}

Vec3 normalised(const std::array<double, 3>& g, bool& ok) {
    const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    ok = std::isfinite(n) && n > 0;
    if (!ok) return {0, 0, 0};
    return {g[0] / n, g[1] / n, g[2] / n};
}

// The piece of surface edge `edge` of a cell is on (0 for a cell of unknown
// configuration: one piece).
// (edgeGroups' answers for every configuration, in a table of 3 KB made
// once: the mesher asks about four times a vertex, and the call with its
// guarded static was a twentieth of buildVertices.)
using PieceTable = std::array<std::array<std::int8_t, 12>, 256>;
const PieceTable& pieceTable() {
    static const auto table = [] {
        PieceTable t{};
        for (int config = 0; config < 256; ++config)
            for (std::size_t edge = 0; edge < 12; ++edge) {
                const int piece = edgeGroups(config).group[edge];
                t[std::size_t(config)][edge] =
                    std::int8_t(piece >= 0 && piece < kPieces ? piece : 0);
            }
        return t;
    }();
    return table;
}
int pieceOf(const PieceTable& table, int config, int edge) {
    return config < 0 ? 0 : table[std::size_t(config)][std::size_t(edge)];
}

// The block-local vertex of a cell's piece of surface that `edge` is on, or
// -1 when the cell has none there.
// (`pieces`: pieceTable(), which the connect phase holds.)
std::int32_t vertexOf(const PieceTable& pieces, const Block& block, int cell, int edge) {
    const SurfaceCell* c = block.surfaceCell(cell);
    if (!c) return -1;
    const int piece = pieceOf(pieces, c->config, edge);
    const unsigned mask = c->pieceMask;
    if (!(mask >> piece & 1u)) return -1;
    static constexpr std::uint8_t kOnes[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    return std::int32_t(c->firstVertex) + kOnes[mask & ((1u << piece) - 1)];
}

// The normal of the triangle (a, b, c) of a quad, unscaled.
Vec3 triangleNormal(const std::array<const Vec3f*, 4>& pos, std::size_t a, std::size_t b,
                    std::size_t c) {
    auto at = [&](std::size_t q) { return Vec3{(*pos[q])[0], (*pos[q])[1], (*pos[q])[2]}; };
    return field::cross(field::minus(at(b), at(a)), field::minus(at(c), at(a)));
}
// Whether splitting the quad along a-c folds it: its triangles (a, b, c) and
// (a, c, d) face opposite ways.
bool foldsAlong(const std::array<const Vec3f*, 4>& pos, std::size_t a, std::size_t b, std::size_t c,
                std::size_t d) {
    return field::dot(triangleNormal(pos, a, b, c), triangleNormal(pos, a, c, d)) < 0;
}
// A vertex on a closed box's face has the face's normal (vertexNormal).
bool faceNormal(const Vec3f& n) {
    return std::abs(n[0]) == 1 || std::abs(n[1]) == 1 || std::abs(n[2]) == 1;
}

// Two triangles for the quad q0 q1 q2 q3 (in order around its edge, facing
// out), split along the diagonal that lies closer to the surface: a
// diagonal from a to b bows off a surface by about (n_a - n_b).(b - a) / 8
// at its middle (n the vertex normals; kappa L^2 / 8 for a curvature kappa
// along it). On a saddle (the gyroid is nearly one everywhere) the two
// diagonals bend opposite ways by different amounts, and the flatter one
// is the smaller error. Where the two bow about as much (their (n_a -
// n_b).(b - a) within a thousandth of the shorter diagonal: flat patches, a
// sphere) the shorter diagonal, for better-shaped triangles; and where a
// crease crosses the quad (a diagonal's ends' normals over kCreaseTurn
// apart) too: there the normals tell the crease, not a curvature, and the
// flatter diagonal can fold a triangle over it.
// Where a crease has put the quad's vertices out of convex order, one
// diagonal folds it and the other may not. A quad whose four normals are
// one (a plane: the watermelon's cut, a box face) is split so that both
// triangles face along that normal, if only one split's do; in a block
// beside a closed box (`besideTheBox`), one with a vertex on a face (whose
// crease vertices may sit a cell and a half from their cells: onBoxFaces)
// along the diagonal that does not fold it, if only one does. (The gyroid
// in its closed box at 128: 583 folded edges -> 318; the watermelon at 96:
// 46 -> 14.)
void appendQuad(std::pmr::vector<Triangle>& out, const std::array<std::uint32_t, 4>& id,
                const std::array<const Vec3f*, 4>& pos, const std::array<const Vec3f*, 4>& normal,
                bool besideTheBox) {
    auto dist2 = [](const Vec3f& x, const Vec3f& y) {
        double d = 0;
        for (std::size_t k = 0; k < 3; ++k)
            d += (double(x[k]) - y[k]) * (double(x[k]) - y[k]);
        return d;
    };
    auto bow = [&](std::size_t a, std::size_t b) {
        double e = 0;
        for (std::size_t k = 0; k < 3; ++k)
            e +=
                (double((*normal[a])[k]) - (*normal[b])[k]) * (double((*pos[b])[k]) - (*pos[a])[k]);
        return std::abs(e);
    };
    auto along = [&](std::size_t a, std::size_t b) {
        double d = 0;
        for (std::size_t k = 0; k < 3; ++k)
            d += double((*normal[a])[k]) * (*normal[b])[k];
        return d;
    };
    const double d02 = dist2(*pos[0], *pos[2]), d13 = dist2(*pos[1], *pos[3]);
    bool alongFirst = d02 <= d13;
    const bool flat =
        *normal[0] == *normal[1] && *normal[1] == *normal[2] && *normal[2] == *normal[3];
    if (!flat && along(0, 2) > kCreaseTurn && along(1, 3) > kCreaseTurn) { // no crease in it
        const double b02 = bow(0, 2), b13 = bow(1, 3);
        if (std::abs(b02 - b13) > 1e-3 * std::sqrt(std::min(d02, d13))) alongFirst = b02 < b13;
    }
    if (flat) { // both of a split's triangles should face along the one normal
        const Vec3 n{(*normal[0])[0], (*normal[0])[1], (*normal[0])[2]};
        auto facesOut = [&](std::size_t a, std::size_t b, std::size_t c) {
            return field::dot(triangleNormal(pos, a, b, c), n) > 0;
        };
        const bool first = facesOut(0, 1, 2) && facesOut(0, 2, 3);
        const bool second = facesOut(0, 1, 3) && facesOut(1, 2, 3);
        if (first != second) alongFirst = first;
    } else if (besideTheBox && (faceNormal(*normal[0]) || faceNormal(*normal[1]) ||
                                faceNormal(*normal[2]) || faceNormal(*normal[3]))) {
        const bool first = foldsAlong(pos, 0, 1, 2, 3), second = foldsAlong(pos, 1, 2, 3, 0);
        if (first != second) alongFirst = second;
    }
    if (alongFirst) {
        out.push_back({id[0], id[1], id[2]});
        out.push_back({id[0], id[2], id[3]});
    } else {
        out.push_back({id[0], id[1], id[3]});
        out.push_back({id[1], id[2], id[3]});
    }
}

class Contourer {
    struct CellQef; // a cell's QEF and sums (below)

  public:
    Contourer(const ImplicitField& field, const MeshOptions& options, const Grid& grid)
        : field_(field), options_(options), grid_(grid),
          minCell_(std::min({grid.h[0], grid.h[1], grid.h[2]})) {}

    // Phase 1: corner values, edge crossings and cell vertices of one block.
    void sampleBlock(Block& block, FieldSampler& sampler, Observations& seen) {
        const BlockCoord& b = block.coord;
        // The formula simplified for this block (tape_simplify.h): every
        // point sampled below lies in a cell of the block or, for a vertex's
        // gradient, at most kVertexRoom of a cell outside it — within a cell
        // of its faces, the margin narrowed to.
        std::optional<field::Narrowing> narrowed;
        if (options_.simplifyPerBlock && block.narrowed)
            narrowed.emplace(sampler, block.tape);
        else if (options_.simplifyPerBlock) {
            const auto box = grid_.blocksAndACell(b, {b[0] + 1, b[1] + 1, b[2] + 1});
            narrowed.emplace(sampler, box[0], box[1]);
        }
        block.tape.reset();
        // Which corners to evaluate: those of the octants the intervals
        // cannot rule out.
        CornerBits needed{};
        markNeededCorners(block, sampler, seen, needed);
        // Their coordinates, per axis.
        std::array<std::array<double, kC>, 3> along{};
        for (std::size_t a = 0; a < 3; ++a)
            for (int n = 0; n < kC; ++n)
                along[a][std::size_t(n)] = grid_.coordinate(a, long(b[a]) * kB + n);
        std::size_t count = 0;
        for (std::size_t w = 0; w < needed.size(); ++w)
            for (std::uint64_t bits = needed[w]; bits != 0; bits &= bits - 1) {
                const int c = int(w * 64 + std::size_t(std::countr_zero(bits)));
                const auto [ci, cj, ck] = cornerAt(c);
                cornerX_[count] = along[0][std::size_t(ci)];
                cornerY_[count] = along[1][std::size_t(cj)];
                cornerZ_[count] = along[2][std::size_t(ck)];
                evaluated_[count++] = c;
            }
        out_.resize(count);
        if (count != 0)
            sampler.values(cornerX_.data(), cornerY_.data(), cornerZ_.data(), count, out_.data());
        // (values_ is read only where a corner was evaluated: no clearing.)
        allInBox_ = blockInBox(block);
        // Which corners are known (evaluated and defined, or margin of a
        // closed box: out) and inside, a row of bits at a time in registers;
        // without branches on the values where it can (half the corners near
        // the surface are inside: a branch on it is mispredicted), and with
        // the running maxima in registers, not in `seen` (the block's first
        // highest corner and first undefined one, in corner order).
        double maxValue = -std::numeric_limits<double>::infinity(), maxAbs = seen.maxAbs;
        std::size_t maxAt = count, nanAt = count; // none
        for (std::size_t w = 0, n = 0; w < needed.size(); ++w) {
            std::uint64_t known = 0, insideRow = 0;
            for (std::uint64_t bits = needed[w]; bits != 0; bits &= bits - 1, ++n) {
                const auto c = std::size_t(evaluated_[n]);
                const double v = out_[n];
                values_[c] = v;
                const std::uint64_t bit = std::uint64_t(1) << (c % 64);
                if (!allInBox_ && !cornerInBox(block, int(c))) {
                    known |= bit; // margin of a closed box: out
                    continue;
                }
                const bool defined = !std::isnan(v), in = inside(v);
                known |= bit & (std::uint64_t(0) - std::uint64_t(defined));
                insideRow |= bit & (std::uint64_t(0) - std::uint64_t(in));
                if (!defined) {
                    nanAt = std::min(nanAt, n);
                    continue;
                }
                if (v > maxValue) {
                    maxValue = v;
                    maxAt = n;
                }
                const double size = std::abs(v);
                maxAbs = size < std::numeric_limits<double>::infinity() ? std::max(maxAbs, size)
                                                                        : maxAbs;
            }
            known_[w] = known;
            insideBits_[w] = insideRow;
        }
        seen.maxAbs = maxAbs;
        if (maxAt != count)
            seen.offerMax(maxValue, {cornerX_[maxAt], cornerY_[maxAt], cornerZ_[maxAt]});
        if (nanAt != count) seen.offerNaN({cornerX_[nanAt], cornerY_[nanAt], cornerZ_[nanAt]});
        // Only sub-blocks with corners on both sides hold sign-changing edges.
        const auto& subCorners = subBlockCorners();
        std::erase_if(kept_, [&](std::uint8_t sub) {
            const SubBlockCorners& m = subCorners[sub];
            std::uint64_t in = 0, out = 0;
            for (std::size_t k = 0; k < 4 && m.first + k < known_.size(); ++k) {
                in |= insideBits_[m.first + k] & m.mask[k];
                out |= known_[m.first + k] & ~insideBits_[m.first + k] & m.mask[k];
            }
            return in == 0 || out == 0;
        });
        computeCrossings(block, sampler);
        block.cells.clear();
        block.positions.clear();
        block.normals.clear();
        configs_.fill(-1); // only cells of kept sub-blocks can hold surface
        setKeptCellConfigs();
        buildVertices(block, sampler);
    }

    // The corner configuration of each cell of the kept sub-blocks (bit i:
    // corner i = x + 2y + 4z inside), or -1 where some corner is undefined
    // or was never evaluated. A sub-block's 27 corners are 9 rows of 3 along
    // x in the bit rows, read once (reading each cell's 8 corners again made
    // this 4% of a re-mesh); a cell takes two of each of its 4 rows.
    void setKeptCellConfigs() {
        for (std::uint8_t sub : kept_) {
            const auto [si, sj, sk] = subBlockOrigin(sub);
            unsigned known[3][3], in[3][3]; // [z][y], 3 corners along x
            for (int dz = 0; dz < 3; ++dz)
                for (int dy = 0; dy < 3; ++dy) {
                    const int c = cornerIndex(si, sj + dy, sk + dz);
                    known[dz][dy] = threeBits(known_, c);
                    in[dz][dy] = threeBits(insideBits_, c);
                }
            for (int cell = 0; cell < 8; ++cell) {
                const int x = cell & 1, y = (cell >> 1) & 1, z = cell >> 2;
                unsigned k = 0, config = 0;
                for (int r = 0; r < 4; ++r) { // the cell's rows: y + (r & 1), z + (r >> 1)
                    k |= (known[z + (r >> 1)][y + (r & 1)] >> x & 3u) << (2 * r);
                    config |= (in[z + (r >> 1)][y + (r & 1)] >> x & 3u) << (2 * r);
                }
                configs_[std::size_t(cellIndex(si + x, sj + y, sk + z))] =
                    std::int16_t(k == 0xFFu ? int(config) : -1);
            }
        }
    }

    // Phase 2: the quads around every sign-changing edge this block owns
    // that the sampling pass could not make (those on its lower faces).
    // Fills `missing` with the blocks of neighbouring cells that were never
    // sampled (their quads are left for the next round).
    void connectBlock(Block& block, std::vector<BlockCoord>& missing) {
        block.triangles.clear();
        block.triangles.reserve(2 * block.lowerFaceEdges.size());
        const BlockCoord& b = block.coord;
        // The 27 blocks around (and including) this one, looked up once: a
        // column's three (along z) lie next to each other in the sorted list.
        for (int column = 0; column < 9; ++column) {
            const int x = b[0] + column % 3 - 1, y = b[1] + column / 3 - 1;
            for (int dz = 0; dz < 3; ++dz) {
                const std::size_t n = std::size_t(dz * 9 + column);
                neighbourCoords_[n] = {x, y, b[2] + dz - 1};
                neighbours_[n] = nullptr;
            }
            if (x < 0 || y < 0) continue;
            const std::uint64_t first = keyOf({x, y, std::max(b[2] - 1, 0)}),
                                last = keyOf({x, y, b[2] + 1});
            const std::vector<std::uint64_t>& keys = *keys_;
            for (auto it = std::lower_bound(keys.begin(), keys.end(), first);
                 it != keys.end() && *it <= last; ++it) {
                const Block& other = (*blocks_)[std::size_t(it - keys.begin())];
                neighbours_[std::size_t((other.coord[2] - b[2] + 1) * 9 + column)] = &other;
            }
        }
        for (const std::uint32_t edge : block.lowerFaceEdges) {
            const auto [local, axis, lowerIn] = lowerFaceEdge(edge);
            quad(block, axis, local.data(), lowerIn, missing);
        }
        // (The list stays: a later round, after sampling a block an interval
        // wrongly ruled out, connects every block again.)
    }

    // The blocks, sorted by key, and their keys, shared by every thread's
    // contourer (read only while connecting): a binary search of the keys
    // finds a neighbour (8 bytes a block, where probing the blocks touched
    // a cache line of each).
    void index(const std::vector<Block>& blocks, const std::vector<std::uint64_t>& keys) {
        blocks_ = &blocks;
        keys_ = &keys;
    }

  private:
    // The box of cells [c0, c1) of this block (clamped to the grid), or false
    // when it holds no cell.
    bool cellBox(const Block& block, const int c0[3], const int c1[3], Vec3& lo, Vec3& hi) const {
        for (std::size_t a = 0; a < 3; ++a) {
            const long first = long(block.coord[a]) * kB + c0[a];
            const long last = std::min<long>(long(block.coord[a]) * kB + c1[a], grid_.cells[a]);
            if (first >= last) return false;
            lo[a] = grid_.origin[a] + double(first) * grid_.h[a];
            hi[a] = grid_.origin[a] + double(last) * grid_.h[a];
        }
        return true;
    }

    static bool mayCross(const formula::Interval& r) { return !r.empty() && r.lo <= 0 && r.hi > 0; }

    // Which corners to evaluate: those of the block's 4x4x4-cell octants whose
    // interval may hold a zero. Their 2x2x2-cell sub-blocks are the candidates
    // for surface (sampleBlock keeps those with corners on both sides). Asking
    // the intervals of the sub-blocks too would save about 5 corner values per
    // interval, but an interval costs more than 5 values of the batch
    // evaluator (a gyroid's 25x as much): 14% slower on the gyroid at 512.
    void markNeededCorners(Block& block, FieldSampler& sampler, Observations& seen,
                           CornerBits& needed) {
        kept_.clear();
        for (int octant = 0; octant < 8; ++octant) {
            const int o0[3] = {(octant & 1) * 4, ((octant >> 1) & 1) * 4, ((octant >> 2) & 1) * 4};
            const int o1[3] = {o0[0] + 4, o0[1] + 4, o0[2] + 4};
            Vec3 lo{}, hi{};
            if (!cellBox(block, o0, o1, lo, hi)) continue;
            const formula::Interval r = sampler.interval(lo, hi);
            if (!mayCross(r)) {
                // Ruled out where f may be undefined: a place to look for NaN.
                if (r.nan)
                    seen.offerUndefinedCandidate(
                        Vec3{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2});
                continue;
            }
            // Its sub-blocks with a cell in the grid (an octant at the grid's
            // far end may stick out), and their corners.
            for (int sub = 0; sub < 8; ++sub) {
                const int s0[3] = {o0[0] + (sub & 1) * 2, o0[1] + ((sub >> 1) & 1) * 2,
                                   o0[2] + ((sub >> 2) & 1) * 2};
                bool inGrid = true;
                for (std::size_t a = 0; a < 3; ++a)
                    inGrid = inGrid && long(block.coord[a]) * kB + s0[a] < grid_.cells[a];
                if (!inGrid) continue;
                const std::uint8_t index = subBlockIndex(s0);
                kept_.push_back(index);
                const SubBlockCorners& m = subBlockCorners()[index];
                for (std::size_t k = 0; k < 4 && m.first + k < needed.size(); ++k)
                    needed[m.first + k] |= m.mask[k];
            }
        }
    }

    // Every sign-changing edge of the block's lattice: its crossing moved onto
    // f = 0 by regula falsi, all edges of the block at once (one batch
    // evaluation per step), and its normal from the analytic gradient.
    void computeCrossings(const Block& block, FieldSampler& sampler) {
        pending_.clear();
        found_.clear();
        throughFace_.clear();
        static constexpr int kStride[3] = {1, kC, kC * kC};
        // A sign-changing edge from corner c along `axis` (found_ takes its
        // slot: the edges come in increasing slot order).
        auto visit = [&](int axis, int c) {
            const int cb = c + kStride[axis];
            const auto [ci, cj, ck] = cornerAt(c);
            const BlockCoord& b = block.coord;
            const Vec3 pa =
                grid_.corner(long(b[0]) * kB + ci, long(b[1]) * kB + cj, long(b[2]) * kB + ck);
            const double h = grid_.h[std::size_t(axis)];
            const Vec3 pb = {axis == 0 ? pa[0] + h : pa[0], axis == 1 ? pa[1] + h : pa[1],
                             axis == 2 ? pa[2] + h : pa[2]};
            const double fa = values_[std::size_t(c)], fb = values_[std::size_t(cb)];
            const int found = int(found_.size());
            found_.push_back(axis * kCorners + c);
            const bool aInBox = allInBox_ || cornerInBox(block, c),
                       bInBox = allInBox_ || cornerInBox(block, cb);
            if (aInBox && bInBox) {
                // Made in place, every field from its value: a copy read
                // whole what was just written field by field (which the
                // processor cannot forward from its stores), and a default
                // one was zeroed first by a `rep stos` (a tenth of this loop).
                pending_.emplace_back(found, axis, pa, pb, fa, fb, firstGuess(fa, fb));
                return;
            }
            // Through a face of the closed box: the solid ends at the face,
            // or before it where f turns negative first (f at the block's
            // face points in one batch, below).
            PendingCrossing p{found, axis, pa, pb, fa, fb};
            Vec3 face = aInBox ? p.pa : p.pb;
            face[std::size_t(axis)] =
                aInBox ? field_.box.hi[std::size_t(axis)] : field_.box.lo[std::size_t(axis)];
            (aInBox ? p.pb : p.pa) = face;
            throughFace_.push_back({p, aInBox});
        };
        // The sign-changing edges: both ends evaluated and defined, one
        // inside — bit rows over the block's corners, the far ends' row the
        // near ends' shifted by the axis's stride. These are exactly the
        // kept 2x2x2-cell sub-blocks' sign-changing edges (which a walk of
        // those sub-blocks found, each shared edge twice): such an edge lies
        // in a sub-block that holds both its ends, and that sub-block has
        // corners on both sides, so it was kept.
        for (int axis = 0; axis < 3; ++axis) {
            const CornerBits far = shiftedDown(known_, kStride[axis]);
            const CornerBits farInside = shiftedDown(insideBits_, kStride[axis]);
            const CornerBits& nearEnds = edgeStarts(axis);
            for (std::size_t w = 0; w < known_.size(); ++w)
                for (std::uint64_t bits =
                         known_[w] & far[w] & (insideBits_[w] ^ farInside[w]) & nearEnds[w];
                     bits != 0; bits &= bits - 1)
                    visit(axis, int(w * 64 + std::size_t(std::countr_zero(bits))));
        }
        crossings_.resize(found_.size());
        resolveFaceCrossings(sampler);
        for (int step = 0; step < options_.refineSteps && !pending_.empty(); ++step) {
            evaluateGuesses(sampler, nullptr);
            for (std::size_t n = 0; n < pending_.size(); ++n)
                bracketStep(pending_[n], out_[n], false);
        }
        // Normals: the gradients of all the block's crossings in one call.
        // A crossing at a grid corner (f exactly 0 there: a surface through
        // the lattice, as a plane x = 0 in a box symmetric about it) may sit
        // on a crease of min/max, where the gradient is either side's; a
        // step of 1e-4 of the edge into it gives the side this edge crosses.
        // (Taken at the corner, the wedge cut out of the watermelon got one
        // plane's normal on both of its faces' crossings along their shared
        // edge, and that edge's vertices sat a cell off it.)
        crossingAt_.resize(pending_.size());
        gradientAt_.resize(pending_.size());
        for (std::size_t n = 0; n < pending_.size(); ++n)
            place(pending_[n], crossingAt_[n], gradientAt_[n]);
        gradientOut_.resize(gradientAt_.size());
        if (!gradientAt_.empty())
            sampler.gradients(gradientAt_.data(), gradientAt_.size(), gradientOut_.data());
        refineStragglers(sampler);
        for (std::size_t n = 0; n < pending_.size(); ++n) {
            const PendingCrossing& p = pending_[n];
            Crossing& x = crossings_[std::size_t(p.found)];
            x.point = crossingAt_[n];
            bool ok = false;
            x.normal = normalised(gradientOut_[n].d, ok);
            if (!ok) { // no gradient here: the edge's own direction
                x.normal = {0, 0, 0};
                x.normal[std::size_t(p.axis)] = 1;
            }
        }
    }

    // The edges through a face of the closed box: f where each meets the
    // face, in one batch. Where the solid reaches the face (or f is
    // undefined there) the crossing is that point, facing along the edge;
    // else the edge is cut at the face and its crossing refined as any other.
    void resolveFaceCrossings(FieldSampler& sampler) {
        if (throughFace_.empty()) return;
        valuesAt(sampler, throughFace_.size(), [&](std::size_t i) {
            const auto& [p, faceIsB] = throughFace_[i];
            return faceIsB ? p.pb : p.pa;
        });
        for (std::size_t n = 0; n < throughFace_.size(); ++n) {
            auto [p, aInBox] = throughFace_[n]; // (the face is b when a is in the box)
            const double ff = out_[n];
            if (inside(ff) || std::isnan(ff)) {
                Crossing& x = crossings_[std::size_t(p.found)];
                x.point = aInBox ? p.pb : p.pa;
                x.normal = {0, 0, 0};
                x.normal[std::size_t(p.axis)] = 1;
                continue;
            }
            (aInBox ? p.fb : p.fa) = ff;
            p.t = firstGuess(p.fa, p.fb);
            pending_.push_back(p);
        }
    }

    // Crossings the regula falsi steps left more than a thousandth of a cell
    // off the surface (by the value and gradient just taken there): where
    // min/max kinks f along the edge, the line through the edge's ends
    // misses the zero by much of the edge — on the watermelon, a sphere
    // crossing put a tenth of a cell up the edge, inside the solid, with the
    // cut plane's normal — and plain regula falsi crawls from one side.
    // These few take more steps of Illinois's variant (the end kept twice
    // has its value halved, so the bracket closes from both sides), then
    // their gradients again. A smooth field's crossings never come here.
    void refineStragglers(FieldSampler& sampler) {
        constexpr int kMoreSteps = 12;
        constexpr double kOffBy = 1e-3; // of the cell
        stragglers_.clear();
        for (std::size_t n = 0; n < pending_.size(); ++n) {
            const PendingCrossing& p = pending_[n];
            const formula::Dual& g = gradientOut_[n];
            const double slope = field::length(g.d);
            if (!(slope > 0) || !std::isfinite(g.v)) continue;
            if (std::abs(g.v) > kOffBy * grid_.h[std::size_t(p.axis)] * slope)
                stragglers_.push_back(n);
        }
        if (stragglers_.empty()) return;
        for (std::size_t n : stragglers_)
            pending_[n].done = false;
        for (int step = 0; step < kMoreSteps; ++step) {
            evaluateGuesses(sampler, &stragglers_);
            bool any = false;
            for (std::size_t i = 0; i < stragglers_.size(); ++i)
                any = bracketStep(pending_[stragglers_[i]], out_[i], true) || any;
            if (!any) break;
        }
        gradientAt_.resize(stragglers_.size());
        for (std::size_t i = 0; i < stragglers_.size(); ++i)
            place(pending_[stragglers_[i]], crossingAt_[stragglers_[i]], gradientAt_[i]);
        redoneOut_.resize(stragglers_.size());
        sampler.gradients(gradientAt_.data(), stragglers_.size(), redoneOut_.data());
        for (std::size_t i = 0; i < stragglers_.size(); ++i)
            gradientOut_[stragglers_[i]] = redoneOut_[i];
    }

    // Where the line through the edge's ends meets zero — or the middle,
    // where that is no number on the edge (an end at ±inf gives inf / inf):
    // a guess off the edge would be evaluated outside the block.
    static double firstGuess(double fa, double fb) {
        const double t = fa / (fa - fb);
        return t >= 0 && t <= 1 ? t : 0.5;
    }
    // (Each coordinate chosen, not the axis's written into a copy of pa: a
    // store at a variable index, then the point read whole, waited for the
    // store to drain — a tenth of the sphere's crossings.)
    static Vec3 pointOnEdge(const PendingCrossing& p, double t) {
        const std::size_t a = std::size_t(p.axis);
        const double along = p.pa[a] + t * (p.pb[a] - p.pa[a]);
        return {a == 0 ? along : p.pa[0], a == 1 ? along : p.pa[1], a == 2 ? along : p.pa[2]};
    }
    // The crossing's point at its current guess, and where its gradient is
    // taken (kIntoTheEdge inside the edge when the guess is at a corner).
    static void place(const PendingCrossing& p, Vec3& point, Vec3& gradientAt) {
        const double t = std::clamp(p.t, 0.0, 1.0);
        point = pointOnEdge(p, t);
        gradientAt = pointOnEdge(p, std::clamp(t, kIntoTheEdge, 1 - kIntoTheEdge));
    }
    // f at the current guesses of the crossings `which` names (all pending
    // ones for none), into out_, in one batch.
    void evaluateGuesses(FieldSampler& sampler, const std::vector<std::size_t>* which) {
        const std::size_t count = which ? which->size() : pending_.size();
        valuesAt(sampler, count, [&](std::size_t i) {
            const PendingCrossing& p = pending_[which ? (*which)[i] : i];
            return pointOnEdge(p, p.t);
        });
    }
    // f at `count` points (pointAt(i)), in one batch, into out_.
    template <class PointAt>
    void valuesAt(FieldSampler& sampler, std::size_t count, PointAt pointAt) {
        if (xs_.size() < count) { // grown only, written in place (no check per point)
            xs_.resize(count);
            ys_.resize(count);
            zs_.resize(count);
        }
        for (std::size_t i = 0; i < count; ++i) {
            const Vec3 q = pointAt(i);
            xs_[i] = q[0];
            ys_[i] = q[1];
            zs_[i] = q[2];
        }
        out_.resize(count);
        sampler.values(xs_.data(), ys_.data(), zs_.data(), count, out_.data());
    }
    // One regula falsi step of a crossing given f at its guess: the bracket
    // keeps the end on f's other side and the next guess is where the line
    // through the ends meets zero. With `illinois`, an end kept twice has
    // its value halved (so a kinked f is closed in from both sides) and a
    // bracket narrower than 1e-12 of the edge ends the search. False once
    // the crossing is done (f exactly 0, undefined, or no better guess).
    static bool bracketStep(PendingCrossing& p, double f, bool illinois) {
        if (p.done) return false;
        if (!std::isfinite(f) || f == 0) {
            p.done = true;
            return false;
        }
        if (inside(f) == inside(p.fa)) {
            p.ta = p.t;
            p.fa = f;
            if (illinois && p.kept == 1) p.fb /= 2; // b kept twice
            if (illinois) p.kept = 1;
        } else {
            p.tb = p.t;
            p.fb = f;
            if (illinois && p.kept == -1) p.fa /= 2; // a kept twice
            if (illinois) p.kept = -1;
        }
        const double next = p.ta - p.fa * (p.tb - p.ta) / (p.fb - p.fa);
        if (!(next >= p.ta && next <= p.tb) || (illinois && p.tb - p.ta < 1e-12)) {
            p.done = true;
            return false;
        }
        p.t = next;
        return true;
    }

    // One vertex per cell the crossings touch: each crossing adds its plane
    // to the QEFs of the (up to) four cells of this block around its edge.
    void buildVertices(Block& block, FieldSampler& sampler) {
        const long base[3] = {long(block.coord[0]) * kB, long(block.coord[1]) * kB,
                              long(block.coord[2]) * kB};
        // The block's cells along each axis (fewer at the grid's far end).
        const long limit[3] = {std::min<long>(kB, grid_.cells[0] - base[0]),
                               std::min<long>(kB, grid_.cells[1] - base[1]),
                               std::min<long>(kB, grid_.cells[2] - base[2])};
        around_.assign(found_.size(), {-1, -1, -1, -1});
        normalAt_.clear();
        normalOf_.clear();
        normalEntry_.clear();
        // Cell q around an edge along `axis` lies at -(q & 1) along u and
        // -(q >> 1) along v from the edge's first corner: its index from the
        // corner's, and the edge as that cell numbers it.
        static constexpr int kU[3] = {1, 2, 0}, kV[3] = {2, 0, 1};
        static constexpr int kCellStride[3] = {1, kB, kB * kB};
        static const auto kEdge = [] {
            std::array<std::array<std::int8_t, 4>, 3> e{};
            for (int a = 0; a < 3; ++a)
                for (int q = 0; q < 4; ++q)
                    e[std::size_t(a)][std::size_t(q)] = std::int8_t(cubeEdge(a, q & 1, q >> 1));
            return e;
        }();
        // First which (cell, piece) each crossing adds to, marked in a byte
        // each (a store, no read: a bit set's read-modify-write made each
        // step wait on the one before), then their QEFs numbered in index
        // order, then the adding: one pass doing all waited on the chain
        // from a cell to its piece, its entry and its sums at every step.
        for (std::size_t n = 0; n < found_.size(); ++n) {
            const int slot = found_[n];
            const int axis = slot / kCorners, c = slot % kCorners;
            const std::array<int, 3> corner = cornerAt(c);
            const int u = kU[axis], v = kV[axis];
            if (corner[std::size_t(axis)] >= limit[axis]) continue; // on the block's far face
            // Which of the four cells lie in the block (and the grid).
            const bool inU[2] = {corner[std::size_t(u)] < limit[u],
                                 corner[std::size_t(u)] >= 1 && corner[std::size_t(u)] <= limit[u]};
            const bool inV[2] = {corner[std::size_t(v)] < limit[v],
                                 corner[std::size_t(v)] >= 1 && corner[std::size_t(v)] <= limit[v]};
            const int own = (corner[2] * kB + corner[1]) * kB + corner[0];
            for (int q = 0; q < 4; ++q) {
                if (!inU[q & 1] || !inV[q >> 1]) continue;
                const int cell = own - (q & 1) * kCellStride[u] - (q >> 1) * kCellStride[v];
                const int index =
                    cell * kPieces + pieceOf(pieces_, configs_[std::size_t(cell)],
                                             kEdge[std::size_t(axis)][std::size_t(q)]);
                touchedMark_[std::size_t(index)] = 1;
                around_[n][std::size_t(q)] = index;
            }
        }
        // The marked entries in increasing order (eight marks a word), each
        // QEF numbered by its rank, the marks cleared for the next block.
        touched_.clear();
        static_assert(std::endian::native == std::endian::little, "mark i of a word is byte i");
        for (std::size_t i = 0; i < touchedMark_.size(); i += 8) {
            std::uint64_t marks = 0;
            std::memcpy(&marks, &touchedMark_[i], sizeof marks);
            for (; marks != 0; marks &= marks - 1) {
                const std::size_t index = i + std::size_t(std::countr_zero(marks)) / 8;
                qefSlot_[index] = std::uint16_t(touched_.size());
                touched_.push_back(int(index));
                touchedMark_[index] = 0;
            }
        }
        const std::size_t qefCount = touched_.size();
        for (std::array<int, 4>& cells : around_) // entries -> their QEFs' places
            for (int& cell : cells)
                if (cell >= 0) cell = qefSlot_[std::size_t(cell)];
        if (qefs_.size() < qefCount) qefs_.resize(qefCount);
        // Every cell's sums about the block's first corner: a crossing's
        // share is then the same for its four cells, made once. First the
        // few a smooth cell's vertex needs (balancedFromMassPoint: points,
        // outward normals, offsets, count); the QEF's (16 sums a crossing
        // and cell, most of the adding) only for the cells that turn out to
        // need it — a crease, or a curvature out of bounds — in a second
        // pass over the crossings in the same order, so its sums and
        // solution are what adding everything once gave.
        const Vec3 origin = grid_.corner(base[0], base[1], base[2]);
        for (std::size_t k = 0; k < qefCount; ++k)
            qefs_[k].reset();
        for (std::size_t n = 0; n < found_.size(); ++n) {
            const std::array<int, 4>& cells = around_[n];
            if (cells[0] < 0 && cells[1] < 0 && cells[2] < 0 && cells[3] < 0) continue;
            const int slot = found_[n];
            const Crossing& x = crossings_[n];
            const int axis = slot / kCorners, c = slot % kCorners;
            // Outward: along the edge from its inside corner to its outside one.
            const bool lowerIn = isInside(c);
            const double sign = (x.normal[std::size_t(axis)] >= 0) == lowerIn ? 1.0 : -1.0;
            const Vec3 signedNormal{sign * x.normal[0], sign * x.normal[1], sign * x.normal[2]};
            const Vec3 at{x.point[0] - origin[0], x.point[1] - origin[1], x.point[2] - origin[2]};
            double offset = 0;
            for (std::size_t k = 0; k < 3; ++k)
                offset += signedNormal[k] * at[k];
            for (std::size_t q = 0; q < 4; ++q) {
                if (cells[q] < 0) continue;
                CellQef& cq = qefs_[std::size_t(cells[q])];
                for (std::size_t k = 0; k < 3; ++k) {
                    cq.pointSum[k] += at[k];
                    cq.normalSum[k] += signedNormal[k];
                }
                cq.offsetSum += offset;
                cq.count += 1.0;
            }
        }
        // Where the crossings' analytic normals agree (a smooth patch: most
        // cells), their mean is the vertex normal and the balanced vertex
        // has a closed form; where they do not (a crease, a corner, a box
        // face) the QEF places the vertex and the gradient there decides.
        bool anyQef = false;
        for (std::size_t entry = 0; entry < qefCount; ++entry) {
            CellQef& cq = qefs_[entry];
            cq.length = cq.normalLength();
            cq.smooth = cq.length > 0.9995 * cq.count;
            if (cq.smooth) {
                const auto [cellLo, cellHi] = vertexRoom(base, touched_[entry] / kPieces);
                if (const auto v = balancedFromMassPoint(cq, origin, cellLo, cellHi)) {
                    cq.balanced = *v;
                    continue;
                }
            }
            cq.needsQef = anyQef = true;
            cq.qef.reset(origin);
        }
        for (std::size_t n = 0; anyQef && n < found_.size(); ++n) {
            const std::array<int, 4>& cells = around_[n];
            bool wanted = false;
            for (std::size_t q = 0; q < 4; ++q)
                wanted = wanted || (cells[q] >= 0 && qefs_[std::size_t(cells[q])].needsQef);
            if (!wanted) continue;
            const Crossing& x = crossings_[n];
            const Qef::Plane plane = Qef::plane(origin, x.point, x.normal);
            const std::uint8_t face = allInBox_ ? 0 : boxFaceOf(x);
            for (std::size_t q = 0; q < 4; ++q)
                if (cells[q] >= 0 && qefs_[std::size_t(cells[q])].needsQef) {
                    qefs_[std::size_t(cells[q])].qef.add(plane);
                    qefs_[std::size_t(cells[q])].faces |= face;
                }
        }
        block.positions.reserve(touched_.size()); // one vertex per entry: no growth slack
        block.cells.reserve(touched_.size());     // at most one cell per entry
        block.normals.reserve(touched_.size());
        for (std::size_t entry = 0; entry < touched_.size(); ++entry) {
            const int index = touched_[entry];
            CellQef& cq = qefs_[entry];
            const int cell = index / kPieces;
            Vec3 n{}, p{};
            if (cq.smooth)
                n = {cq.normalSum[0] / cq.length, cq.normalSum[1] / cq.length,
                     cq.normalSum[2] / cq.length};
            if (!cq.needsQef) {
                p = cq.balanced;
            } else {
                // The vertex may sit up to half a cell outside its cell:
                // where a crease passes just beside the cell, both of its
                // surfaces cross the cell but their meeting line does not,
                // and a vertex held in the cell lies off both (measured on
                // the watermelon at 256: max error 1.2e-3 of the diagonal
                // with the old fallback to the mass point, 6.9e-4 held in
                // the cell, under 2e-4 with half a cell of room, and fewer
                // folded triangles at its creases, not more).
                if (cq.faces) {
                    p = onBoxFaces(cq, base, cell);
                } else {
                    const auto [cellLo, cellHi] = vertexRoom(base, cell);
                    p = cq.qef.solveInBox(cellLo, cellHi, 0.1);
                }
                if (!cq.smooth) { // all of the block's such vertices at once, below
                    normalAt_.push_back(p);
                    normalOf_.push_back(std::uint32_t(block.positions.size()));
                    normalEntry_.push_back(std::uint32_t(entry));
                }
            }
            // touched_ is sorted, so a cell's pieces come in order, one after another.
            if (block.cells.empty() || block.cells.back().cell != cell)
                block.cells.push_back({std::uint16_t(cell), configs_[std::size_t(cell)],
                                       std::uint16_t(block.positions.size()), 0});
            block.cells.back().pieceMask |= std::uint8_t(1u << (index % kPieces));
            cq.vertex = std::uint32_t(block.positions.size());
            block.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
            block.normals.push_back({float(n[0]), float(n[1]), float(n[2])});
        }
        if (!normalAt_.empty()) {
            normalGradients_.resize(normalAt_.size());
            sampler.gradients(normalAt_.data(), normalAt_.size(), normalGradients_.data());
            for (std::size_t k = 0; k < normalAt_.size(); ++k) {
                const CellQef& cq = qefs_[normalEntry_[k]];
                const Vec3 n = vertexNormal(normalGradients_[k], normalAt_[k], cq.normalSum);
                block.normals[normalOf_[k]] = {float(n[0]), float(n[1]), float(n[2])};
                // The crossings' normals disagree: a curved patch, or a crease
                // (where the gradient at the vertex is one side's and far from
                // their mean, and the vertex stays where the QEF put it — or,
                // on a shallow crease, where a lower cutoff puts it).
                if (cq.faces) continue;
                const auto [cellLo, cellHi] = vertexRoom(base, touched_[normalEntry_[k]] / kPieces);
                if (smoothAround(n, cq)) {
                    const Vec3 p = balancedOnSurface(cq, normalAt_[k], origin, cellLo, cellHi);
                    block.positions[normalOf_[k]] = {float(p[0]), float(p[1]), float(p[2])};
                } else if (cq.spread() < kMaxSpread) {
                    // A crease whose sides turn by under 37 degrees: the
                    // cutoff of 0.1 dropped its direction (the vertex stayed
                    // between the sides, up to a third of a cell off both).
                    creaseAt_.push_back(cq.qef.solveInBox(cellLo, cellHi, kShallowCreaseCutoff));
                    creaseOf_.push_back(std::uint32_t(k));
                }
            }
            keepShallowCreases(block, sampler);
        }
        block.occupied.fill(0);
        for (const SurfaceCell& c : block.cells)
            block.occupied[c.cell / 64] |= std::uint64_t(1) << (c.cell % 64);
        for (std::size_t w = 0, count = 0; w < block.occupied.size(); ++w) {
            block.before[w] = std::uint16_t(count);
            count += std::size_t(std::popcount(block.occupied[w]));
        }
        makeInteriorQuads(block, limit);
    }

    // The shallow creases' vertices (buildVertices) that lie on the surface
    // — within kCreaseOnSurface cells of it to first order (by the gradient
    // at the vertex they replace, in the same cell), or nearer than that
    // vertex: a smooth patch taken for a crease would have its vertex where
    // its tangent planes meet, off the surface; a crease's lies on both of
    // its sides. (Only nearer than the old vertex was too strict: the
    // textured sphere's bumps, creased by the texture's bilinear
    // interpolation, kept vertices that measured worse.) One batch of values.
    void keepShallowCreases(Block& block, FieldSampler& sampler) {
        if (creaseAt_.empty()) return;
        valuesAt(sampler, creaseAt_.size(), [&](std::size_t i) { return creaseAt_[i]; });
        for (std::size_t i = 0; i < creaseAt_.size(); ++i) {
            const std::size_t k = creaseOf_[i];
            const formula::Dual& was = normalGradients_[k];
            const double slope = field::length(was.d);
            if (!(std::abs(out_[i]) <=
                  std::max(std::abs(was.v), kCreaseOnSurface * minCell_ * slope)))
                continue;
            const Vec3& p = creaseAt_[i];
            block.positions[normalOf_[k]] = {float(p[0]), float(p[1]), float(p[2])};
        }
        creaseAt_.clear();
        creaseOf_.clear();
    }

    // The quads around the crossings this block owns whose four cells all lie
    // in it: most of them, made here from what buildVertices knows, without
    // looking anything up (the connect phase does the rest).
    // (`limit`: the block's cells along each axis, as buildVertices has them.)
    void makeInteriorQuads(Block& block, const long limit[3]) {
        // Not owned by the next block, no cell of the one before around it,
        // and not at the border of the grid (left open there).
        // Those on a lower face go to the connect phase: the ones a walk of
        // the kept sub-blocks' cells would find (the cell the edge starts
        // from lies in a kept sub-block and in the grid), in its order.
        std::uint64_t keptSubs = 0;
        for (std::uint8_t sub : kept_)
            keptSubs |= std::uint64_t(1) << sub;
        interiorCrossings_.clear();
        lowerFaceEdges_.clear();
        for (std::size_t n = 0; n < found_.size(); ++n) {
            const int axis = found_[n] / kCorners, c = found_[n] % kCorners;
            const std::array<int, 3> corner = cornerAt(c);
            const std::array<int, 4>& cells = around_[n];
            if (corner[0] >= kB || corner[1] >= kB || corner[2] >= kB) continue;
            if (corner[std::size_t((axis + 1) % 3)] == 0 ||
                corner[std::size_t((axis + 2) % 3)] == 0) {
                const int s0[3] = {corner[0] & ~1, corner[1] & ~1, corner[2] & ~1};
                if ((keptSubs >> subBlockIndex(s0) & 1u) && corner[0] < limit[0] &&
                    corner[1] < limit[1] && corner[2] < limit[2])
                    lowerFaceEdges_.push_back(packLowerFaceEdge(c, axis, isInside(c)));
            } else if (cells[0] >= 0 && cells[1] >= 0 && cells[2] >= 0 && cells[3] >= 0) {
                interiorCrossings_.push_back(n);
            }
        }
        // Gathered here, kept at their exact size (the block's arena never
        // takes back what growing would leave behind).
        std::sort(lowerFaceEdges_.begin(), lowerFaceEdges_.end());
        block.lowerFaceEdges.assign(lowerFaceEdges_.begin(), lowerFaceEdges_.end());
        block.interior.clear();
        block.interior.reserve(2 * interiorCrossings_.size()); // exact: the budget counts capacity
        for (std::size_t n : interiorCrossings_) {
            const int c = found_[n] % kCorners;
            // buildVertices' cell q lies at (-(q & 1), -(q >> 1)) in (u, v);
            // the quad goes round (-1,-1), (0,-1), (0,0), (-1,0) as connect's.
            std::array<std::uint32_t, 4> ids{};
            static constexpr int kOrder[4] = {3, 2, 0, 1};
            for (std::size_t q = 0; q < 4; ++q)
                ids[q] = qefs_[std::size_t(around_[n][std::size_t(kOrder[q])])].vertex;
            if (!isInside(c)) std::swap(ids[1], ids[3]);
            std::array<const Vec3f*, 4> pos{}, normal{};
            for (std::size_t q = 0; q < 4; ++q) {
                pos[q] = &block.positions[ids[q]];
                normal[q] = &block.normals[ids[q]];
            }
            appendQuad(block.interior, ids, pos, normal, !allInBox_);
        }
    }

    // Whether a lattice corner lies in the domain box (always, when open).
    bool inBox(long i, long j, long k) const {
        if (field_.boundary != BoxBoundary::Closed) return true;
        return i > 0 && j > 0 && k > 0 && i < grid_.cells[0] && j < grid_.cells[1] &&
               k < grid_.cells[2];
    }
    // Whether every corner of the block lies in the domain box (most blocks:
    // then no corner needs asking).
    bool blockInBox(const Block& block) const {
        const long i = long(block.coord[0]) * kB, j = long(block.coord[1]) * kB,
                   k = long(block.coord[2]) * kB;
        return inBox(i, j, k) && inBox(i + kB, j + kB, k + kB);
    }
    bool cornerInBox(const Block& block, int c) const {
        const auto [ci, cj, ck] = cornerAt(c);
        return inBox(long(block.coord[0]) * kB + ci, long(block.coord[1]) * kB + cj,
                     long(block.coord[2]) * kB + ck);
    }

    // The box a cell's vertex may take: the cell widened by `room` cells.
    std::pair<Vec3, Vec3> vertexRoom(const long base[3], int cell,
                                     double room = kVertexRoom) const {
        const int ci = cell % kB, cj = (cell / kB) % kB, ck = cell / (kB * kB);
        const Vec3 lo = grid_.corner(base[0] + ci, base[1] + cj, base[2] + ck);
        Vec3 cellLo{}, cellHi{};
        for (std::size_t k = 0; k < 3; ++k) {
            cellLo[k] = lo[k] - room * grid_.h[k];
            cellHi[k] = lo[k] + (1 + room) * grid_.h[k];
        }
        return {cellLo, cellHi};
    }

    // The closed box's face a crossing lies on, as a bit (2 a for the low
    // face across axis a, 2 a + 1 for the high one), or 0: where the solid
    // reaches a face, resolveFaceCrossings puts the crossing on it, facing
    // along the edge, exactly.
    std::uint8_t boxFaceOf(const Crossing& x) const {
        for (std::size_t a = 0; a < 3; ++a) {
            if (x.normal[a] != 1) continue;
            if (x.point[a] == field_.box.lo[a]) return std::uint8_t(1u << (2 * a));
            if (x.point[a] == field_.box.hi[a]) return std::uint8_t(1u << (2 * a + 1));
        }
        return 0;
    }

    // The vertex of a cell that holds part of a closed box's face and part
    // of the shape's surface: on the face (or the edge or corner where
    // faces meet) — a plane known exactly — and there where the shape's
    // planes meet it. The QEF of all planes could not find that crease
    // where the shape meets the face at a shallow angle (its small
    // eigenvalue under the cutoff): the gyroid cut by its box had vertices
    // a third of a cell from both, max error 7.8e-4 of the diagonal at 256
    // where the rest of the mesh was under 1.4e-5.
    // Where the angle is shallow, the crease may pass a cell or more away
    // from where the surface crosses this cell's edges: the vertex may go
    // kFaceVertexRoom cells out of its cell along the face (max error at
    // 256 7.8e-4 -> 4.4e-4 held in kVertexRoom, 5.2e-5 in 1.5 cells).
    Vec3 onBoxFaces(const CellQef& cq, const long base[3], int cell) const {
        std::array<bool, 3> held{};
        Vec3 at{};
        for (std::size_t a = 0; a < 3; ++a) {
            held[a] = (cq.faces >> (2 * a) & 3u) != 0;
            at[a] = (cq.faces >> (2 * a) & 1u) ? field_.box.lo[a] : field_.box.hi[a];
        }
        // (Within the box: the room of a cell by another face would
        // reach past it.)
        auto [lo, hi] = vertexRoom(base, cell, kFaceVertexRoom);
        for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = std::max(lo[a], field_.box.lo[a]);
            hi[a] = std::min(hi[a], field_.box.hi[a]);
        }
        return cq.qef.solveOnPlanes(held, at, lo, hi, 0.1);
    }

    // Whether a cell whose crossings' normals disagree is a curved patch
    // rather than a crease, by the unit normal n at its vertex: on a smooth
    // surface the crossings' mean normal is the normal at their centre to
    // second order, so n lies far closer to it than the crossings' normals
    // do; across a crease n is one side's, as far from the mean as they
    // are (unless nearly all crossings lie on that side, where the crease
    // barely moves the vertex anyway).
    static bool smoothAround(const Vec3& n, const CellQef& cq) {
        const double length = cq.length;
        if (!(length > 0)) return false;
        const double along =
            (n[0] * cq.normalSum[0] + n[1] * cq.normalSum[1] + n[2] * cq.normalSum[2]) / length;
        const double spread = cq.spread();
        return spread < kMaxSpread && 1 - along < kCreaseTest * spread;
    }

    // A smooth patch's vertex moved along the crossings' mean normal n to
    // where a mesh deviates least from a curved surface. The QEF's vertex
    // lies on the crossings' tangent planes on average, which a convex
    // patch keeps outside it (by kappa d^2 / 2 at a lateral distance d):
    // the vertex sat up to 1.3 % of a cell off the sphere, and those
    // vertices were the mesh's largest deviation. Each crossing i (point p_i,
    // outward normal n_i) gives the height of v above the surface to second
    // order as n_i.(v - p_i) + (n - n_i).(v - p_i) / 2, the second term half
    // its curvature term kappa d^2. Averaged: the height H = D + c / 2, with
    // D the mean distance above the planes and c the mean curvature term
    // (from the cell's sums, nothing stored per crossing). A flat triangle
    // between vertices on a convex surface lies inside it by up to about
    // c / 2 (the sagitta across its circumcircle), so the least largest
    // deviation puts the vertices kSurfaceLift * c above the surface (a
    // concave patch, c < 0, the other way). Bounded: c of a few cells means
    // the second-order picture is wrong; the move stays small, in the room.
    Vec3 balancedOnSurface(const CellQef& cq, const Vec3& p, const Vec3& origin, const Vec3& lo,
                           const Vec3& hi) const {
        const Vec3& sum = cq.normalSum;
        const double length = cq.length;
        if (!(length > 0)) return p;
        const double perPlane = 1.0 / cq.count, perLength = 1.0 / length;
        const Vec3& points = cq.pointSum; // about origin
        double planes = -cq.offsetSum, aboveMean = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const double v = p[a] - origin[a];
            planes += sum[a] * v;
            aboveMean += sum[a] * (v - points[a] * perPlane);
        }
        const double d = planes * perPlane, c = aboveMean * perLength - d;
        const double cell = minCell_;
        if (!(std::abs(c) < kMaxCurvatureTerm * cell)) return p;
        const double shift =
            std::clamp(kSurfaceLift * c - (d + c / 2), -kMaxShift * cell, kMaxShift * cell) *
            perLength;
        return {std::clamp(p[0] + shift * sum[0], lo[0], hi[0]),
                std::clamp(p[1] + shift * sum[1], lo[1], hi[1]),
                std::clamp(p[2] + shift * sum[2], lo[2], hi[2])};
    }

    // balancedOnSurface for a cell whose crossings' normals agree, straight
    // from the crossings' mass point c: the QEF's answer there lies on the
    // line through c along their mean normal n (its other eigenvalues are
    // below any cutoff), and so does the balanced vertex, so the QEF need
    // not be solved. Along that line v = c + s n the mean distance above the
    // planes is D_c + s L (L = |sum of normals| / count, about 1) and the
    // curvature term s (1 - L) - D_c, both linear in s: the height
    // D + c / 2 equals kSurfaceLift * c at
    //   s = -D_c (1/2 + kSurfaceLift) / (L + (1/2 - kSurfaceLift) (1 - L)).
    // Nothing when the curvature term is out of bounds (the caller solves
    // the QEF then, and keeps its vertex).
    std::optional<Vec3> balancedFromMassPoint(const CellQef& cq, const Vec3& origin, const Vec3& lo,
                                              const Vec3& hi) const {
        const double length = cq.length;
        const double perPlane = 1.0 / cq.count, share = length * perPlane;
        const Vec3& points = cq.pointSum; // about origin
        double planes = -cq.offsetSum;
        for (std::size_t a = 0; a < 3; ++a)
            planes += cq.normalSum[a] * points[a] * perPlane;
        const double atMass = planes * perPlane;
        const double s =
            -atMass * (0.5 + kSurfaceLift) / (share + (0.5 - kSurfaceLift) * (1 - share));
        const double curvature = s * (1 - share) - atMass;
        if (!(std::abs(curvature) < kMaxCurvatureTerm * minCell_) || !(length > 0))
            return std::nullopt;
        const double along = s / length;
        Vec3 v{};
        for (std::size_t a = 0; a < 3; ++a)
            v[a] = std::clamp(origin[a] + points[a] * perPlane + along * cq.normalSum[a], lo[a],
                              hi[a]);
        return v;
    }

    // Outward unit normal at a vertex: the box face's where the vertex is
    // nearer to a face than to the shape's surface (closed boundary), else
    // -grad f; where the gradient vanishes, the crossings' normals.
    // (d: f and its gradient at p, from one batch for the block's vertices.)
    Vec3 vertexNormal(const formula::Dual& d, const Vec3& p, const Vec3& crossingNormals) const {
        bool ok = false;
        Vec3 n = normalised({-d.d[0], -d.d[1], -d.d[2]}, ok);
        if (field_.boundary == BoxBoundary::Closed) {
            const double g = field::length(d.d);
            double surface = ok && std::isfinite(d.v) ? std::abs(d.v) / g
                                                      : std::numeric_limits<double>::infinity();
            for (std::size_t a = 0; a < 3; ++a) {
                const double toLo = p[a] - field_.box.lo[a], toHi = field_.box.hi[a] - p[a];
                if (toLo < surface) {
                    surface = toLo;
                    n = {0, 0, 0};
                    n[a] = -1;
                    ok = true;
                }
                if (toHi < surface) {
                    surface = toHi;
                    n = {0, 0, 0};
                    n[a] = 1;
                    ok = true;
                }
            }
        }
        if (!ok) n = normalised(crossingNormals, ok);
        return n;
    }

    // The vertex of the cell at `local` (possibly one block away, -1..kB),
    // or none (with its block noted as missing when it was never sampled).
    struct VertexRef {
        const Block* block = nullptr;
        std::int32_t local = -1;
    };
    VertexRef vertexAt(const int local[3], int edge, std::vector<BlockCoord>& missing) const {
        int n = 0, cell[3];
        for (int a = 2; a >= 0; --a) {
            const int d = local[a] < 0 ? 0 : local[a] >= kB ? 2 : 1;
            n = n * 3 + d;
            cell[a] = local[a] - (d - 1) * kB;
        }
        const Block* owner = neighbours_[std::size_t(n)];
        if (!owner) {
            missing.push_back(neighbourCoords_[std::size_t(n)]);
            return {};
        }
        return {owner, vertexOf(pieces_, *owner, cellIndex(cell[0], cell[1], cell[2]), edge)};
    }

    void quad(Block& block, int a, const int local[3], bool lowerInside,
              std::vector<BlockCoord>& missing) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        const long base[3] = {long(block.coord[0]) * kB, long(block.coord[1]) * kB,
                              long(block.coord[2]) * kB};
        // Around the edge, counter-clockwise seen from +a (a = u x v).
        static const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
        VertexRef refs[4];
        for (int q = 0; q < 4; ++q) {
            int c[3] = {local[0], local[1], local[2]};
            c[u] += offsets[q][0];
            c[v] += offsets[q][1];
            const long gu = base[u] + c[u], gv = base[v] + c[v];
            if (gu < 0 || gv < 0 || gu >= grid_.cells[u] || gv >= grid_.cells[v])
                return; // at the border of the grid: left open
            // The edge as seen from this cell: it starts at offset (-du, -dv).
            refs[q] = vertexAt(c, cubeEdge(a, -offsets[q][0], -offsets[q][1]), missing);
            if (refs[q].local < 0) return;
        }
        // Inside below, outside above: the surface faces +a; else the other way.
        if (!lowerInside) std::swap(refs[1], refs[3]);
        std::array<std::uint32_t, 4> ids{};
        std::array<const Vec3f*, 4> pos{}, normal{};
        for (std::size_t q = 0; q < 4; ++q) {
            ids[q] = refs[q].block->offset + std::uint32_t(refs[q].local);
            pos[q] = &refs[q].block->positions[std::size_t(refs[q].local)];
            normal[q] = &refs[q].block->normals[std::size_t(refs[q].local)];
        }
        appendQuad(block.triangles, ids, pos, normal, !blockInBox(block));
    }

  private:
    const ImplicitField& field_;
    const MeshOptions& options_;
    const Grid& grid_;
    double minCell_; // the shortest side of a cell
    const PieceTable& pieces_ = pieceTable();
    std::vector<double> xs_, ys_, zs_, out_;
    // The corners of the block being sampled that are evaluated, and where.
    std::array<int, kCorners> evaluated_{};
    std::array<double, kCorners> cornerX_{}, cornerY_{}, cornerZ_{};
    std::vector<Crossing> crossings_; // of found_'s edges, in its order
    // Of the block being sampled: the 2x2x2-cell sub-blocks that may hold
    // surface.
    std::vector<std::uint8_t> kept_;
    std::vector<PendingCrossing> pending_;
    // Edges through a closed box's face, cut there, and whether b is the face.
    std::vector<std::pair<PendingCrossing, bool>> throughFace_;
    std::array<double, kCorners> values_{}; // of the block being sampled (where evaluated)
    bool allInBox_ = true;                  // every corner of that block is in the domain box
    // A corner of the block being sampled is in the solid, out of it, or
    // where f is undefined (NaN); with a closed boundary the margin corners
    // outside the domain box are out. Corners the intervals showed to be far
    // from the surface are never evaluated, and no crossing touches them.
    CornerBits known_{};      // evaluated and defined, or margin (bit c)
    CornerBits insideBits_{}; // of those, inside
    bool isInside(int c) const { return insideBits_[std::size_t(c) / 64] >> (c % 64) & 1u; }
    std::vector<int> found_; // the block's sign-changing edges, by slot, in increasing order
    std::vector<Vec3> crossingAt_, gradientAt_;
    std::vector<std::size_t> stragglers_;  // pending_ entries refined further
    std::vector<formula::Dual> redoneOut_; // their gradients
    std::vector<formula::Dual> gradientOut_;
    // The block's vertices whose normal is the gradient there: where, which
    // vertex, their crossings' normals summed, and the gradients.
    std::vector<Vec3> normalAt_;
    std::vector<std::uint32_t> normalOf_;
    std::vector<std::uint32_t> normalEntry_; // their QEFs' places
    std::vector<Vec3> creaseAt_;             // shallow creases' vertices (keepShallowCreases)
    std::vector<std::uint32_t> creaseOf_;    // their places in normalAt_
    std::vector<formula::Dual> normalGradients_;
    struct CellQef {
        std::uint32_t vertex = 0; // block-local, once made
        bool smooth = false;      // the crossings' normals agree (see buildVertices)
        bool needsQef = false;    // the vertex comes from qef, which holds every plane
        std::uint8_t faces = 0;   // closed box faces its crossings lie on (boxFaceOf), with qef
        double count = 0;         // crossings
        Vec3 pointSum{};          // of p_i - origin
        Vec3 normalSum{};         // of the outward n_i
        double offsetSum = 0;     // of n_i . (p_i - origin): see balancedOnSurface
        double length = 0;        // |normalSum|, once every crossing is in
        Vec3 balanced{};          // balancedFromMassPoint's vertex, unless needsQef
        Qef qef;                  // filled only where needsQef
        double normalLength() const { return field::length(normalSum); }
        // 1 - |mean normal|: 0 where every crossing's normal agrees.
        double spread() const { return 1 - length / count; }
        // As new, member by member: value-initialising the whole entry
        // made a `rep stos`, whose start-up cost a few percent of meshing
        // the watermelon. (The QEF is reset where it is needed.)
        void reset() {
            vertex = 0;
            smooth = needsQef = false;
            faces = 0;
            count = 0;
            pointSum = {0.0, 0.0, 0.0};
            normalSum = {0.0, 0.0, 0.0};
            offsetSum = 0;
        }
    };
    // The QEFs of the block's touched cells and pieces, in touched_'s order,
    // and where each (cell, piece) has its own (valid if touched): kept
    // dense, as the few hundred a block touches fit in the first-level cache
    // where one entry for each of the 2 048 (cell, piece) pairs did not.
    // Entries past touched_.size() are left over from earlier blocks.
    std::vector<CellQef> qefs_;
    std::array<std::uint16_t, kCells * kPieces> qefSlot_{};
    std::array<std::uint8_t, kCells * kPieces> touchedMark_{}; // all 0 between blocks
    std::array<std::int16_t, kCells> configs_{}; // of the block being sampled, -1 unknown
    std::vector<int> touched_; // the (cell, piece) entries touched, in increasing order
    // Per found_ crossing, its (up to) four cells: first their (cell, piece)
    // entries, then (buildVertices) where those entries' QEFs are in qefs_;
    // -1 where the cell is not in the block.
    std::vector<std::array<int, 4>> around_;
    std::vector<std::size_t> interiorCrossings_;       // those of found_ makeInteriorQuads serves
    std::vector<std::uint32_t> lowerFaceEdges_;        // the block's, gathered
    const std::vector<Block>* blocks_ = nullptr;       // sorted by keyOf(coord)
    const std::vector<std::uint64_t>* keys_ = nullptr; // theirs, in that order
    std::array<const Block*, 27> neighbours_{};
    std::array<BlockCoord, 27> neighbourCoords_{};
};

using BlockRange = std::array<std::array<int, 3>, 2>; // [lo, hi) in blocks

// What pruning found: the blocks to mesh, and where to look for warnings.
struct PruneFindings {
    std::vector<BlockCoord> active;
    std::vector<std::shared_ptr<const field::NarrowedTape>> tapes; // per active block (Block::tape)
    std::vector<Vec3> undefinedCentres; // boxes where f may be undefined (first few)
    std::vector<Vec3> touchCentres;     // boxes where f <= 0 reaches 0 at most (first few)
    bool overLimit = false;

    // A subtree's findings after these, in a fixed order.
    void append(PruneFindings&& later) {
        active.insert(active.end(), later.active.begin(), later.active.end());
        tapes.insert(tapes.end(), later.tapes.begin(), later.tapes.end());
        for (const Vec3& c : later.undefinedCentres)
            if (undefinedCentres.size() < 8) undefinedCentres.push_back(c);
        if (touchCentres.empty()) touchCentres = std::move(later.touchCentres);
        overLimit = overLimit || later.overLimit;
    }
};

// Octree over blocks: a node whose interval cannot hold a sign change is
// dropped with everything below it. With a split depth, the nodes reached at
// that depth (one axis is halved per level) are handed back as tasks instead:
// their subtrees then run on the threads, each with a Pruner of its own.
struct Pruner {
    Pruner(const Grid& g, FieldSampler& s, std::size_t blockLimit, std::atomic<std::size_t>& count,
           bool simplifyTapes, int depth = -1)
        : grid(g), sampler(s), limit(blockLimit), activeCount(count), simplify(simplifyTapes),
          splitDepth(depth) {}

    const Grid& grid;
    FieldSampler& sampler;
    std::size_t limit;
    std::atomic<std::size_t>& activeCount; // all the pruners' active blocks
    bool simplify;                         // narrow the formula down the tree
    bool rootNarrowed = false;             // the sampler already runs the root's tape (a task)
    int splitDepth = -1;
    std::vector<BlockRange> tasks;
    std::vector<std::shared_ptr<const field::NarrowedTape>>
        taskTapes; // the formula narrowed to each
    PruneFindings found;

    void run(std::array<int, 3> lo, std::array<int, 3> hi, int depth = 0) {
        if (found.overLimit || activeCount > limit) {
            found.overLimit = true;
            return;
        }
        Vec3 boxLo{}, boxHi{};
        for (std::size_t a = 0; a < 3; ++a) {
            boxLo[a] = grid.origin[a] + double(lo[a]) * kB * grid.h[a];
            boxHi[a] = grid.origin[a] + double(std::min(hi[a] * kB, grid.cells[a])) * grid.h[a];
        }
        // The formula simplified for this node from its parent's (libfive's
        // way down an octree; tape_simplify.h), over the node and a cell
        // around it: its blocks sample that far (sampleBlock), so a block
        // takes its leaf's tape as it is.
        std::optional<field::Narrowing> narrowed;
        if (simplify && !(depth == 0 && rootNarrowed)) {
            const auto box = grid.blocksAndACell(lo, hi);
            narrowed.emplace(sampler, box[0], box[1]);
        }
        const formula::Interval r = sampler.interval(boxLo, boxHi);
        const Vec3 centre{(boxLo[0] + boxHi[0]) / 2, (boxLo[1] + boxHi[1]) / 2,
                          (boxLo[2] + boxHi[2]) / 2};
        const bool possible = !r.empty() && r.lo <= 0 && r.hi > 0; // f may change sign here
        const bool touching = !possible && !r.empty() && r.hi == 0;
        if (!possible) {
            if (r.nan && found.undefinedCentres.size() < 8)
                found.undefinedCentres.push_back(centre);
            // f <= 0 here and reaches 0 at most: a surface without an inside?
            // Followed down to blocks (only while this pruner has found none)
            // to say where.
            if (!touching || !found.touchCentres.empty() || !found.active.empty()) return;
        }
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
        if (hi[axis] - lo[axis] == 1) {
            if (touching) {
                found.touchCentres.push_back(centre);
                return;
            }
            found.active.push_back(lo);
            found.tapes.push_back(sampler.tapeNow());
            if (++activeCount > limit) found.overLimit = true;
            return;
        }
        if (depth == splitDepth) {
            tasks.push_back({lo, hi});
            taskTapes.push_back(sampler.tapeNow());
            return;
        }
        const int mid = lo[axis] + (hi[axis] - lo[axis]) / 2;
        std::array<int, 3> hiA = hi, loB = lo;
        hiA[axis] = mid;
        loB[axis] = mid;
        run(lo, hiA, depth + 1);
        run(loB, hi, depth + 1);
    }
};

Grid makeGrid(const ImplicitField& field, double resolution) {
    Grid g;
    const double target = field.box.longestSide() / resolution;
    for (std::size_t a = 0; a < 3; ++a) {
        const double size = field.box.size(int(a));
        const int n = std::max(1, int(std::ceil(size / target - 1e-9)));
        g.h[a] = size / n;
        // Closed: half a cell of margin on each side, so the box faces cut
        // cells through their middle and never land on corners.
        const bool closed = field.boundary == BoxBoundary::Closed;
        // Open: the lattice reaches a few millionths of a cell past the box
        // on each side, by different amounts (and per axis), so that the
        // planes through a box's centre that students write (x = 0, z = x)
        // do not pass exactly through its corners: there f is 0 on whole
        // lines of corners and a crease's crossings sit on the crease
        // itself, where the gradient is either side's (the watermelon's cut
        // had its inner edge's vertices half a cell off it, max error 1.1e-3
        // of the diagonal at 128). Past the box on both sides, not moved:
        // a ball touching the box's faces still closes at its tips.
        static constexpr double kBefore[3] = {3.1e-6, 4.3e-6, 5.7e-6};
        static constexpr double kAfter[3] = {7.3e-6, 2.9e-6, 6.1e-6};
        if (!closed) {
            const double h0 = g.h[a];
            g.h[a] = (size + (kBefore[a] + kAfter[a]) * h0) / n;
            g.origin[a] = field.box.lo[a] - kBefore[a] * h0;
        } else {
            g.origin[a] = field.box.lo[a] - g.h[a] / 2;
        }
        g.cells[a] = n + (closed ? 1 : 0);
        g.blocks[a] = (g.cells[a] + kB - 1) / kB;
    }
    return g;
}

template <class Task>
void parallelFor(std::size_t count, int threads, const ImplicitField& field,
                 std::vector<EvaluationCounts>& counts, Task task) {
    std::atomic<std::size_t> next{0};
    const std::function<void(int)> worker = [&](int w) {
        FieldSampler sampler(field);
        for (std::size_t i = next++; i < count; i = next++)
            task(i, sampler, w);
        counts[std::size_t(w)] += sampler.counts();
    };
    parallel::WorkPool::shared().run(threads, worker);
}

std::string formatPoint(const Vec3& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p[0], p[1], p[2]);
    return buf;
}

} // namespace

MeshResult meshImplicit(const ImplicitField& field, const MeshOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    MeshResult result;
    if (!field.box.valid()) {
        result.error = "the domain box must be finite with max above min on every axis";
        return result;
    }
    if (!(options.resolution >= 1) || !std::isfinite(options.resolution)) {
        result.error = "the resolution must be at least 1 cell along the longest side";
        return result;
    }
    if (options.resolution > double(kB) * (1 << 20)) {
        result.error = "a resolution above " + std::to_string(kB << 20) + " cells is not supported";
        return result;
    }
    const Grid grid = makeGrid(field, options.resolution);
    result.stats.cells = grid.cells;
    result.stats.cellSize = grid.h;
    result.stats.blocks = std::size_t(grid.blocks[0]) * grid.blocks[1] * grid.blocks[2];

    // What one active block typically costs while meshing, its share of the
    // mesh included (a smooth surface through a block makes about kB^2
    // vertices): the first check, before any work. Sampling then counts what
    // the blocks really hold and stops at the budget.
    const std::size_t bytesPerBlock = kB * kB * kBytesPerVertex;
    const std::size_t blockLimit =
        std::max<std::size_t>(1, options.memoryBudgetBytes / bytesPerBlock);

    const int threads = options.threads > 0 ? options.threads
                                            : std::max(1, int(std::thread::hardware_concurrency()));
    // The octree's top six levels here, their subtrees (64 or fewer) on the
    // mesher's threads.
    FieldSampler pruneSampler(field);
    std::atomic<std::size_t> activeCount{0};
    Pruner top(grid, pruneSampler, blockLimit, activeCount, options.simplifyPerBlock, 6);
    top.run({0, 0, 0}, grid.blocks);
    PruneFindings pruned = std::move(top.found);
    EvaluationCounts counts = pruneSampler.counts();
    {
        std::vector<EvaluationCounts> taskCounts(static_cast<std::size_t>(threads));
        std::vector<PruneFindings> subtrees(top.tasks.size());
        parallelFor(subtrees.size(), threads, field, taskCounts,
                    [&](std::size_t i, FieldSampler& s, int) {
                        Pruner task(grid, s, blockLimit, activeCount, options.simplifyPerBlock);
                        std::optional<field::Narrowing> adopted;
                        if (options.simplifyPerBlock) adopted.emplace(s, top.taskTapes[i]);
                        task.rootNarrowed = options.simplifyPerBlock;
                        task.run(top.tasks[i][0], top.tasks[i][1]);
                        subtrees[i] = std::move(task.found);
                    });
        for (PruneFindings& f : subtrees)
            pruned.append(std::move(f));
        for (const EvaluationCounts& c : taskCounts)
            counts += c;
    }
    const std::string overBudget =
        "resolution " + std::to_string(int(options.resolution)) + " would need more than " +
        std::to_string(options.memoryBudgetBytes >> 20) +
        " MiB for this shape; lower the resolution (or the target accuracy) or raise "
        "the memory budget";
    if (pruned.overLimit) {
        result.error = overBudget;
        result.stats.evaluations = counts;
        return result;
    }
    BlockArena arena(threads); // before the blocks: it outlives their arrays
    std::vector<Block> blocks;
    blocks.reserve(pruned.active.size());
    for (std::size_t i = 0; i < pruned.active.size(); ++i) {
        Block& b = blocks.emplace_back(&arena);
        b.coord = pruned.active[i];
        b.tape = std::move(pruned.tapes[i]);
        b.narrowed = true;
    }
    std::sort(blocks.begin(), blocks.end(),
              [](const Block& a, const Block& b) { return keyOf(a.coord) < keyOf(b.coord); });
    std::vector<EvaluationCounts> perThread(static_cast<std::size_t>(threads));
    std::vector<Observations> seen(static_cast<std::size_t>(threads));
    std::atomic<bool> stopped{false};
    std::mutex progressMutex;
    std::atomic<std::size_t> done{0};
    const std::size_t totalWork = 2 * blocks.size();
    auto report = [&] {
        const std::size_t d = std::min<std::size_t>(++done, totalWork); // extra blocks too
        if (options.progress && (d % 64 == 0 || d == totalWork)) {
            std::lock_guard lock(progressMutex);
            options.progress(double(d) / double(std::max<std::size_t>(totalWork, 1)));
        }
    };
    auto cancelled = [&] { return options.cancel && options.cancel->load(); };

    std::vector<Contourer> contourers;
    contourers.reserve(std::size_t(threads));
    for (int w = 0; w < threads; ++w)
        contourers.emplace_back(field, options, grid);
    // The memory the blocks hold plus what their vertices will still cost
    // (triangles, the mesh's copy), counted as they are sampled.
    std::atomic<std::size_t> bytesHeld{0};
    std::atomic<bool> overBudgetNow{false};
    auto sample = [&](std::vector<Block>& list) {
        parallelFor(list.size(), threads, field, perThread,
                    [&](std::size_t i, FieldSampler& s, int w) {
                        if (stopped || cancelled()) {
                            stopped = true;
                            return;
                        }
                        const BlockArena::Slot slot(arena, w);
                        Block& b = list[i];
                        contourers[std::size_t(w)].sampleBlock(b, s, seen[std::size_t(w)]);
                        // (the interior quads, counted among the later bytes, exist already)
                        const std::size_t later = b.positions.size() * kLaterBytesPerVertex;
                        const std::size_t made = b.interior.size() * sizeof(Triangle);
                        const std::size_t bytes = b.bytes() + later - std::min(later, made);
                        if (bytesHeld += bytes; bytesHeld > options.memoryBudgetBytes) {
                            overBudgetNow = true;
                            stopped = true;
                        }
                        report();
                    });
    };
    sample(blocks);

    // Phase 2, repeated in the rare case a neighbouring cell's block was not
    // sampled (an interval that should have held a zero did not); the last
    // round only connects what the one before it sampled.
    constexpr int kRounds = 4;
    for (int round = 0; round < kRounds && !stopped; ++round) {
        std::sort(blocks.begin(), blocks.end(),
                  [](const Block& a, const Block& b) { return keyOf(a.coord) < keyOf(b.coord); });
        std::uint32_t offset = 0;
        for (Block& b : blocks) {
            b.offset = offset;
            offset += std::uint32_t(b.positions.size());
        }
        std::vector<std::uint64_t> keys(blocks.size());
        for (std::size_t i = 0; i < blocks.size(); ++i)
            keys[i] = keyOf(blocks[i].coord);
        for (Contourer& c : contourers)
            c.index(blocks, keys);
        std::vector<std::vector<BlockCoord>> missing(static_cast<std::size_t>(threads));
        parallelFor(blocks.size(), threads, field, perThread,
                    [&](std::size_t i, FieldSampler&, int w) {
                        if (stopped || cancelled()) {
                            stopped = true;
                            return;
                        }
                        const BlockArena::Slot slot(arena, w);
                        contourers[std::size_t(w)].connectBlock(blocks[i], missing[std::size_t(w)]);
                        if (round == 0) report();
                    });
        std::vector<BlockCoord> extra;
        for (auto& m : missing)
            extra.insert(extra.end(), m.begin(), m.end());
        std::sort(extra.begin(), extra.end(),
                  [](const BlockCoord& a, const BlockCoord& b) { return keyOf(a) < keyOf(b); });
        extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
        if (extra.empty() || round == kRounds - 1) break;
        std::vector<Block> added;
        added.reserve(extra.size());
        for (const BlockCoord& coord : extra)
            added.emplace_back(&arena).coord = coord;
        sample(added);
        for (Block& b : added)
            blocks.push_back(std::move(b));
    }
    for (const EvaluationCounts& c : perThread)
        counts += c;
    result.stats.evaluations = counts;
    result.stats.activeBlocks = blocks.size();
    if (overBudgetNow) {
        result.error = overBudget;
        return result;
    }
    if (stopped) {
        result.cancelled = true;
        return result;
    }

    // Each block's share is copied to its place in the mesh (its vertices
    // from its offset on, its triangles after the blocks before it), the
    // blocks on the threads; the budget counts both, as the blocks' arena
    // gives their memory back only when the mesh is done.
    Mesh& mesh = result.mesh;
    std::vector<std::size_t> firstTriangle(blocks.size() + 1, 0);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        result.stats.surfaceCells += b.positions.size();
        firstTriangle[i + 1] = firstTriangle[i] + b.interior.size() + b.triangles.size();
    }
    mesh.positions.resize(result.stats.surfaceCells);
    mesh.normals.resize(result.stats.surfaceCells);
    mesh.triangles.resize(firstTriangle.back());
    parallelFor(blocks.size(), threads, field, perThread, [&](std::size_t i, FieldSampler&, int) {
        const Block& b = blocks[i];
        std::copy(b.positions.begin(), b.positions.end(), mesh.positions.begin() + b.offset);
        std::copy(b.normals.begin(), b.normals.end(), mesh.normals.begin() + b.offset);
        auto out = mesh.triangles.begin() + std::ptrdiff_t(firstTriangle[i]);
        for (const Triangle& t : b.interior)
            *out++ = {t[0] + b.offset, t[1] + b.offset, t[2] + b.offset};
        std::copy(b.triangles.begin(), b.triangles.end(), out);
    });

    // Warnings: undefined regions, and a function that touches zero without
    // ever changing sign (no inside, so no surface).
    Observations all;
    for (const Observations& o : seen)
        all.merge(o);
    if (all.undefinedCandidate) pruned.undefinedCentres.push_back(*all.undefinedCandidate);
    if (!all.sawNaN) {
        FieldSampler probe(field);
        for (const Vec3& c : pruned.undefinedCentres)
            if (std::isnan(probe.value(c))) {
                all.sawNaN = true;
                all.nanPoint = c;
                break;
            }
    }
    if (all.sawNaN) {
        std::string where;
        formula::ParameterValues params(field.tape);
        for (const auto& [name, v] : field.parameters)
            params.set(name, v);
        if (auto d = formula::explainNonFinite(
                field.tape, params.values(),
                formula::pointXYZ(all.nanPoint[0], all.nanPoint[1], all.nanPoint[2], field.t)))
            where = " (" + d->message + " at " + std::to_string(d->range.begin.line) + ":" +
                    std::to_string(d->range.begin.column) + " of the formula)";
        result.warnings.push_back("the function is undefined (NaN) in part of the box, e.g. at " +
                                  formatPoint(all.nanPoint) + where +
                                  "; the surface is meshed only where it is defined");
    }
    if (mesh.empty() && (std::isfinite(all.maxValue) || !pruned.touchCentres.empty())) {
        FieldSampler probe(field);
        if (!std::isfinite(all.maxValue)) {
            all.maxPoint = pruned.touchCentres.front();
            all.maxAbs = std::abs(probe.value(all.maxPoint));
        }
        const double reached = climbTowardsZero(probe, all.maxPoint);
        if (reached > 0)
            result.warnings.push_back("the solid is thinner than a cell near " +
                                      formatPoint(all.maxPoint) +
                                      " and no grid corner falls inside it; raise the resolution");
        else if (reached > -1e-12 * std::max(all.maxAbs, 1e-300))
            result.warnings.push_back(
                "the function reaches zero near " + formatPoint(all.maxPoint) +
                " but never becomes positive (as f = -g^2 does): there is no inside, so there is "
                "no surface; write the function so that it is positive inside (for f = -g^2, use "
                "g, or 0.01 - abs(g) for a thin shell)");
    }
    result.stats.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace fl::mesh
