#include "pde_file.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace fl::pde {
namespace {

constexpr char kMagic[6] = {'F', 'L', 'P', 'D', 'E', '\0'};
constexpr std::string_view kTextHeader = "FLPDE text 1";

// Every coefficient of a patch in file order: the spine's four, then for
// each n the cosine's four and the sine's four.
template <typename P, typename F>
void forEachCoefficient(P& patch, F&& f) {
    for (auto& c : patch.spine)
        f(c);
    for (std::size_t k = 0; k < patch.radii(); ++k) {
        for (auto& c : patch.cosines[k])
            f(c);
        for (auto& c : patch.sines[k])
            f(c);
    }
}

// The coefficients a file stores: all, but for a cap not those its
// conditions fix (completeCap sets them on reading).
template <typename P, typename F>
void forEachStored(P& patch, F&& f) {
    for (auto& c : patch.spine)
        f(c);
    for (std::size_t k = 0; k < patch.radii(); ++k)
        for (auto* mode : {&patch.cosines[k], &patch.sines[k]})
            for (int i = 0; i < 4; ++i)
                if (!patch.cap || !capDerived(int(k) + 1, i)) f((*mode)[std::size_t(i)]);
}

// --- binary ---------------------------------------------------------------

struct Writer {
    std::string out;
    void raw(const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); }
    void f64(double v) {
        std::uint64_t b;
        std::memcpy(&b, &v, 8);
        for (int i = 0; i < 8; ++i)
            out.push_back(char((b >> (8 * i)) & 0xff));
    }
    void f32(float v) {
        std::uint32_t b;
        std::memcpy(&b, &v, 4);
        for (int i = 0; i < 4; ++i)
            out.push_back(char((b >> (8 * i)) & 0xff));
    }
    void varint(std::uint64_t v) {
        while (v >= 0x80) {
            out.push_back(char((v & 0x7f) | 0x80));
            v >>= 7;
        }
        out.push_back(char(v));
    }
    void zigzag(std::int64_t v) { varint((std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63)); }
};

struct Reader {
    std::string_view bytes;
    std::size_t at = 0;
    std::string error;

    bool fail(const std::string& what) {
        if (error.empty()) error = "payload byte " + std::to_string(at) + ": " + what;
        return false;
    }
    std::size_t left() const { return bytes.size() - at; }
    bool f64(double& v, const char* what) {
        if (left() < 8) return fail(std::string("the file ends inside ") + what);
        std::uint64_t b = 0;
        for (int i = 0; i < 8; ++i)
            b |= std::uint64_t(std::uint8_t(bytes[at + std::size_t(i)])) << (8 * i);
        std::memcpy(&v, &b, 8);
        at += 8;
        if (!std::isfinite(v)) return at -= 8, fail(std::string(what) + " is not a finite number");
        return true;
    }
    bool f32(float& v, const char* what) {
        if (left() < 4) return fail(std::string("the file ends inside ") + what);
        std::uint32_t b = 0;
        for (int i = 0; i < 4; ++i)
            b |= std::uint32_t(std::uint8_t(bytes[at + std::size_t(i)])) << (8 * i);
        std::memcpy(&v, &b, 4);
        at += 4;
        if (!std::isfinite(v)) return at -= 4, fail(std::string(what) + " is not a finite number");
        return true;
    }
    bool varint(std::uint64_t& v, const char* what) {
        v = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            if (left() == 0) return fail(std::string("the file ends inside ") + what);
            const auto b = std::uint8_t(bytes[at++]);
            v |= std::uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80)) return true;
        }
        return fail(std::string(what) + " is longer than 10 bytes");
    }
    bool zigzag(std::int64_t& v, const char* what) {
        std::uint64_t u;
        if (!varint(u, what)) return false;
        v = std::int64_t(u >> 1) ^ -std::int64_t(u & 1);
        return true;
    }
};

bool hasStartBorders(const Model& model) {
    return std::any_of(model.startBorders.begin(), model.startBorders.end(),
                       [](const auto& loop) { return !loop.empty(); });
}

