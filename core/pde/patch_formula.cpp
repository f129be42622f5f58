#include "patch_formula.h"

#include <algorithm>
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

std::string patchScene(const Model& model, std::size_t k, bool classic) {
    auto vec = [](const Vec3& v) { return number(v[0]) + " " + number(v[1]) + " " + number(v[2]); };
    std::string definition;
    for (const std::string& line : patchScript(model.patches.at(k)))
        definition += (definition.empty() ? ""
                       : classic          ? "\n      "
                                          : "\n                 ") +
                      ("\"" + line + "\"");
    const std::string name = "PATCH_" + std::to_string(k);
    // An FGeometry's box must have depth on every axis: a flat mesh's model
    // box gets a hundredth of its diagonal where it has none.
    Model box = model;
    const double pad = model.diagonal() > 0 ? model.diagonal() / 100 : 1e-3;
    for (std::size_t c = 0; c < 3; ++c)
        if (!(box.hi[c] - box.lo[c] >= pad)) {
            const double middle = (box.lo[c] + box.hi[c]) / 2;
            box.lo[c] = std::min(box.lo[c], middle - pad / 2);
            box.hi[c] = std::max(box.hi[c], middle + pad / 2);
        }
    if (classic)
        return "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
               "DEF " +
               name +
               " FShape {\n  geometry FGeometry {\n    type \"parametric\"\n"
               "    uRange 0 1\n    vRange 0 6.283185307\n    domainMin " +
               vec(box.lo) + "\n    domainMax " + vec(box.hi) + "\n    definition [\n      " +
               definition + "\n    ]\n  }\n}\n";
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<X3D profile='Immersive' version='3.3'>\n  <head>\n    <component "
           "name='FunctionLab' level='1'/>\n  </head>\n  <Scene>\n    <FShape DEF='" +
           name +
           "'>\n      <FGeometry type='parametric' uRange='0 1' vRange='0 6.283185307'\n"
           "                 domainMin='" +
           vec(box.lo) + "' domainMax='" + vec(box.hi) + "'\n                 definition='" +
           definition +
           "'/>\n    </FShape>\n"
           "  </Scene>\n</X3D>\n";
}

} // namespace fl::pde
