#include "pde_scene.h"

#include "patch_formula.h"
#include "pde_data_url.h"
#include "scene/scene_writer.h"

#include <algorithm>
#include <cstdio>

namespace fl::pde {
namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    const std::string s(buf);
    return s == "-0" ? "0" : s;
}

std::string vec(const Vec3& v) {
    return number(v[0]) + " " + number(v[1]) + " " + number(v[2]);
}

// One FShape (its text in the encoding's syntax) in a whole scene.
std::string scene(const std::string& shape, bool classic) {
    if (classic) return "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n" + shape;
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<X3D profile='Immersive' version='3.3'>\n  <head>\n    <component "
           "name='FunctionLab' level='1'/>\n  </head>\n  <Scene>\n" +
           shape + "  </Scene>\n</X3D>\n";
}

} // namespace

std::string patchScene(const Model& model, std::size_t k, bool classic) {
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
        return scene("DEF " + name +
                         " FShape {\n  geometry FGeometry {\n    type \"parametric\"\n"
                         "    uRange 0 1\n    vRange 0 6.283185307\n    domainMin " +
                         vec(box.lo) + "\n    domainMax " + vec(box.hi) +
                         "\n    definition [\n      " + definition + "\n    ]\n  }\n}\n",
                     true);
    return scene("    <FShape DEF='" + name +
                     "'>\n      <FGeometry type='parametric' uRange='0 1' vRange='0 6.283185307'\n"
                     "                 domainMin='" +
                     vec(box.lo) + "' domainMax='" + vec(box.hi) +
                     "'\n                 definition='" + definition + "'/>\n    </FShape>\n",
                 false);
}

std::string modelScene(const std::string& url, bool classic) {
    // The url is someone's file name: quoted as an MFString holds it, and
    // escaped again as an XML attribute holds that.
    const std::string quoted = scene::quotedString(url);
    if (classic)
        return scene("DEF MODEL FShape {\n  geometry FPdeSurface {\n    url " + quoted +
                         "\n    resolution 32\n  }\n}\n",
                     true);
    return scene("    <FShape DEF='MODEL'>\n      <FPdeSurface resolution='32' url='" +
                     scene::xmlAttributeText(quoted, '\'') + "'/>\n    </FShape>\n",
                 false);
}

std::string carryingScene(const Model& model, const EncodeOptions& options, bool classic) {
    return modelScene(dataUrlOf(model, options), classic); // base64: nothing to escape
}

} // namespace fl::pde
