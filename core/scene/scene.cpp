#include "scene.h"

#include <atomic>

#include <algorithm>

namespace fl::scene {

std::uint64_t SceneSerial::next() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

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
        if (d.node == &node && d.field == field) return d.tape.get();
    for (const auto& child : referenced) // a node of an Inline's scene
        if (const formula::Tape* tape = child->definition(node, field)) return tape;
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

const std::string& Scene::pathOf(int file) const {
    static const std::string none;
    return file >= 0 && std::size_t(file) < files.size() ? files[std::size_t(file)].path : none;
}

std::string Scene::locationOf(const Node& n) const {
    const std::string& path = pathOf(n.file);
    return (path.empty() ? std::string("<scene>") : path) + ":" + std::to_string(n.where.line) +
           ":" + std::to_string(n.where.column);
}

const Node* effectiveNode(const Node* n) {
    for (int i = 0; n && n->proto && i < 64; ++i) // 64: deeper than any PROTO nesting allowed
        n = n->expansion.empty() ? nullptr : n->expansion.front();
    return n;
}

std::vector<const Scene*> scenesShownBy(const Scene& scene) {
    std::vector<const Scene*> all{&scene};
    for (std::size_t i = 0; i < all.size(); ++i)
        all[i]->forEachNode([&](const Node& n) {
            if (n.inlined && !n.inProtoBody &&
                std::find(all.begin(), all.end(), n.inlined) == all.end())
                all.push_back(n.inlined);
        });
    return all;
}

void Scene::shiftFileIndices(int offset) {
    auto shift = [offset](int& file) {
        if (file >= 0) file += offset;
    };
    auto shiftRoutes = [&](std::vector<Route>& routes) {
        for (Route& r : routes)
            shift(r.file);
    };
    for (auto& n : nodes_) {
        shift(n->file);
        for (Field& f : n->fields) {
            shift(f.file);
            for (StringOrigin& o : f.value.stringOrigins)
                shift(o.file);
        }
        for (FieldDeclaration& d : n->declarations)
            for (StringOrigin& o : d.value.stringOrigins)
                shift(o.file);
        shiftRoutes(n->expansionRoutes);
    }
    for (auto& p : protos_) {
        shift(p->file);
        shiftRoutes(p->routes);
        for (FieldDeclaration& d : p->interface)
            for (StringOrigin& o : d.value.stringOrigins)
                shift(o.file);
    }
    shiftRoutes(routes);
    for (auto& child : referenced)
        child->shiftFileIndices(offset);
}

} // namespace fl::scene
