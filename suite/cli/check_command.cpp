// `functionlab check FILE [--json] [--plan]`: load a scene and report what is
// wrong with it, located as FILE:LINE:COL.
#include "cli/commands.h"
#include "cli/json.h"
#include "platform/exit_codes.h"
#include "scene/scene_diagnostic_json.h"

#include "animation/animator.h"
#include "scene/effects_plan.h"
#include "scene/scene_reader.h"
#include "scene/scene_work.h"

#include <cstdio>
#include <iostream>

namespace fl::cli {
namespace {

std::string vectorJson(const std::array<double, 3>& v) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict, bug 105329)
    // about literal + std::string chains.
    std::string out = "[";
    for (std::size_t i = 0; i < 3; ++i) {
        if (i) out += ",";
        out += jsonNumber(v[i]);
    }
    return out + "]";
}

std::string timeVaryingJson(unsigned bits) {
    std::string out = "[";
    for (std::string_view name : scene::timeVaryingNames(bits)) {
        if (out.size() > 1) out += ",";
        out += jsonString(name);
    }
    return out + "]";
}

std::string planJson(const scene::EffectsPlan& plan) {
    auto boolean = [](bool b) { return std::string(b ? "true" : "false"); };
    std::string out = "{\"functionShapes\":" + std::to_string(plan.functionShapes) +
                      ",\"timeVarying\":" + timeVaryingJson(plan.timeVarying) +
                      ",\"needsHaptics\":" + boolean(plan.needsHaptics) +
                      ",\"usesWallClock\":" + boolean(plan.usesWallClock) + ",\"entries\":[";
    for (std::size_t i = 0; i < plan.entries.size(); ++i) {
        const scene::PlanEntry& e = plan.entries[i];
        out += std::string(i ? "," : "") + "{\"name\":" + jsonString(e.name) +
               ",\"location\":" + jsonString(e.location) +
               ",\"geometry\":" + jsonString(e.geometry) +
               ",\"timeVarying\":" + timeVaryingJson(e.timeVarying) +
               ",\"usesWallClock\":" + boolean(e.usesWallClock) +
               ",\"appliesToSiblings\":" + boolean(e.appliesToSiblings) + ",\"tangible\":[";
        for (std::size_t j = 0; j < e.tangible.size(); ++j) {
            const scene::TangibleEffect& t = e.tangible[j];
            out += std::string(j ? "," : "") +
                   "{\"kind\":" + jsonString(std::string(scene::tangibleKindName(t.kind))) +
                   ",\"domainMin\":" + vectorJson(t.domainMin) +
                   ",\"domainMax\":" + vectorJson(t.domainMax) +
                   ",\"timeVarying\":" + boolean(t.timeVarying) + "}";
        }
        out += "]}";
    }
    return out + "]}";
}

std::string workJson(const scene::Scene& s, const scene::SceneWork& w) {
    std::string out = "{\"tapeInstructions\":" + std::to_string(w.tapeInstructions);
    out += ",\"meshCells\":" + jsonNumber(w.meshCells);
    out += ",\"meshEvaluations\":" + jsonNumber(w.meshEvaluations);
    out += ",\"costliest\":";
    out += w.costliest ? jsonString(s.locationOf(*w.costliest)) : std::string("null");
    return out + "}";
}

std::string workText(const scene::Scene& s, const scene::SceneWork& w) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "work: %zu formula instructions; meshing at the files' resolutions: %.3g cells, "
                  "%.3g instructions evaluated on a dense grid",
                  w.tapeInstructions, w.meshCells, w.meshEvaluations);
    std::string out = line;
    if (w.costliest)
        out += " (most: " + w.costliest->type + " at " + s.locationOf(*w.costliest) + ")";
    return out + "\n";
}

} // namespace

const CommandSpec& checkSpec() {
    static const CommandSpec spec{
        .name = "check",
        .summary = "load a scene; diagnostics as FILE:LINE:COL; --plan: what varies, what is "
                   "tangible",
        .synopsis = {"check FILE [--plan] [--json]"},
        .description =
            "Loads a scene (.x3d, .x3dv, .wrl and their gzip forms), expands its PROTOs,\n"
            "compiles every function definition, and prints each problem as\n"
            "  FILE:LINE:COL: error|warning: message (suggestion)\n",
        .positionals = {{.name = "FILE", .help = "the scene"}},
        .options = {{.name = "plan",
                     .help = "also print the effects plan: per node, what depends on time and "
                             "which tangible effects exist; and the work: formula instructions, "
                             "and cells and evaluations meshing at the files' resolutions takes"},
                    {.name = "json",
                     .help = "print one JSON object instead: {\"file\", \"loaded\", "
                             "\"diagnostics\": [...], \"plan\": {...}, \"work\": {...} (with "
                             "--plan)}"}},
        .exitStatus = "0 the scene loaded (warnings allowed), 1 it did not, 2 usage error",
    };
    return spec;
}

int checkCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(checkSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const bool json = a->flag("json"), plan = a->flag("plan");
    const std::string file = a->positional("FILE");
    scene::ReadResult r = scene::readSceneFile(file);
    if (r.ok()) {
        // Wiring the animation finds what only running it would show
        // (interpolator keys it cannot use, UTC times sent into scene time).
        const animation::Animator animator(*r.scene);
        r.diagnostics.insert(r.diagnostics.end(), animator.diagnostics().begin(),
                             animator.diagnostics().end());
    }
    if (json) {
        // Appended piece by piece: GCC 12 warns falsely (-Wrestrict, bug
        // 105329) about literal + std::string chains here.
        std::string out = "{\"file\":";
        out += jsonString(file);
        out += ",\"loaded\":";
        out += r.ok() ? "true" : "false";
        out += ",\"diagnostics\":[";
        for (std::size_t i = 0; i < r.diagnostics.size(); ++i) {
            if (i) out += ",";
            out += scene::sceneDiagnosticJson(r.diagnostics[i]);
        }
        out += "]";
        if (plan && r.ok()) {
            out += ",\"plan\":" + planJson(scene::makeEffectsPlan(*r.scene));
            out += ",\"work\":" + workJson(*r.scene, scene::estimateSceneWork(*r.scene));
        }
        std::cout << out << "}\n";
    } else {
        for (const auto& d : r.diagnostics)
            std::cerr << scene::formatSceneDiagnostic(d) << "\n";
        if (plan && r.ok())
            std::cout << scene::planText(scene::makeEffectsPlan(*r.scene))
                      << workText(*r.scene, scene::estimateSceneWork(*r.scene));
    }
    return r.ok() ? kExitOk : kExitDiagnostic;
}

} // namespace fl::cli
