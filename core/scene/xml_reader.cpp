#include "xml_reader.h"

#include "components.h"

#include "field_access.h"
#include "source_map.h"
#include "xml_syntax_help.h"

#include <QString>
#include <QXmlStreamReader>

#include <algorithm>

namespace fl::scene {
namespace {

std::string str(QStringView s) {
    return s.toString().toStdString();
}

class XmlReader {
  public:
    explicit XmlReader(SceneBuilder& b)
        : b_(b), bytes_(b.scene().files[b.file()].text), lines_(bytes_) {
        text_ = QString::fromUtf8(bytes_.data(), static_cast<qsizetype>(bytes_.size()));
        buildOffsetMap();
        xml_.addData(text_);
        xml_.setNamespaceProcessing(false);
    }

    void readFile();

  private:
    struct Attr {
        std::string name;
        std::string value;       // decoded by the XML parser
        std::size_t valueOffset; // byte offset of the raw value in the file
        FilePos pos;             // of the attribute name
    };

    // --- positions
    void buildOffsetMap();
    std::size_t byteOffset(qsizetype q) const {
        if (qToByte_.empty()) return static_cast<std::size_t>(q);
        return qToByte_[static_cast<std::size_t>(std::clamp<qsizetype>(q, 0, qToByte_.size() - 1))];
    }
    // The parser's error, explained where it is one a student makes (a
    // formula's & or < inside an attribute).
    [[noreturn]] void malformed() {
        if (auto help = explainXmlSyntaxError(bytes_, here()))
            b_.failWithFix(help->at, std::move(help->message), std::move(help->suggestion),
                           std::move(help->fix));
        b_.fail(here(), "malformed XML: " + xml_.errorString().toStdString());
    }
    FilePos here() const {
        return {static_cast<int>(xml_.lineNumber()), static_cast<int>(xml_.columnNumber()) + 1};
    }
    void scanTag(); // fills tagPos_ and attrs_ for the current StartElement

    // --- structure
    bool nextChild(); // advances to the next child StartElement of the current element
    void skipElement();
    void head();
    void headElement();
    void statement(std::vector<Node*>* roots, Node* parent);
    Node* nodeElement();
    void nodeContent(Node& n);
    void attachChild(Node& parent, Node* child, const std::string& containerField, FilePos pos);
    void setAttributeField(Node& n, const Attr& a);
    FieldDeclaration fieldElement(bool external, bool inProtoInterface);
    void isElement(Node& n);
    void fieldValueElement(Node& instance);
    void protoDeclare(bool external);
    void route();
    void importExport(bool isImport);
    const Attr* attr(std::string_view name) const {
        for (const Attr& a : attrs_)
            if (a.name == name) return &a;
        return nullptr;
    }
    std::string attrValue(std::string_view name) const {
        const Attr* a = attr(name);
        return a ? a->value : std::string();
    }
    bool parseValue(const Attr& a, FieldType type, FieldValue& out) {
        std::string problem;
        StringOrigin origin{b_.file(), a.valueOffset, StringEscapes::XmlAttribute};
        if (parseXmlAttributeValue(a.value, type, out, origin, bytes_, problem)) return true;
        b_.error(lines_.position(a.valueOffset), "attribute " + a.name + ": " + problem);
        return false;
    }

