#include "bench_pde_spec.h"

namespace fl::measure {

const cli::CommandSpec& benchPdeSpec() {
    using cli::OptionKind;
    static const cli::CommandSpec spec{
        .name = "bench pde",
        .summary = "PDE models against Draco and simplification + Draco: bytes and error",
        .synopsis = {"bench pde MESH.obj [--patches P,P,...] [--radii N] [--draco Q,Q,...]\n"
                     "[--simplify E,E,...] [--samples N] [--plot SVG] [--json]"},
        .description =
            "Measures what a PDE model of MESH costs and how close it is, side by side in one\n"
            "run with what a user would pick instead: the mesh compressed by Draco at the\n"
            "given position quantisations, and simplified by meshoptimizer to the given\n"
            "errors (fractions of the diagonal) then compressed by Draco at 11 bits. Every\n"
            "row's error is measured by the same code against the mesh: RMS and symmetric\n"
            "Hausdorff distance, exact point-to-triangle, N area-weighted samples each way,\n"
            "fractions of the bounding-box diagonal. The PDE rows are pde fit with\n"
            "--patches P (and one with its default --error); for a file named bunny.obj the\n"
            "paper's figures for the Stanford bunny (539 KB OBJ: 86 KB at 180 patches,\n"
            "120 KB at 250; no error given) are printed too. Peers: Debian's libdraco-dev and\n"
            "libmeshoptimizer-dev, linked only by functionlab-bench.\n",
        .positionals = {{.name = "MESH", .help = "the polygon mesh (Wavefront OBJ)"}},
        .options = {{.name = "patches",
                     .kind = OptionKind::NumberList,
                     .valueName = "P,P,...",
                     .help = "PDE patch counts to fit",
                     .defaultValue = "10,20,40,80",
                     .min = 1,
                     .max = 10000},
                    {.name = "radii",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "the most radii a patch may have in those fits",
                     .defaultValue = "8",
                     .min = 1,
                     .max = 32},
                    {.name = "draco",
                     .kind = OptionKind::NumberList,
                     .valueName = "Q,Q,...",
                     .help = "Draco position quantisation bits",
                     .defaultValue = "7,8,10,11,14",
                     .min = 1,
                     .max = 30},
                    {.name = "simplify",
                     .kind = OptionKind::NumberList,
                     .valueName = "E,E,...",
                     .help = "meshoptimizer target errors (fractions of the diagonal) before "
                             "Draco",
                     .defaultValue = "0.001,0.002,0.005,0.01",
                     .min = 0,
                     .max = 1},
                    {.name = "samples",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "area-weighted samples each way for every error",
                     .defaultValue = "100000",
                     .min = 1000,
                     .max = 10000000},
                    {.name = "plot",
                     .kind = OptionKind::Path,
                     .valueName = "SVG",
                     .help = "also draw bytes against RMS error, one line per method, as SVG"},
                    {.name = "json", .help = "one JSON object per row instead of a table"}},
        .exitStatus = "0 measured, 1 the mesh could not be read or fitted, 2 usage error",
    };
    return spec;
}

} // namespace fl::measure