std::string payloadOf(const Model& model, double step) {
    Writer w;
    for (double v : model.lo)
        w.f64(v);
    for (double v : model.hi)
        w.f64(v);
    w.f64(step);
    w.varint(model.patches.size());
    for (const Patch& p : model.patches) {
        w.varint(p.radii());
        w.f32(float(p.a));
        w.out.push_back(char(p.cap ? 1 : 0));
        forEachStored(p, [&](const Vec3& c) {
            for (double x : c)
                w.zigzag(std::int64_t(std::llround(std::clamp(x / step, -0x1p53, 0x1p53))));
        });
    }
    // The shared border points, each as the step count from the previous
    // one (neighbours along a loop: small numbers), then each patch's loop
    // as differences of indices (mostly +1).
    w.varint(model.borderPoints.size());
    std::array<std::int64_t, 3> last{};
    for (const Vec3& p : model.borderPoints)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto q = std::int64_t(
                std::llround(std::clamp((p[k] - model.lo[k]) / step, -0x1p53, 0x1p53)));
            w.zigzag(q - last[k]);
            last[k] = q;
        }
    auto loops = [&](const std::vector<std::vector<std::uint32_t>>& all) {
        for (std::size_t i = 0; i < model.patches.size(); ++i) {
            const auto& loop = i < all.size() ? all[i] : std::vector<std::uint32_t>{};
            w.varint(loop.size());
            std::int64_t previous = 0;
            for (std::uint32_t index : loop) {
                w.zigzag(std::int64_t(index) - previous);
                previous = index;
            }
        }
    };
    loops(model.borders);
    if (hasStartBorders(model)) loops(model.startBorders); // version 2
    return w.out;
}

