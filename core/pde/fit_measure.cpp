#include "fit_measure.h"

namespace fl::pde {

std::optional<FitMeasure> measureFit(const mesh::Mesh& original, const Model& model,
                                     const MeasureOptions& o, std::string* why) {
    FitMeasure m;
    m.bytes = o.text ? encodeText(model) : encodeBinary(model, o.encode);
    ReadResult back = readModel(m.bytes, "fitted.pde");
    if (!back.ok()) {
        if (why) *why = back.error;
        return std::nullopt;
    }
    m.model = std::move(*back.model);
    m.rebuilt = meshModel(m.model, o.grid);
    m.distance = o.originalTree
                     ? mesh::compareSurfaces(original, *o.originalTree, m.rebuilt, o.samples)
                     : mesh::compareSurfaces(original, m.rebuilt, o.samples);
    m.diagonal = m.model.diagonal() > 0 ? m.model.diagonal() : 1.0;
    return m;
}

} // namespace fl::pde
