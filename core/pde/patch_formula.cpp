#include "patch_formula.h"

#include <cstdio>

namespace fl::pde {
namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s(buf);
    return s == "-0" ? "0" : s;
}

// Σ m[i][c] * basis[i], the zero terms left out, signs written once.
std::string sum(const Mode& m, std::size_t c, const char* const (&basis)[4]) {
    std::string out;
    for (std::size_t i = 0; i < 4; ++i) {
        if (m[i][c] == 0) continue;
        const std::string n = number(m[i][c]);
        out += out.empty() ? n : (n[0] == '-' ? " - " + n.substr(1) : " + " + n);
        if (*basis[i]) out += std::string("*") + basis[i];
    }
    return out.empty() ? "0" : out;
}

constexpr const char* kRadius[4] = {"g", "u*g", "h", "u*h"};
constexpr const char* kSpine[4] = {"", "u", "u^2", "u^3"};

} // namespace

std::vector<std::string> patchScript(const Patch& p) {
    std::vector<std::string> lines;
    lines.push_back(
        "// A Bloor-Wilson PDE patch: X(u,v) = A0(u) + sum of An(u) cos(nv) + Bn(u) sin(nv),");
    lines.push_back("// u in [0, 1], v in [0, 2 pi]; An, Bn = c1 g + c2 u g + c3 h + c4 u h with");
    lines.push_back("// g = exp(-a n (1-u)), h = exp(-a n u) (docs/pde.md).");
    lines.push_back("a = " + number(p.a) + ";");
    lines.push_back("// the spine A0(u): a cubic in u");
    const char* axis[3] = {"x", "y", "z"};
    for (std::size_t c = 0; c < 3; ++c)
        lines.push_back(std::string(axis[c]) + " = " + sum(p.spine, c, kSpine) + ";");
    for (std::size_t k = 0; k < p.radii(); ++k) {
        const std::string n = std::to_string(k + 1);
        lines.push_back("// radius " + n + ": A" + n + "(u) cos(" + n + "v) + B" + n + "(u) sin(" +
                        n + "v)");
        lines.push_back("g = exp(-a*" + n + "*(1 - u)); h = exp(-a*" + n + "*u);");
        lines.push_back("c = cos(" + n + "*v); s = sin(" + n + "*v);");
        for (std::size_t c = 0; c < 3; ++c)
            lines.push_back(std::string(axis[c]) + " += (" + sum(p.cosines[k], c, kRadius) +
                            ")*c + (" + sum(p.sines[k], c, kRadius) + ")*s;");
    }
    return lines;
}

} // namespace fl::pde