bool readPayload(Reader& r, Model& m, int version) {
    for (double& v : m.lo)
        if (!r.f64(v, "the box")) return false;
    for (double& v : m.hi)
        if (!r.f64(v, "the box")) return false;
    for (int k = 0; k < 3; ++k)
        if (!(m.lo[std::size_t(k)] <= m.hi[std::size_t(k)]))
            return r.fail("the box's low corner is above its high corner");
    double step = 0;
    if (!r.f64(step, "the quantisation step")) return false;
    if (!(step > 0)) return r.fail("the quantisation step must be positive");
    std::uint64_t count = 0;
    if (!r.varint(count, "the patch count")) return false;
    // Each patch takes at least 4 + 12 bytes (radii, a, twelve coefficients).
    if (count > kMaxPatches || count > r.left() / 16)
        return r.fail(std::to_string(count) + " patches cannot fit in the " +
                      std::to_string(r.left()) + " bytes that follow (at most " +
                      std::to_string(kMaxPatches) + ")");
    m.patches.resize(std::size_t(count));
    for (Patch& p : m.patches) {
        std::uint64_t radii = 0;
        if (!r.varint(radii, "a patch's radii")) return false;
        if (radii > kMaxRadii)
            return r.fail("a patch has " + std::to_string(radii) + " radii (at most " +
                          std::to_string(kMaxRadii) + ")");
        float a = 0;
        if (!r.f32(a, "a patch's a")) return false;
        if (!(a > 0)) return r.fail("a patch's a must be positive");
        p.a = a;
        p.setRadii(std::size_t(radii));
        if (r.left() < 1) return r.fail("the file ends inside a patch's flags");
        const auto flags = std::uint8_t(r.bytes[r.at++]);
        if (flags > 1) return r.at -= 1, r.fail("unknown patch flags " + std::to_string(flags));
        p.cap = flags & 1;
        // Each stored coefficient takes at least three bytes (x, y, z).
        const std::size_t derived = p.cap && p.radii() ? 4 * p.radii() - 2 : 0;
        if (r.left() < 3 * (p.coefficientCount() - derived))
            return r.fail("the file ends inside a patch's coefficients");
        bool ok = true;
        forEachStored(p, [&](Vec3& c) {
            for (double& x : c) {
                std::int64_t q = 0;
                ok = ok && r.zigzag(q, "a coefficient");
                x = double(q) * step;
                ok = ok && (std::isfinite(x) || r.fail("a coefficient is not a finite number"));
            }
        });
        if (!ok) return false;
        completeCap(p);
    }
    std::uint64_t points = 0;
    if (!r.varint(points, "the border point count")) return false;
    if (points > r.left() / 3 || points > 0xffffffffu)
        return r.fail(std::to_string(points) + " border points cannot fit in the " +
                      std::to_string(r.left()) + " bytes that follow");
    m.borderPoints.resize(std::size_t(points));
    std::array<std::int64_t, 3> last{};
    for (Vec3& p : m.borderPoints)
        for (std::size_t k = 0; k < 3; ++k) {
            std::int64_t d = 0;
            if (!r.zigzag(d, "a border point")) return false;
            if ((d > 0 && last[k] > (std::int64_t(1) << 60) - d) ||
                (d < 0 && last[k] < -(std::int64_t(1) << 60) - d))
                return r.fail("a border point is too far out");
            last[k] += d;
            p[k] = m.lo[k] + double(last[k]) * step;
        }
    auto readLoops = [&](std::vector<std::vector<std::uint32_t>>& all) {
        all.resize(m.patches.size());
        for (auto& loop : all) {
            std::uint64_t length = 0;
            if (!r.varint(length, "a border's length")) return false;
            if (length > r.left()) return r.fail("a border longer than the bytes that follow");
            if (length > 0 && length < 3) return r.fail("a border of fewer than three points");
            loop.resize(std::size_t(length));
            std::int64_t previous = 0;
            for (std::uint32_t& index : loop) {
                std::int64_t d = 0;
                if (!r.zigzag(d, "a border index")) return false;
                if (d > std::int64_t(points) || d < -std::int64_t(points) || previous + d < 0 ||
                    previous + d >= std::int64_t(points))
                    return r.fail("a border names a point that is not there");
                previous += d;
                index = std::uint32_t(previous);
            }
        }
        return true;
    };
    if (!readLoops(m.borders)) return false;
    if (version >= 2) {
        if (!readLoops(m.startBorders)) return false;
        for (std::size_t i = 0; i < m.patches.size(); ++i)
            if (m.patches[i].cap && !m.startBorders[i].empty())
                return r.fail("a cap (one point at u = 0) with a start border");
    }
    if (r.left() != 0) return r.fail(std::to_string(r.left()) + " bytes follow the last border");
    return true;
}

ReadResult readBinary(std::string_view bytes, std::string_view name) {
    ReadResult out;
    auto fail = [&](const std::string& what) {
        out.error = std::string(name) + ": " + what;
        return out;
    };
    if (bytes.size() < 12) return fail("byte 0: too short for a .pde header");
    const int version = std::uint8_t(bytes[6]);
    if (version < 1 || version > kFormatVersion)
        return fail("byte 6: version " + std::to_string(version) + " (this program reads 1 to " +
                    std::to_string(kFormatVersion) + ")");
    std::uint32_t size = 0;
    for (int i = 0; i < 4; ++i)
        size |= std::uint32_t(std::uint8_t(bytes[8 + std::size_t(i)])) << (8 * i);
    if (size > kMaxPayloadBytes)
        return fail("byte 8: a payload of " + std::to_string(size) + " bytes (at most " +
                    std::to_string(kMaxPayloadBytes) + ")");
    std::string payload(size, '\0');
    uLongf written = size;
    const int z =
        uncompress(reinterpret_cast<Bytef*>(payload.data()), &written,
                   reinterpret_cast<const Bytef*>(bytes.data() + 12), uLong(bytes.size() - 12));
    if (z != Z_OK || written != size)
        return fail("byte 12: the compressed payload is damaged (" +
                    std::string(z == Z_BUF_ERROR ? "longer than its stated size"
                                : z == Z_OK      ? "shorter than its stated size"
                                                 : "not zlib data") +
                    ")");
    Reader r;
    r.bytes = payload;
    Model m;
    if (!readPayload(r, m, version)) return fail(r.error);
    out.model = std::move(m);
    return out;
}

