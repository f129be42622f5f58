#include "scene.h"

namespace fl::scene {

std::size_t FieldValue::elementCount() const {
    if (holdsNodes(type)) return nodes.size();
    if (holdsStrings(type) || type == FieldType::Unknown) return strings.size();
    const int per = componentsPerElement(type);
    return per > 0 ? numbers.size() / static_cast<std::size_t>(per) : numbers.size();
}

const Field* Node::field(std::string_view name) const {
    for (const Field& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

Field* Node::field(std::string_view name) {
    for (Field& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

const FieldDeclaration* ProtoDeclaration::interfaceField(std::string_view fieldName) const {
    for (const FieldDeclaration& f : interface)
        if (f.name == fieldName) return &f;
    return nullptr;
}

const formula::Tape* Scene::definition(const Node& node, std::string_view field) const {
    for (const CompiledDefinition& d : definitions)
        if (d.node == &node && d.field == field) return &d.tape;
    return nullptr;
}

Node* Scene::newNode() {
    nodes_.push_back(std::make_unique<Node>());
    return nodes_.back().get();
}

ProtoDeclaration* Scene::newProto() {
    protos_.push_back(std::make_unique<ProtoDeclaration>());
    return protos_.back().get();
}

} // namespace fl::scene