    SceneBuilder& b_;
    const std::string& bytes_;
    QString text_;
    QXmlStreamReader xml_;
    std::vector<std::size_t> qToByte_;
    LineIndex lines_;
    FilePos tagPos_;
    std::vector<Attr> attrs_;
};

void XmlReader::buildOffsetMap() {
    bool ascii = true;
    for (char c : bytes_)
        if (static_cast<unsigned char>(c) >= 0x80) {
            ascii = false;
            break;
        }
    if (ascii) return;
    // Map each UTF-16 unit of text_ to the byte where its character starts.
    qToByte_.reserve(static_cast<std::size_t>(text_.size()) + 1);
    std::size_t byte = 0;
    for (qsizetype q = 0; q < text_.size(); ++q) {
        qToByte_.push_back(byte);
        const char16_t u = text_[q].unicode();
        if (QChar::isHighSurrogate(u)) {
            qToByte_.push_back(byte);
            ++q;
            byte += 4;
        } else {
            byte += u < 0x80 ? 1 : u < 0x800 ? 2 : 3;
        }
    }
    qToByte_.push_back(byte);
}

void XmlReader::scanTag() {
    attrs_.clear();
    qsizetype end = xml_.characterOffset();
    qsizetype start = end - 1;
    while (start > 0 && text_[start] != u'<')
        --start;
    tagPos_ = lines_.position(byteOffset(start));
    // Raw offsets of the attribute values, in file order.
    std::vector<std::pair<QString, qsizetype>> raw;
    qsizetype i = start + 1;
    auto isSpace = [](QChar c) { return c == u' ' || c == u'\t' || c == u'\n' || c == u'\r'; };
    while (i < end && !isSpace(text_[i]) && text_[i] != u'>' && text_[i] != u'/')
        ++i; // element name
    while (i < end) {
        while (i < end && isSpace(text_[i]))
            ++i;
        const qsizetype nameStart = i;
        while (i < end && text_[i] != u'=' && !isSpace(text_[i]) && text_[i] != u'>' &&
               text_[i] != u'/')
            ++i;
        if (i == nameStart) break;
        QString name = text_.mid(nameStart, i - nameStart);
        while (i < end && isSpace(text_[i]))
            ++i;
        if (i >= end || text_[i] != u'=') break;
        ++i;
        while (i < end && isSpace(text_[i]))
            ++i;
        if (i >= end || (text_[i] != u'"' && text_[i] != u'\'')) break;
        const QChar quote = text_[i++];
        raw.emplace_back(name, i);
        while (i < end && text_[i] != quote)
            ++i;
        ++i;
        (void)nameStart;
    }
    for (const QXmlStreamAttribute& a : xml_.attributes()) {
        Attr at;
        at.name = str(a.qualifiedName());
        at.value = str(a.value());
        at.valueOffset = byteOffset(start);
        at.pos = tagPos_;
        for (const auto& [name, q] : raw)
            if (name == a.qualifiedName()) {
                at.valueOffset = byteOffset(q);
                at.pos = lines_.position(at.valueOffset);
                break;
            }
        attrs_.push_back(std::move(at));
    }
}

bool XmlReader::nextChild() {
    while (!xml_.atEnd()) {
        switch (xml_.readNext()) {
        case QXmlStreamReader::StartElement:
            scanTag();
            return true;
        case QXmlStreamReader::EndElement:
            return false;
        case QXmlStreamReader::Invalid:
            malformed();
        default:
            break;
        }
    }
    if (xml_.hasError()) malformed();
    return false;
}

void XmlReader::skipElement() {
    while (nextChild())
        skipElement();
}

void XmlReader::readFile() {
    // The root element.
    while (!xml_.atEnd()) {
        const auto t = xml_.readNext();
        if (t == QXmlStreamReader::Invalid) malformed();
        if (t == QXmlStreamReader::StartElement) break;
    }
    if (xml_.tokenType() != QXmlStreamReader::StartElement)
        b_.fail(here(), "the file has no XML elements");
    scanTag();
    if (xml_.name() != u"X3D")
        b_.fail(tagPos_, "the root element is <" + str(xml_.name()) + ">, not <X3D>");
    Scene& s = b_.scene();
    s.encoding = Encoding::Xml;
    s.version = attrValue("version");
    if (!s.version.empty() && !isKnownX3dVersion(s.version))
        b_.error(tagPos_, "unknown X3D version '" + s.version + "'; expected 3.0 to 4.1",
                 "write version='3.3'");
    if (attrValue("profile").empty())
        b_.error(tagPos_, "<X3D> needs a profile attribute",
                 "write <X3D profile='Immersive' version='3.3'>");
    else
        b_.setProfile(attrValue("profile"), tagPos_);
    bool sawScene = false;
    while (nextChild()) {
        if (xml_.name() == u"head") {
            head();
        } else if (xml_.name() == u"Scene") {
            if (sawScene) b_.fail(tagPos_, "a second <Scene> element");
            sawScene = true;
            while (nextChild())
                statement(&s.roots, nullptr);
        } else if (xml_.name() == u"component" || xml_.name() == u"meta" ||
                   xml_.name() == u"unit") {
            b_.warning(tagPos_, "<" + str(xml_.name()) + "> belongs inside <head>");
            headElement();
        } else {
            b_.fail(tagPos_, "<" + str(xml_.name()) + "> cannot stand directly in <X3D>",
                    "nodes go inside <Scene>");
        }
    }
    if (!sawScene)
        b_.fail(tagPos_, "the file has no <Scene> element", "put the nodes inside <Scene>");
    while (!xml_.atEnd())
        if (xml_.readNext() == QXmlStreamReader::Invalid) malformed();
}

void XmlReader::head() {
    while (nextChild())
        headElement();
}

void XmlReader::headElement() {
    Scene& s = b_.scene();
    {
        if (xml_.name() == u"component") {
            const std::string name = attrValue("name");
            int level = 1;
            try {
                level = std::stoi(attrValue("level").empty() ? "1" : attrValue("level"));
            } catch (...) {
                level = 0;
            }
            b_.addComponent(name, level, attrValue("level"), tagPos_, tagPos_);
        } else if (xml_.name() == u"meta") {
            s.meta.emplace_back(attrValue("name"), attrValue("content"));
        } else if (xml_.name() == u"unit") {
            s.units.push_back("UNIT " + attrValue("category") + " " + attrValue("name") + " " +
                              attrValue("conversionFactor"));
        }
        skipElement();
    }
}

void XmlReader::statement(std::vector<Node*>* roots, Node* parent) {
    const QStringView name = xml_.name();
    if (name == u"ROUTE") return route();
    if (name == u"ProtoDeclare" || name == u"ExternProtoDeclare")
        return protoDeclare(name == u"ExternProtoDeclare");
    if (name == u"IMPORT" || name == u"EXPORT") return importExport(name == u"IMPORT");
    const FilePos pos = tagPos_;
    const std::string explicitContainer = attrValue("containerField");
    Node* n = nodeElement();
    if (!n) return;
    if (roots) {
        if (n->spec && n->spec->family == NodeFamily::Standard &&
            n->spec->containerField != "children" && n->spec->containerField != "metadata" &&
            explicitContainer.empty())
            b_.warning(pos, n->type + " cannot stand at the top of a scene; it belongs in a " +
                                std::string(n->spec->containerField) + " field");
        roots->push_back(n);
    } else if (parent) {
        std::string container = explicitContainer;
        if (container.empty())
            container = n->spec ? std::string(n->spec->containerField) : "children";
        attachChild(*parent, n, container, pos);
    }
}

Node* XmlReader::nodeElement() {
    const bool instance = xml_.name() == u"ProtoInstance";
    const FilePos pos = tagPos_;
    if (xml_.name() == u"NULL") {
        skipElement();
        return nullptr;
    }
    if (const Attr* use = attr("USE")) {
        Node* n = b_.use(use->value, use->pos);
        for (const Attr& a : attrs_)
            if (a.name != "USE" && a.name != "containerField" && a.name != "class" &&
                a.name != "id")
                b_.warning(a.pos, "attribute " + a.name + " is ignored on a USE");
        skipElement();
        return n;
    }
    std::string type = instance ? attrValue("name") : str(xml_.name());
    if (type.empty()) b_.fail(pos, "<ProtoInstance> needs a name attribute");
    Node* n = b_.openNode(type, pos);
    if (const Attr* def = attr("DEF")) b_.define(n, def->value, def->pos);
    for (const Attr& a : attrs_) {
        if (a.name == "DEF" || a.name == "containerField") {
            if (a.name == "containerField") n->containerField = a.value;
            continue;
        }
        if (instance && a.name == "name") continue;
        if (a.name.starts_with("xmlns") || a.name.starts_with("xsd:")) continue;
        setAttributeField(*n, a);
    }
    nodeContent(*n);
    b_.closeNode();
    return n;
}

void XmlReader::setAttributeField(Node& n, const Attr& a) {
    if (!isPortableName(a.name, true)) {
        // xml:lang, a namespace prefix, ...: no field of any node, and no
        // name ClassicVRML could write back.
        b_.warning(a.pos, "attribute " + a.name + " is not an X3D field name; it is ignored");
        return;
    }
    FieldInfo info = b_.fieldInfo(n, a.name);
    Field field;
    field.name = a.name;
    field.where = a.pos;
    field.file = b_.file();
    if (!info.known) {
        const bool htmlAttribute = a.name == "class" || a.name == "id" || a.name == "style";
        if (!htmlAttribute) b_.reportUnknownField(n, a.name, a.pos);
        parseValue(a, FieldType::Unknown, field.value);
    } else if (b_.reportUnassignable(n, info, a.name, a.pos)) {
        return;
    } else if (!parseValue(a, info.type, field.value)) {
        return;
    }
    if (Field* old = n.field(a.name))
        *old = std::move(field);
    else
        n.fields.push_back(std::move(field));
}

void XmlReader::nodeContent(Node& n) {
    while (!xml_.atEnd()) {
        const auto t = xml_.readNext();
        if (t == QXmlStreamReader::Invalid) malformed();
        if (t == QXmlStreamReader::EndElement) return;
        if (t == QXmlStreamReader::Characters && !xml_.isWhitespace() && n.sourceInText()) {
            // Script source in CDATA: the same as a url entry holding it.
            Field* url = n.field("url");
            if (!url) {
                n.fields.push_back({"url", {}, here(), b_.file(), {}});
                url = &n.fields.back();
                url->value.type = FieldType::MFString;
            }
            url->value.strings.emplace_back(str(xml_.text()));
            url->value.stringOrigins.push_back(
                {b_.file(), byteOffset(xml_.characterOffset() - xml_.text().size()),
                 StringEscapes::XmlText});
            continue;
        }
        if (t != QXmlStreamReader::StartElement) continue;
        scanTag();
        const QStringView name = xml_.name();
        if (name == u"IS") {
            isElement(n);
        } else if (name == u"field") {
            if (!n.declaresFields()) {
                b_.warning(tagPos_, "<field> declarations belong in Script and shader nodes "
                                    "(ComposedShader, PackagedShader, ShaderProgram)");
                skipElement();
            } else if (const std::string type = attrValue("type"); !parseFieldType(type)) {
                // A type of another browser's (X_ITE's SFQuaternion): the
                // node stays usable without that one field.
                b_.warning(tagPos_, "<field name='" + attrValue("name") + "'> has type '" + type +
                                        "', which X3D does not define; the field is left out");
                skipElement();
            } else {
                FieldDeclaration d = fieldElement(false, false);
                // An attribute of the same name (a field of a later X3D
                // version, kept as unknown) would make the node say two
                // things; the declared field is the one the Script sees.
                const auto clash =
                    std::find_if(n.fields.begin(), n.fields.end(), [&](const Field& f) {
                        return f.name == d.name && f.value.type == FieldType::Unknown;
                    });
                if (clash != n.fields.end()) {
                    b_.warning(clash->where, "attribute '" + d.name +
                                                 "' has the name of a <field> "
                                                 "this node declares; the <field> is used");
                    n.fields.erase(clash);
                }
                n.declarations.push_back(std::move(d));
            }
        } else if (name == u"fieldValue") {
            fieldValueElement(n);
        } else {
            statement(nullptr, &n);
        }
    }
}

void XmlReader::attachChild(Node& parent, Node* child, const std::string& containerField,
                            FilePos pos) {
    FieldInfo info = b_.fieldInfo(parent, containerField);
    if (!info.known && !parent.isUnknown()) {
        b_.warning(pos,
                   parent.type + " has no field '" + containerField + "' to hold " + child->type +
                       "; it is kept but ignored",
                   "set containerField to one of " + parent.type + "'s node fields");
    } else if (info.known && !holdsNodes(info.type)) {
        b_.error(pos, "field '" + containerField + "' of " + parent.type + " holds " +
                          std::string(fieldTypeName(info.type)) + ", not nodes");
        return;
    }
    Field* f = parent.field(containerField);
    if (!f) {
        parent.fields.push_back({containerField, {}, pos, b_.file(), {}});
        f = &parent.fields.back();
        f->value.type = info.known ? info.type : FieldType::Unknown;
    }
    if (f->value.type == FieldType::SFNode && !f->value.nodes.empty()) {
        b_.warning(pos, parent.type + "." + containerField + " holds one node; " + child->type +
                            " replaces the one before it");
        f->value.nodes.clear();
    }
    f->value.nodes.push_back(child);
}

FieldDeclaration XmlReader::fieldElement(bool external, bool inProtoInterface) {
    FieldDeclaration d;
    d.where = tagPos_;
    d.name = attrValue("name");
    if (!d.name.empty()) b_.checkName(d.name, NameKind::Field, tagPos_);
    const std::string typeName = attrValue("type");
    const std::string accessName = attrValue("accessType");
    if (d.name.empty()) b_.fail(tagPos_, "<field> needs a name attribute");
    std::optional<FieldType> type = parseFieldType(typeName);
    if (!type)
        b_.fail(tagPos_, "<field name='" + d.name + "'> has unknown type '" + typeName + "'");
    std::optional<AccessType> access = parseAccessType(accessName);
    if (!access)
        b_.fail(tagPos_,
                "<field name='" + d.name + "'> has unknown accessType '" + accessName + "'",
                "use initializeOnly, inputOnly, outputOnly or inputOutput");
    d.type = *type;
    d.access = *access;
    d.value.type = *type;
    if (const Attr* v = attr("value")) {
        if (!hasInitialValue(d.access))
            b_.error(v->pos, "field '" + d.name + "' is " + std::string(accessTypeName(d.access)) +
                                 " and takes no value");
        else if (external)
            b_.warning(v->pos, "values in an ExternProtoDeclare are ignored");
        else if (parseValue(*v, d.type, d.value))
            d.hasValue = true;
    }
    // Node values as child elements.
    if (inProtoInterface) b_.pushScope(nullptr);
    while (nextChild()) {
        if (xml_.name() == u"IS" || xml_.name() == u"appinfo" || xml_.name() == u"documentation") {
            skipElement();
            continue;
        }
        const FilePos pos = tagPos_;
        Node* n = nodeElement();
        if (!n) continue;
        if (!holdsNodes(d.type)) {
            b_.error(pos, "field '" + d.name + "' is " + std::string(fieldTypeName(d.type)) +
                              " and cannot hold " + n->type);
            continue;
        }
        d.value.nodes.push_back(n);
        d.hasValue = true;
    }
    if (inProtoInterface) b_.popScope();
    if (hasInitialValue(d.access) && !external && !d.hasValue && d.isReferences.empty()) {
        d.value = typeDefault(d.type); // no value attribute: the type's default
        d.hasValue = true;
        d.valueIsDefault = true; // until an <IS> connects it (then it has no value)
    }
    return d;
}

namespace {

// One more IS connection of a field (X3D allows several), each once.
void addIs(std::vector<std::string>& references, const std::string& protoField) {
    if (std::find(references.begin(), references.end(), protoField) == references.end())
        references.push_back(protoField);
}

} // namespace

void XmlReader::isElement(Node& n) {
    while (nextChild()) {
        if (xml_.name() != u"connect") {
            b_.warning(tagPos_, "<IS> holds only <connect> elements");
            skipElement();
            continue;
        }
        const std::string nodeField = attrValue("nodeField");
        const std::string protoField = attrValue("protoField");
        const FilePos pos = tagPos_;
        skipElement();
        for (FieldDeclaration& d : n.declarations)
            if (d.name == nodeField) {
                FieldInfo info{d.type, d.access, true, false, d.name};
                b_.checkIs(n, info, nodeField, protoField, pos);
                addIs(d.isReferences, protoField);
                if (d.valueIsDefault) { // the value comes through IS, as in ClassicVRML
                    d.value = FieldValue{d.type, {}, {}, {}, {}};
                    d.hasValue = d.valueIsDefault = false;
                }
                goto next;
            }
        {
            FieldInfo info = b_.fieldInfo(n, nodeField);
            if (!info.known && !n.isUnknown())
                b_.error(pos, n.type + " has no field '" + nodeField + "' to connect",
                         b_.suggestField(n, nodeField));
            b_.checkIs(n, info, nodeField, protoField, pos);
            Field* f = n.field(nodeField);
            if (!f) {
                n.fields.push_back({nodeField, {}, pos, b_.file(), {}});
                f = &n.fields.back();
                f->value.type = info.type;
            }
            addIs(f->isReferences, protoField); // several <connect>s: several IS
        }
    next:;
    }
}

void XmlReader::fieldValueElement(Node& instance) {
    const std::string name = attrValue("name");
    const FilePos pos = tagPos_;
    b_.checkName(name, NameKind::Field, pos);
    FieldInfo info = b_.fieldInfo(instance, name);
    Field field;
    field.name = name;
    field.where = pos;
    field.file = b_.file();
    field.value.type = info.type;
    if (!info.known) {
        b_.reportUnknownField(instance, name, pos);
        field.value.type = FieldType::Unknown;
    }
    if (const Attr* v = attr("value"))
        parseValue(*v, info.known ? info.type : FieldType::Unknown, field.value);
    while (nextChild()) {
        Node* n = nodeElement();
        if (n) field.value.nodes.push_back(n);
    }
    if (Field* old = instance.field(name)) {
        field.isReferences = old->isReferences; // an <IS> may come first
        *old = std::move(field);
    } else
        instance.fields.push_back(std::move(field));
}

void XmlReader::protoDeclare(bool external) {
    b_.checkName(attrValue("name"), NameKind::Proto, tagPos_);
    ProtoDeclaration* p = b_.scene().newProto();
    p->name = attrValue("name");
    p->external = external;
    p->where = tagPos_;
    p->file = b_.file();
    if (p->name.empty())
        b_.fail(tagPos_, std::string(external ? "<ExternProtoDeclare>" : "<ProtoDeclare>") +
                             " needs a name attribute");
    if (external) {
        if (const Attr* url = attr("url")) {
            FieldValue v;
            if (parseValue(*url, FieldType::MFString, v)) p->urls = v.strings;
        }
    }
    b_.declareProto(p, p->where);
    if (ProtoDeclaration* outer = b_.currentProto())
        outer->protos.push_back(p);
    else
        b_.scene().protos.push_back(p);
    bool sawBody = false;
    auto readInterfaceField = [&] {
        FieldDeclaration d = fieldElement(external, true);
        b_.checkInterfaceField(*p, d, d.where);
        p->interface.push_back(std::move(d));
    };
    while (nextChild()) {
        if (xml_.name() == u"ProtoInterface") {
            while (nextChild()) {
                if (xml_.name() == u"field")
                    readInterfaceField();
                else
                    skipElement();
            }
        } else if (xml_.name() == u"field" && external) {
            readInterfaceField();
        } else if (xml_.name() == u"ProtoBody" && !external) {
            sawBody = true;
            b_.pushScope(p);
            while (nextChild())
                statement(&p->body, nullptr);
            b_.popScope();
        } else {
            skipElement();
        }
    }
    if (!external && (!sawBody || p->body.empty()))
        b_.warning(p->where, "ProtoDeclare " + p->name +
                                 " has no nodes in its <ProtoBody>; its instances show nothing");
}

void XmlReader::route() {
    const FilePos pos = tagPos_;
    std::string from = attrValue("fromNode"), fromField = attrValue("fromField"),
                to = attrValue("toNode"), toField = attrValue("toField");
    skipElement();
    if (from.empty() || fromField.empty() || to.empty() || toField.empty()) {
        b_.error(pos, "<ROUTE> needs fromNode, fromField, toNode and toField");
        return;
    }
    b_.addRoute(from, fromField, to, toField, pos);
}

void XmlReader::importExport(bool isImport) {
    const FilePos pos = tagPos_;
    std::string text;
    if (isImport)
        text = "IMPORT " + attrValue("inlineDEF") + "." + attrValue("importedDEF") +
               (attrValue("exportedDEF").empty() ? "" : attrValue("exportedDEF"));
    else
        text = "EXPORT " + attrValue("localDEF");
    if (!attrValue("AS").empty()) text += " AS " + attrValue("AS");
    skipElement();
    if (!isImport && b_.currentProto()) b_.error(pos, "EXPORT is not allowed inside a PROTO body");
    if (isImport)
        b_.declareImport(attrValue("AS").empty() ? attrValue("importedDEF") : attrValue("AS"), pos);
    if (isImport && b_.currentProto())
        b_.currentProto()->imports.push_back({text, pos});
    else
        (isImport ? b_.scene().imports : b_.scene().exports).push_back({text, pos});
}

} // namespace

bool looksLikeXml(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size() &&
           (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r'))
        ++i;
    return text.substr(i).starts_with("<");
}

void readXml(SceneBuilder& builder) {
    XmlReader reader(builder);
    reader.readFile();
}

} // namespace fl::scene