// --- text -----------------------------------------------------------------

std::string number(double v) {
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v); // shortest exact
    return std::string(buf, res.ptr);
}

struct Token {
    std::string_view text;
    std::size_t column; // 1-based
};

std::vector<Token> tokens(std::string_view line) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
            ++i;
            continue;
        }
        if (line[i] == '#') break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' &&
               line[i] != '#')
            ++i;
        out.push_back({line.substr(start, i - start), start + 1});
    }
    return out;
}

std::string printable(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40))
        out += (std::uint8_t(c) < 0x20 || c == 0x7f) ? '?' : c;
    return out + (s.size() > 40 ? "..." : "");
}

ReadResult readText(std::string_view bytes, std::string_view name) {
    ReadResult out;
    Model m;
    std::size_t lineNo = 0, pos = 0;
    std::vector<Token> t;
    Token end{{}, 1};
    auto fail = [&](const Token& at, const std::string& what) {
        out.error = std::string(name) + ":" + std::to_string(lineNo) + ":" +
                    std::to_string(at.column) + ": " + what;
        return false;
    };
    // The next line with tokens; false at the end of the file.
    auto nextLine = [&]() {
        while (pos < bytes.size()) {
            const std::size_t eol = std::min(bytes.find('\n', pos), bytes.size());
            const std::string_view line = bytes.substr(pos, eol - pos);
            pos = eol + 1;
            ++lineNo;
            t = tokens(line);
            end.column = line.size() + 1;
            if (!t.empty()) return true;
        }
        return false;
    };
    auto numberAt = [&](std::size_t i, double& v, const char* what) {
        if (i >= t.size()) return fail(end, std::string("expected ") + what);
        const auto s = t[i].text;
        const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
        if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v))
            return fail(t[i], std::string("expected ") + what + ", not '" + printable(s) + "'");
        return true;
    };
    auto wholeAt = [&](std::size_t i, std::size_t& v, std::size_t max, const char* what) {
        double d = 0;
        if (!numberAt(i, d, what)) return false;
        if (d < 0 || d != std::floor(d) || d > double(max))
            return fail(t[i], std::string(what) + " must be a whole number from 0 to " +
                                  std::to_string(max));
        v = std::size_t(d);
        return true;
    };
    auto keyword = [&](std::string_view k, const std::string& expected) {
        if (t[0].text != k)
            return fail(t[0], "expected " + expected + ", not '" + printable(t[0].text) + "'");
        return true;
    };
    auto modeLine = [&](Mode& mode, std::string_view k, std::size_t n) {
        if (!nextLine()) return fail(end, "the file ends before the " + std::string(k) + " line");
        const std::string expected =
            std::string(k) + (n ? " " + std::to_string(n) : "") + " and twelve numbers";
        if (!keyword(k, "'" + expected + "'")) return false;
        std::size_t i = 1;
        if (n) {
            std::size_t got = 0;
            if (!wholeAt(1, got, kMaxRadii, "the mode number")) return false;
            if (got != n) return fail(t[1], "expected mode " + std::to_string(n));
            i = 2;
        }
        for (Vec3& c : mode)
            for (double& x : c)
                if (!numberAt(i++, x, "a coefficient")) return false;
        if (i < t.size()) return fail(t[i], "more than twelve numbers on a mode line");
        return true;
    };
    if (!nextLine() || t[0].text != "FLPDE")
        return out.error = std::string(name) + ":1:1: not a PDE model (a .pde file starts with "
                                               "the bytes FLPDE)",
               out;
    if (t.size() != 3 || t[1].text != "text" || t[2].text != "1")
        return fail(t.size() > 1 ? t[1] : end, "expected 'FLPDE text 1'"), out;
    if (!nextLine()) return fail(end, "expected 'box' and six numbers"), out;
    if (!keyword("box", "'box' and six numbers")) return out;
    for (std::size_t k = 0; k < 6; ++k)
        if (!numberAt(1 + k, k < 3 ? m.lo[k] : m.hi[k - 3], "a box coordinate")) return out;
    for (int k = 0; k < 3; ++k)
        if (!(m.lo[std::size_t(k)] <= m.hi[std::size_t(k)]))
            return fail(t[1 + std::size_t(k)], "the box's low corner is above its high corner"),
                   out;
    // Shared border points, then the patches, each perhaps with its border.
    bool more = nextLine();
    while (more && t[0].text == "point") {
        if (m.borderPoints.size() >= 0xffffffffu) return fail(t[0], "too many points"), out;
        Vec3& p = m.borderPoints.emplace_back();
        for (std::size_t k = 0; k < 3; ++k)
            if (!numberAt(1 + k, p[k], "a point coordinate")) return out;
        if (t.size() > 4) return fail(t[4], "a point has three coordinates"), out;
        more = nextLine();
    }
    while (more) {
        if (!keyword("patch", "'patch radii N a A'")) return out;
        if (m.patches.size() >= kMaxPatches)
            return fail(t[0], "more than " + std::to_string(kMaxPatches) + " patches"), out;
        const bool cap = t.size() == 6 && t[5].text == "cap";
        if ((t.size() != 5 && !cap) || t[1].text != "radii" || t[3].text != "a")
            return fail(t.size() > 1 ? t[1] : end, "expected 'patch radii N a A' (and 'cap')"), out;
        std::size_t radii = 0;
        double a = 0;
        if (!wholeAt(2, radii, kMaxRadii, "radii") || !numberAt(4, a, "a")) return out;
        // (Binary files keep a as a float32: the same model must write in both forms.)
        if (!(a >= 1e-30 && a <= 1e30)) return fail(t[4], "a must be from 1e-30 to 1e30"), out;
        Patch& p = m.patches.emplace_back();
        p.a = a;
        p.cap = cap;
        p.setRadii(radii);
        if (!modeLine(p.spine, "spine", 0)) return out;
        for (std::size_t k = 0; k < radii; ++k)
            if (!modeLine(p.cosines[k], "cos", k + 1) || !modeLine(p.sines[k], "sin", k + 1))
                return out;
        completeCap(p); // a cap's fixed coefficients follow from the free ones
        m.borders.emplace_back();
        m.startBorders.emplace_back();
        more = nextLine();
        // Its border (u = 1), then for a tube its start border (u = 0).
        for (const char* keyword : {"border", "start"}) {
            if (!more || t[0].text != keyword) continue;
            if (t.size() < 4) return fail(t[0], "a border has at least three points"), out;
            if (m.borderPoints.empty())
                return fail(t[0], "a border, but no 'point' lines before the patches"), out;
            if (cap && t[0].text == "start")
                return fail(t[0], "a cap (one point at u = 0) has no start border"), out;
            auto& loop = t[0].text == "border" ? m.borders.back() : m.startBorders.back();
            for (std::size_t i = 1; i < t.size(); ++i) {
                std::size_t index = 0;
                if (!wholeAt(i, index, m.borderPoints.size() - 1, "a point number")) return out;
                loop.push_back(std::uint32_t(index));
            }
            more = nextLine();
        }
    }
    if (!hasStartBorders(m)) m.startBorders.clear();
    out.model = std::move(m);
    return out;
}

} // namespace

