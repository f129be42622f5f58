#include "scene_writer.h"

#include "node_graph.h"

#include <charconv>
#include <cmath>
#include <set>

namespace fl::scene {

std::string formatNumber(double v) {
    if (v == 0.0) return std::signbit(v) ? "-0" : "0";
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, p) : std::string("0");
}

std::string xmlAttributeText(std::string_view s, char quote) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '\n':
            out += "&#10;";
            break;
        case '\r':
            out += "&#13;";
            break;
        case '\t':
            out += "&#9;";
            break;
        case '\'':
            out += quote == '"' ? "'" : "&apos;";
            break;
        case '"':
            out += quote == '\'' ? "\"" : "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string xmlEscape(std::string_view s) {
    return xmlAttributeText(s, 0);
}

std::string quotedString(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

namespace {

std::string quoteClassic(std::string_view s) {
    return quotedString(s);
}

std::string element(const FieldValue& v, FieldType single, std::size_t index, bool xml) {
    if (single == FieldType::SFBool) {
        const bool b = v.numbers[index] != 0.0;
        return xml ? (b ? "true" : "false") : (b ? "TRUE" : "FALSE");
    }
    return formatNumber(v.numbers[index]);
}

// Numbers of a value, grouped per element ("1 2 3, 4 5 6").
std::string numbersText(const FieldValue& v, bool xml) {
    const FieldType single = singleOf(v.type);
    const int per = std::max(1, componentsPerElement(single));
    std::string out;
    for (std::size_t i = 0; i < v.numbers.size(); ++i) {
        if (i > 0) out += (single != FieldType::SFImage && i % per == 0) ? ", " : " ";
        out += element(v, single, i, xml);
    }
    return out;
}

// Where a raw unknown value from XML is not valid Classic syntax, quote it.
bool looksLikeClassicValue(std::string_view raw) {
    if (raw.empty()) return false;
    const char c = raw.front();
    return c == '[' || c == '"' || c == '-' || c == '+' || c == '.' || (c >= '0' && c <= '9') ||
           raw == "TRUE" || raw == "FALSE" || raw == "NULL";
}

class Writer {
  public:
    Writer(const Scene& scene, Encoding encoding) : scene_(scene), encoding_(encoding) {}

    std::string classic();
    std::string xml();

  private:
    void line(int depth, const std::string& text) {
        out_.append(static_cast<std::size_t>(depth) * 2, ' ');
        out_ += text;
        out_ += '\n';
    }

    // --- Classic
    void classicProto(const ProtoDeclaration& p, int depth);
    void classicStatementNode(const Node* n, int depth);
    std::string classicNodeRef(const Node* n, int depth); // "USE X" or a node written inline
    void classicNodeBody(const Node& n, int depth);
    std::string classicValue(const FieldValue& v, int depth);
    std::string classicNodeList(const std::vector<Node*>& nodes, int depth); // "[ ... ]"
    void classicRoute(const Route& r, int depth);

    // --- XML
    void xmlProto(const ProtoDeclaration& p, int depth);
    void xmlNode(const Node* n, int depth, const std::string& containerField);
    std::string xmlAttributeValue(const FieldValue& v);
    void xmlRoute(const Route& r, int depth);
    void xmlImport(const KeptStatement& s, int depth);

    const Scene& scene_;
    Encoding encoding_;
    std::string out_;
    std::set<const Node*> written_;
    WalkPath path_; // the nodes being written
};

// ------------------------------------------------------------- Classic

std::string Writer::classic() {
    if (encoding_ == Encoding::Vrml97) {
        out_ = "#VRML V2.0 utf8\n";
    } else {
        const std::string version =
            scene_.version.empty() || scene_.encoding == Encoding::Vrml97 ? "3.3" : scene_.version;
        out_ = "#X3D V" + version + " utf8\n";
        out_ += "PROFILE " + (scene_.profile.empty() ? std::string("Immersive") : scene_.profile) +
                "\n";
        for (const Component& c : scene_.components)
            out_ += "COMPONENT " + c.name + ":" + std::to_string(c.level) + "\n";
        for (const std::string& u : scene_.units)
            out_ += u + "\n";
        for (const auto& [k, v] : scene_.meta)
            out_ += "META " + quoteClassic(k) + " " + quoteClassic(v) + "\n";
    }
    out_ += "\n";
    for (const ProtoDeclaration* p : scene_.protos)
        classicProto(*p, 0);
    // IMPORTed names are used like DEFs, so the IMPORTs come first.
    for (const KeptStatement& s : scene_.imports)
        line(0, s.text);
    for (const Node* n : scene_.roots)
        classicStatementNode(n, 0);
    for (const Route& r : scene_.routes)
        classicRoute(r, 0);
    for (const KeptStatement& s : scene_.exports)
        line(0, s.text);
    return out_;
}

void Writer::classicProto(const ProtoDeclaration& p, int depth) {
    const bool vrml = encoding_ == Encoding::Vrml97;
    line(depth, std::string(p.external ? "EXTERNPROTO " : "PROTO ") + p.name + " [");
    for (const FieldDeclaration& d : p.interface) {
        std::string text =
            std::string(vrml ? vrml97AccessTypeName(d.access) : accessTypeName(d.access)) + " " +
            std::string(fieldTypeName(d.type)) + " " + d.name;
        if (!p.external && hasInitialValue(d.access))
            text += " " + classicValue(d.value, depth + 2);
        line(depth + 1, text);
    }
    if (p.external) {
        std::string urls = "] [";
        for (std::size_t i = 0; i < p.urls.size(); ++i)
            urls += (i ? " " : "") + quoteClassic(p.urls[i]);
        line(depth, urls + "]");
        return;
    }
    line(depth, "] {");
    for (const ProtoDeclaration* nested : p.protos)
        classicProto(*nested, depth + 1);
    for (const KeptStatement& s : p.imports)
        line(depth + 1, s.text);
    for (const Node* n : p.body)
        classicStatementNode(n, depth + 1);
    for (const Route& r : p.routes)
        classicRoute(r, depth + 1);
    line(depth, "}");
}

void Writer::classicStatementNode(const Node* n, int depth) {
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += classicNodeRef(n, depth);
    out_ += '\n';
}

std::string Writer::classicNodeRef(const Node* n, int depth) {
    if (!n) return "NULL";
    if (!n->defName.empty() && (written_.count(n) || n->type == "IMPORT"))
        return "USE " + n->defName; // an IMPORTed node is named by its IMPORT
    const WalkPath::Step step(path_, n);
    if (!step.entered()) return "NULL"; // a loop or a depth the reader refuses
    written_.insert(n);
    std::string head = n->defName.empty() ? "" : "DEF " + n->defName + " ";
    head += n->type + " {";
    if (n->fields.empty() && n->declarations.empty()) return head + " }";
    // The body goes straight into out_; callers print the head first.
    std::string saved;
    saved.swap(out_);
    out_ = head + "\n";
    classicNodeBody(*n, depth + 1);
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += "}";
    std::string text;
    text.swap(out_);
    out_.swap(saved);
    return text;
}

void Writer::classicNodeBody(const Node& n, int depth) {
    const bool vrml = encoding_ == Encoding::Vrml97;
    for (const FieldDeclaration& d : n.declarations) {
        std::string text =
            std::string(vrml ? vrml97AccessTypeName(d.access) : accessTypeName(d.access)) + " " +
            std::string(fieldTypeName(d.type)) + " " + d.name;
        if (!d.isReferences.empty()) {
            // The declaration with its first IS, then each further one.
            line(depth, text + " IS " + d.isReferences.front());
            for (std::size_t i = 1; i < d.isReferences.size(); ++i)
                line(depth, d.name + " IS " + d.isReferences[i]);
            if (!d.hasValue) continue; // IS only
        }
        if (hasInitialValue(d.access)) text += " " + classicValue(d.value, depth);
        line(depth, text);
    }
    for (const Field& f : n.fields) {
        if (!f.isReferences.empty()) {
            for (const std::string& is : f.isReferences)
                line(depth, f.name + " IS " + is);
            if (f.value.numbers.empty() && f.value.strings.empty() && f.value.nodes.empty())
                continue; // IS only
        }
        line(depth, f.name + " " + classicValue(f.value, depth));
    }
}

std::string Writer::classicNodeList(const std::vector<Node*>& nodes, int depth) {
    std::string out = "[\n";
    for (const Node* child : nodes) {
        out.append(static_cast<std::size_t>(depth + 1) * 2, ' ');
        out += classicNodeRef(child, depth + 1) + "\n";
    }
    out.append(static_cast<std::size_t>(depth) * 2, ' ');
    return out + "]";
}

std::string Writer::classicValue(const FieldValue& v, int depth) {
    if (v.type == FieldType::Unknown) {
        if (!v.nodes.empty()) return classicNodeList(v.nodes, depth);
        const std::string raw = v.strings.empty() ? std::string() : v.strings.front();
        return looksLikeClassicValue(raw) ? raw : quoteClassic(raw);
    }
    if (holdsNodes(v.type)) {
        if (v.type == FieldType::SFNode)
            return v.nodes.empty() ? "NULL" : classicNodeRef(v.nodes.front(), depth);
        return v.nodes.empty() ? "[]" : classicNodeList(v.nodes, depth);
    }
    if (holdsStrings(v.type)) {
        if (v.type == FieldType::SFString)
            return quoteClassic(v.strings.empty() ? std::string() : v.strings.front());
        std::string out = "[";
        for (std::size_t i = 0; i < v.strings.size(); ++i)
            out += (i ? " " : "") + quoteClassic(v.strings[i]);
        return out + "]";
    }
    if (isMultiple(v.type)) return "[" + numbersText(v, false) + "]";
    return numbersText(v, false);
}

void Writer::classicRoute(const Route& r, int depth) {
    line(depth, "ROUTE " + r.fromNode->defName + "." + r.fromField + " TO " + r.toNode->defName +
                    "." + r.toField);
}

// ----------------------------------------------------------------- XML

std::string Writer::xml() {
    const std::string version =
        scene_.version.empty() || scene_.encoding == Encoding::Vrml97 ? "3.3" : scene_.version;
    const std::string profile = scene_.profile.empty() ? "Immersive" : scene_.profile;
    out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out_ += "<!DOCTYPE X3D PUBLIC \"ISO//Web3D//DTD X3D " + version +
            "//EN\" \"https://www.web3d.org/specifications/x3d-" + version + ".dtd\">\n";
    out_ += "<X3D profile='" + xmlEscape(profile) + "' version='" + xmlEscape(version) + "'>\n";
    if (!scene_.components.empty() || !scene_.meta.empty() || !scene_.units.empty()) {
        line(1, "<head>");
        for (const Component& c : scene_.components)
            line(2, "<component name='" + xmlEscape(c.name) + "' level='" +
                        std::to_string(c.level) + "'/>");
        for (const std::string& u : scene_.units) {
            // "UNIT category name factor"
            std::string parts[4];
            std::size_t k = 0, start = 0;
            for (std::size_t i = 0; i <= u.size() && k < 4; ++i)
                if (i == u.size() || u[i] == ' ') {
                    parts[k++] = u.substr(start, i - start);
                    start = i + 1;
                }
            line(2, "<unit category='" + xmlEscape(parts[1]) + "' name='" + xmlEscape(parts[2]) +
                        "' conversionFactor='" + xmlEscape(parts[3]) + "'/>");
        }
        for (const auto& [k, v] : scene_.meta)
            line(2, "<meta name='" + xmlEscape(k) + "' content='" + xmlEscape(v) + "'/>");
        line(1, "</head>");
    }
    line(1, "<Scene>");
    for (const ProtoDeclaration* p : scene_.protos)
        xmlProto(*p, 2);
    for (const KeptStatement& s : scene_.imports)
        xmlImport(s, 2);
    for (const Node* n : scene_.roots)
        xmlNode(n, 2, {});
    for (const Route& r : scene_.routes)
        xmlRoute(r, 2);
    for (const KeptStatement& s : scene_.exports) {
        std::string rest = s.text.substr(7);
        std::string as;
        if (auto p = rest.find(" AS "); p != std::string::npos) {
            as = rest.substr(p + 4);
            rest = rest.substr(0, p);
        }
        line(2, "<EXPORT localDEF='" + xmlEscape(rest) + "'" +
                    (as.empty() ? "" : " AS='" + xmlEscape(as) + "'") + "/>");
    }
    line(1, "</Scene>");
    out_ += "</X3D>\n";
    return out_;
}

void Writer::xmlProto(const ProtoDeclaration& p, int depth) {
    if (p.external) {
        std::string urls;
        for (std::size_t i = 0; i < p.urls.size(); ++i)
            urls += (i ? " " : "") + quoteClassic(p.urls[i]);
        line(depth,
             "<ExternProtoDeclare name='" + xmlEscape(p.name) + "' url='" + xmlEscape(urls) + "'>");
    } else {
        line(depth, "<ProtoDeclare name='" + xmlEscape(p.name) + "'>");
        line(depth + 1, "<ProtoInterface>");
    }
    const int fieldDepth = p.external ? depth + 1 : depth + 2;
    for (const FieldDeclaration& d : p.interface) {
        std::string head = "<field name='" + xmlEscape(d.name) + "' type='" +
                           std::string(fieldTypeName(d.type)) + "' accessType='" +
                           std::string(accessTypeName(d.access)) + "'";
        const bool nodes = holdsNodes(d.type) && !d.value.nodes.empty();
        if (!p.external && hasInitialValue(d.access) && !holdsNodes(d.type) && d.hasValue)
            head += " value='" + xmlEscape(xmlAttributeValue(d.value)) + "'";
        if (!nodes || p.external) {
            line(fieldDepth, head + "/>");
            continue;
        }
        line(fieldDepth, head + ">");
        for (const Node* n : d.value.nodes)
            xmlNode(n, fieldDepth + 1, {});
        line(fieldDepth, "</field>");
    }
    if (p.external) {
        line(depth, "</ExternProtoDeclare>");
        return;
    }
    line(depth + 1, "</ProtoInterface>");
    line(depth + 1, "<ProtoBody>");
    for (const ProtoDeclaration* nested : p.protos)
        xmlProto(*nested, depth + 2);
    for (const KeptStatement& s : p.imports)
        xmlImport(s, depth + 2);
    for (const Node* n : p.body)
        xmlNode(n, depth + 2, {});
    for (const Route& r : p.routes)
        xmlRoute(r, depth + 2);
    line(depth + 1, "</ProtoBody>");
    line(depth, "</ProtoDeclare>");
}

std::string Writer::xmlAttributeValue(const FieldValue& v) {
    if (v.type == FieldType::Unknown) return v.strings.empty() ? std::string() : v.strings.front();
    if (v.type == FieldType::SFString) return v.strings.empty() ? std::string() : v.strings.front();
    if (v.type == FieldType::MFString) {
        std::string out;
        for (std::size_t i = 0; i < v.strings.size(); ++i)
            out += (i ? " " : "") + quoteClassic(v.strings[i]);
        return out;
    }
    return numbersText(v, true);
}

void Writer::xmlNode(const Node* n, int depth, const std::string& containerField) {
    const bool instance = n->proto != nullptr;
    // An IMPORTed node's type is not known here; a USE ignores the tag.
    const std::string tag = instance ? "ProtoInstance" : n->type == "IMPORT" ? "Group" : n->type;
    std::string head = "<" + tag;
    if (instance) head += " name='" + xmlEscape(n->type) + "'";
    // containerField: written when it differs from the node type's default.
    std::string defaultContainer = n->spec ? std::string(n->spec->containerField) : "children";
    if (!containerField.empty() && containerField != defaultContainer)
        head += " containerField='" + xmlEscape(containerField) + "'";
    if (!n->defName.empty() && (written_.count(n) || n->type == "IMPORT")) {
        line(depth, head + " USE='" + xmlEscape(n->defName) + "'/>");
        return;
    }
    const WalkPath::Step step(path_, n);
    if (!step.entered()) return; // a loop or a depth the reader refuses
    written_.insert(n);
    if (!n->defName.empty()) head += " DEF='" + xmlEscape(n->defName) + "'";
    struct Child {
        std::string container;
        const Node* node;
    };
    std::vector<Child> children;
    std::vector<const Field*> connections;
    std::vector<const Field*> instanceFields;
    for (const Field& f : n->fields) {
        if (!f.isReferences.empty()) {
            connections.push_back(&f);
            if (f.value.numbers.empty() && f.value.strings.empty() && f.value.nodes.empty())
                continue; // IS only
        }
        if (instance) {
            instanceFields.push_back(&f);
            continue;
        }
        if (holdsNodes(f.value.type) ||
            (f.value.type == FieldType::Unknown && !f.value.nodes.empty())) {
            for (const Node* child : f.value.nodes)
                children.push_back({f.name, child});
            continue;
        }
        head += " " + f.name + "='" + xmlEscape(xmlAttributeValue(f.value)) + "'";
    }
    const bool empty = children.empty() && connections.empty() && instanceFields.empty() &&
                       n->declarations.empty();
    if (empty) {
        line(depth, head + "/>");
        return;
    }
    line(depth, head + ">");
    for (const FieldDeclaration& d : n->declarations) {
        std::string fh = "<field name='" + xmlEscape(d.name) + "' type='" +
                         std::string(fieldTypeName(d.type)) + "' accessType='" +
                         std::string(accessTypeName(d.access)) + "'";
        if (hasInitialValue(d.access) && !holdsNodes(d.type) && d.hasValue)
            fh += " value='" + xmlEscape(xmlAttributeValue(d.value)) + "'";
        if (!holdsNodes(d.type) || d.value.nodes.empty() || !d.isReferences.empty()) {
            line(depth + 1, fh + "/>");
            continue;
        }
        line(depth + 1, fh + ">");
        for (const Node* child : d.value.nodes)
            xmlNode(child, depth + 2, {});
        line(depth + 1, "</field>");
    }
    bool declarationConnections = false;
    for (const FieldDeclaration& d : n->declarations)
        declarationConnections |= !d.isReferences.empty();
    if (!connections.empty() || declarationConnections) {
        line(depth + 1, "<IS>");
        auto connect = [&](const std::string& field, const std::vector<std::string>& references) {
            for (const std::string& is : references)
                line(depth + 2, "<connect nodeField='" + xmlEscape(field) + "' protoField='" +
                                    xmlEscape(is) + "'/>");
        };
        for (const FieldDeclaration& d : n->declarations)
            connect(d.name, d.isReferences);
        for (const Field* f : connections)
            connect(f->name, f->isReferences);
        line(depth + 1, "</IS>");
    }
    for (const Field* f : instanceFields) {
        std::string fh = "<fieldValue name='" + xmlEscape(f->name) + "'";
        if (!holdsNodes(f->value.type) && f->value.nodes.empty()) {
            line(depth + 1, fh + " value='" + xmlEscape(xmlAttributeValue(f->value)) + "'/>");
            continue;
        }
        if (f->value.nodes.empty()) {
            line(depth + 1, fh + "/>");
            continue;
        }
        line(depth + 1, fh + ">");
        for (const Node* child : f->value.nodes)
            xmlNode(child, depth + 2, {});
        line(depth + 1, "</fieldValue>");
    }
    for (const Child& c : children)
        xmlNode(c.node, depth + 1, c.container);
    line(depth, "</" + tag + ">");
}

void Writer::xmlImport(const KeptStatement& s, int depth) {
    // "IMPORT inline.exported AS name"
    std::string rest = s.text.substr(7);
    std::string as;
    if (auto p = rest.find(" AS "); p != std::string::npos) {
        as = rest.substr(p + 4);
        rest = rest.substr(0, p);
    }
    const auto dot = rest.find('.');
    line(depth, "<IMPORT inlineDEF='" + xmlEscape(rest.substr(0, dot)) + "' importedDEF='" +
                    xmlEscape(dot == std::string::npos ? "" : rest.substr(dot + 1)) + "'" +
                    (as.empty() ? "" : " AS='" + xmlEscape(as) + "'") + "/>");
}

void Writer::xmlRoute(const Route& r, int depth) {
    line(depth, "<ROUTE fromNode='" + xmlEscape(r.fromNode->defName) + "' fromField='" +
                    xmlEscape(r.fromField) + "' toNode='" + xmlEscape(r.toNode->defName) +
                    "' toField='" + xmlEscape(r.toField) + "'/>");
}

} // namespace

std::string writeXml(const Scene& scene) {
    return Writer(scene, Encoding::Xml).xml();
}

std::string writeClassic(const Scene& scene, Encoding encoding) {
    return Writer(scene, encoding == Encoding::Vrml97 ? Encoding::Vrml97 : Encoding::ClassicVrml)
        .classic();
}

std::string writeScene(const Scene& scene, Encoding encoding) {
    return encoding == Encoding::Xml ? writeXml(scene) : writeClassic(scene, encoding);
}

namespace {

struct SceneSuffix {
    std::string_view text;
    Encoding encoding;
    bool gzipped;
};

// No suffix ends another one, so the order does not matter.
constexpr SceneSuffix kSceneSuffixes[] = {
    {".x3d", Encoding::Xml, false},
    {".x3dv", Encoding::ClassicVrml, false},
    {".wrl", Encoding::Vrml97, false},
    {".x3d.gz", Encoding::Xml, true},
    {".x3dv.gz", Encoding::ClassicVrml, true},
    {".wrl.gz", Encoding::Vrml97, true},
    {".x3dz", Encoding::Xml, true},
    {".x3dvz", Encoding::ClassicVrml, true},
    {".wrz", Encoding::Vrml97, true},
};

std::string lowered(const std::string& text) {
    std::string lower(text);
    for (char& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower;
}

} // namespace

bool isSceneFileName(const std::string& name) {
    const std::string lower = lowered(name);
    for (const SceneSuffix& s : kSceneSuffixes)
        if (lower.size() > s.text.size() && lower.ends_with(s.text)) return true;
    return false;
}

std::string sceneFilePatterns() {
    std::string out;
    for (const SceneSuffix& s : kSceneSuffixes)
        out += (out.empty() ? "*" : " *") + std::string(s.text);
    return out;
}

bool encodingForPath(const std::string& path, Encoding& encoding, bool& gzipped) {
    const std::string lower = lowered(path);
    for (const SceneSuffix& s : kSceneSuffixes)
        if (lower.ends_with(s.text)) {
            encoding = s.encoding;
            gzipped = s.gzipped;
            return true;
        }
    gzipped = false;
    return false;
}

} // namespace fl::scene
