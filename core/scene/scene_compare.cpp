#include "scene_compare.h"

#include "node_graph.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fl::scene {
namespace {

class Comparer {
  public:
    bool scenes(const Scene& a, const Scene& b) {
        if (a.profile != b.profile && !(a.profile.empty() || b.profile.empty()))
            return differ("profile " + a.profile + " vs " + b.profile);
        if (a.components.size() != b.components.size()) return differ("number of components");
        for (std::size_t i = 0; i < a.components.size(); ++i)
            if (a.components[i].name != b.components[i].name ||
                a.components[i].level != b.components[i].level)
                return differ("component " + a.components[i].name);
        if (a.meta != b.meta) return differ("meta statements");
        if (a.protos.size() != b.protos.size()) return differ("number of PROTO declarations");
        for (std::size_t i = 0; i < a.protos.size(); ++i)
            if (!proto(*a.protos[i], *b.protos[i])) return false;
        if (!nodeLists(a.roots, b.roots, "scene")) return false;
        if (!routes(a.routes, b.routes)) return false;
        if (a.imports.size() != b.imports.size() || a.exports.size() != b.exports.size())
            return differ("IMPORT/EXPORT statements");
        for (std::size_t i = 0; i < a.imports.size(); ++i)
            if (a.imports[i].text != b.imports[i].text)
                return differ("IMPORT " + a.imports[i].text + " vs " + b.imports[i].text);
        for (std::size_t i = 0; i < a.exports.size(); ++i)
            if (a.exports[i].text != b.exports[i].text)
                return differ("EXPORT " + a.exports[i].text + " vs " + b.exports[i].text);
        return true;
    }

    std::string difference;

  private:
    bool differ(std::string what) {
        if (difference.empty()) difference = std::move(what);
        return false;
    }

    bool proto(const ProtoDeclaration& a, const ProtoDeclaration& b) {
        const std::string where = "PROTO " + a.name;
        if (a.name != b.name || a.external != b.external) return differ(where + " vs " + b.name);
        if (a.urls != b.urls) return differ(where + ": urls");
        if (a.interface.size() != b.interface.size()) return differ(where + ": interface size");
        for (std::size_t i = 0; i < a.interface.size(); ++i)
            if (!declaration(a.interface[i], b.interface[i], where, !a.external)) return false;
        if (a.protos.size() != b.protos.size()) return differ(where + ": nested PROTOs");
        for (std::size_t i = 0; i < a.protos.size(); ++i)
            if (!proto(*a.protos[i], *b.protos[i])) return false;
        if (a.imports.size() != b.imports.size()) return differ(where + ": IMPORT statements");
        return nodeLists(a.body, b.body, where + " body") && routes(a.routes, b.routes);
    }

    bool declaration(const FieldDeclaration& a, const FieldDeclaration& b, const std::string& where,
                     bool compareValue) {
        if (a.name != b.name || a.type != b.type || a.access != b.access ||
            a.isReferences != b.isReferences)
            return differ(where + ": field declaration " + a.name + " vs " + b.name);
        if (compareValue && hasInitialValue(a.access))
            return value(a.value, b.value, where + "." + a.name);
        return true;
    }

    bool nodeLists(const std::vector<Node*>& a, const std::vector<Node*>& b,
                   const std::string& where) {
        if (a.size() != b.size())
            return differ(where + ": " + std::to_string(a.size()) + " vs " +
                          std::to_string(b.size()) + " nodes");
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!node(a[i], b[i], where)) return false;
        return true;
    }