double quantisationStep(const Model& model, const EncodeOptions& options) {
    const int bits = std::clamp(options.bits, 4, 40);
    const double d = model.diagonal();
    return (d > 0 && std::isfinite(d) ? d : 1.0) / std::ldexp(1.0, bits);
}

std::string encodeBinary(const Model& model, const EncodeOptions& options) {
    const std::string payload = payloadOf(model, quantisationStep(model, options));
    uLongf size = compressBound(uLong(payload.size()));
    std::string z(size, '\0');
    compress2(reinterpret_cast<Bytef*>(z.data()), &size,
              reinterpret_cast<const Bytef*>(payload.data()), uLong(payload.size()), 9);
    z.resize(size);
    std::string out(kMagic, sizeof kMagic);
    out.push_back(char(hasStartBorders(model) ? 2 : 1));
    out.push_back('\0');
    const auto n = std::uint32_t(payload.size());
    for (int i = 0; i < 4; ++i)
        out.push_back(char((n >> (8 * i)) & 0xff));
    return out + z;
}

std::string encodeText(const Model& model) {
    std::ostringstream o;
    o << kTextHeader << "\n";
    o << "# A PDE model: Bloor-Wilson patches X(u,v) = A0(u) + sum of An(u) cos(nv) + Bn(u) "
         "sin(nv).\n"
         "# spine: A0 = a0 + a1 u + a2 u^2 + a3 u^3 (four x y z); cos n / sin n: An, Bn =\n"
         "# c1 g + c2 u g + c3 h + c4 u h with g = exp(-a n (1-u)), h = exp(-a n u).\n"
         "# A 'cap' patch is one point at u = 0 with one tangent plane: there c3, and\n"
         "# for n >= 2 c4, follow from c1 and c2 (they are written, and recomputed on reading).\n";
    o << "box";
    for (double v : model.lo)
        o << " " << number(v);
    for (double v : model.hi)
        o << " " << number(v);
    o << "\n";
    auto mode = [&](const char* k, std::size_t n, const Mode& m) {
        o << k;
        if (n) o << " " << n;
        for (const Vec3& c : m)
            for (double x : c)
                o << " " << number(x);
        o << "\n";
    };
    if (!model.borderPoints.empty())
        o << "# The boundary curves' points (numbered from 0); a patch's 'border' line\n"
             "# lists its loop, which the patch meets at u = 1 ('start': at u = 0).\n";
    for (const Vec3& p : model.borderPoints)
        o << "point " << number(p[0]) << " " << number(p[1]) << " " << number(p[2]) << "\n";
    for (std::size_t i = 0; i < model.patches.size(); ++i) {
        const Patch& p = model.patches[i];
        o << "patch radii " << p.radii() << " a " << number(p.a) << (p.cap ? " cap" : "") << "\n";
        mode("spine", 0, p.spine);
        for (std::size_t k = 0; k < p.radii(); ++k) {
            mode("cos", k + 1, p.cosines[k]);
            mode("sin", k + 1, p.sines[k]);
        }
        auto loop = [&](const char* keyword, const std::vector<std::vector<std::uint32_t>>& all) {
            if (i >= all.size() || all[i].empty()) return;
            o << keyword;
            for (std::uint32_t index : all[i])
                o << " " << index;
            o << "\n";
        };
        loop("border", model.borders);
        loop("start", model.startBorders);
    }
    return o.str();
}

ReadResult readModel(std::string_view bytes, std::string_view name) {
    if (bytes.size() > kMaxFileBytes) {
        ReadResult r;
        r.error = std::string(name) + ": " + std::to_string(bytes.size()) +
                  " bytes; a .pde file has at most " + std::to_string(kMaxFileBytes);
        return r;
    }
    if (bytes.size() >= sizeof kMagic &&
        bytes.substr(0, sizeof kMagic) == std::string_view(kMagic, sizeof kMagic))
        return readBinary(bytes, name);
    return readText(bytes, name);
}

ReadResult readModelFile(const std::string& path) {
    ReadResult r;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.error = path + ": cannot be opened";
        return r;
    }
    std::string bytes;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        bytes.append(buf, std::size_t(in.gcount()));
        if (bytes.size() > kMaxFileBytes) {
            r.error = path + ": larger than " + std::to_string(kMaxFileBytes >> 20) +
                      " MiB, the most a .pde file may hold";
            return r;
        }
    }
    return readModel(bytes, path);
}

} // namespace fl::pde
