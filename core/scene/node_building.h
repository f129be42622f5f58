#pragma once
// Building nodes in code, as a reader would have made them: a catalogue node
// owned by a scene, and a field with its type and value. The preview of
// `convert` and the pages of `export-web` build their standard X3D this way.
#include "scene.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fl::scene {

inline Node* newCatalogueNode(Scene& scene, std::string_view type) {
    Node* n = scene.newNode();
    n->type = std::string(type);
    n->spec = findNodeSpec(type);
    return n;
}

inline void addNumbersField(Node& n, std::string name, FieldType type,
                            std::vector<double> numbers) {
    Field f;
    f.name = std::move(name);
    f.value.type = type;
    f.value.numbers = std::move(numbers);
    n.fields.push_back(std::move(f));
}

inline void addNodesField(Node& n, std::string name, FieldType type, std::vector<Node*> nodes) {
    Field f;
    f.name = std::move(name);
    f.value.type = type;
    f.value.nodes = std::move(nodes);
    n.fields.push_back(std::move(f));
}

} // namespace fl::scene