    bool node(const Node* a, const Node* b, const std::string& where) {
        if (!a || !b) return a == b ? true : differ(where + ": NULL vs node");
        if (auto it = pairs_.find(a); it != pairs_.end())
            return it->second == b ? true
                                   : differ(where + ": USE " + a->defName + " shares differently");
        if (reverse_.count(b))
            return differ(where + ": " + a->type + " is shared on one side only");
        pairs_[a] = b;
        reverse_[b] = a;
        const WalkPath::Step step(path_, a); // pairs_ ends loops; this bounds the depth
        if (!step.entered()) return differ(where + ": nodes nest too deep to compare");
        const std::string here =
            where + " > " + a->type + (a->defName.empty() ? "" : " " + a->defName);
        if (a->type != b->type || a->defName != b->defName)
            return differ(here + " vs " + b->type + " " + b->defName);
        if (a->declarations.size() != b->declarations.size())
            return differ(here + ": declarations");
        for (std::size_t i = 0; i < a->declarations.size(); ++i)
            if (!declaration(a->declarations[i], b->declarations[i], here, true)) return false;
        // An empty node field (children [], geometry NULL) means the same as
        // no field: XML cannot write it.
        auto meaningful = [](const Field& f) {
            return !(holdsNodes(f.value.type) && f.value.nodes.empty() && f.isReferences.empty());
        };
        auto count = [&](const Node* n) {
            return std::count_if(n->fields.begin(), n->fields.end(), meaningful);
        };
        if (count(a) != count(b))
            return differ(here + ": " + std::to_string(count(a)) + " vs " +
                          std::to_string(count(b)) + " fields");
        for (const Field& fa : a->fields) {
            if (!meaningful(fa)) continue;
            const Field* fb = b->field(fa.name);
            if (!fb) return differ(here + ": field " + fa.name + " missing");
            if (fa.isReferences != fb->isReferences) {
                auto joined = [](const std::vector<std::string>& v) {
                    std::string out;
                    for (const std::string& s : v)
                        out += (out.empty() ? "" : ", ") + s;
                    return out;
                };
                return differ(here + "." + fa.name + ": IS " + joined(fa.isReferences) + " vs " +
                              joined(fb->isReferences));
            }
            if (!value(fa.value, fb->value, here + "." + fa.name)) return false;
        }
        return true;
    }

    bool value(const FieldValue& a, const FieldValue& b, const std::string& where) {
        if (a.type != b.type)
            return differ(where + ": type " + std::string(fieldTypeName(a.type)) + " vs " +
                          std::string(fieldTypeName(b.type)));
        if (a.type == FieldType::Unknown && !a.nodes.empty())
            return nodeLists(a.nodes, b.nodes, where);
        if (a.type == FieldType::Unknown && a.strings.size() == 1 && b.strings.size() == 1) {
            // Unknown values are kept as the text written; moving between
            // encodings may add or drop one level of "quotes".
            auto unquoted = [](std::string_view s) {
                return s.size() >= 2 && s.front() == '"' && s.back() == '"'
                           ? s.substr(1, s.size() - 2)
                           : s;
            };
            if (unquoted(a.strings[0]) != unquoted(b.strings[0]))
                return differ(where + ": unknown value '" + a.strings[0].substr(0, 80) + "' vs '" +
                              b.strings[0].substr(0, 80) + "'");
            return true;
        }
        if (a.strings != b.strings) return differ(where + ": strings differ");
        if (a.numbers.size() != b.numbers.size())
            return differ(where + ": " + std::to_string(a.numbers.size()) + " vs " +
                          std::to_string(b.numbers.size()) + " numbers");
        for (std::size_t i = 0; i < a.numbers.size(); ++i) {
            const double x = a.numbers[i], y = b.numbers[i];
            const bool same =
                (std::isnan(x) && std::isnan(y)) || (x == y && std::signbit(x) == std::signbit(y));
            if (!same) return differ(where + ": number " + std::to_string(i) + " differs");
        }
        return nodeLists(a.nodes, b.nodes, where);
    }

    bool routes(const std::vector<Route>& a, const std::vector<Route>& b) {
        if (a.size() != b.size()) return differ("number of ROUTEs");
        for (std::size_t i = 0; i < a.size(); ++i) {
            auto it = pairs_.find(a[i].fromNode);
            auto jt = pairs_.find(a[i].toNode);
            const bool fromSame = it != pairs_.end()
                                      ? it->second == b[i].fromNode
                                      : a[i].fromNode->defName == b[i].fromNode->defName;
            const bool toSame = jt != pairs_.end() ? jt->second == b[i].toNode
                                                   : a[i].toNode->defName == b[i].toNode->defName;
            if (!fromSame || !toSame || a[i].fromField != b[i].fromField ||
                a[i].toField != b[i].toField)
                return differ("ROUTE " + a[i].fromNode->defName + "." + a[i].fromField);
        }
        return true;
    }

    std::map<const Node*, const Node*> pairs_;
    std::map<const Node*, const Node*> reverse_;
    WalkPath path_;
};

} // namespace

bool sameModel(const Scene& a, const Scene& b, std::string* difference) {
    Comparer c;
    const bool same = c.scenes(a, b);
    if (difference) *difference = c.difference;
    return same;
}

} // namespace fl::scene
