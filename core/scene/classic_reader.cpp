#include "classic_reader.h"

#include "components.h"
#include <algorithm>

#include "classic_lexer.h"
#include "number_text.h"
#include "utf8.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace fl::scene {
namespace {

using T = ClassicToken;

bool isAccessKeyword(std::string_view s) {
    return parseAccessType(s).has_value();
}

std::string describe(const ClassicTokenInfo& t) {
    switch (t.kind) {
    case T::End:
        return "the end of the file";
    case T::String:
        return "a string";
    case T::Invalid:
        return "'" + std::string(t.text.substr(0, 20)) + "'";
    default:
        return "'" + std::string(t.text.substr(0, 40)) + "'";
    }
}

class ClassicReader {
  public:
    ClassicReader(SceneBuilder& b, std::size_t start, FilePos startPos)
        : b_(b), text_(b.scene().files[b.file()].text),
          lex_(text_, start, startPos, b.scene().encoding != Encoding::Vrml97) {}

    void readFile();

  private:
    // --- tokens
    const ClassicTokenInfo& peek() const { return lex_.peek(); }
    ClassicTokenInfo next() {
        ClassicTokenInfo t = lex_.next();
        if (t.kind == T::Invalid)
            b_.fail(t.pos, t.text.starts_with("\"") ? "this string is never closed"
                                                    : "unexpected character " + describe(t));
        return t;
    }
    bool peekWord(std::string_view w) const {
        return peek().kind == T::Identifier && peek().text == w;
    }
    ClassicTokenInfo expect(T kind, std::string_view what) {
        if (peek().kind != kind)
            b_.fail(peek().pos, "expected " + std::string(what) + ", found " + describe(peek()));
        return next();
    }
    std::string name(std::string_view what) {
        return std::string(expect(T::Identifier, what).text);
    }

    // --- statements
    void headerStatements();
    void statement(std::vector<Node*>& roots, bool topLevel);
    Node* nodeStatement(FilePos at);
    Node* node(std::string_view defName, FilePos defPos);
    void nodeBody(Node& n);
    void fieldDeclaration(Node& n);
    void proto(bool external);
    void interface(ProtoDeclaration& p, bool external);
    void route();
    void importExport(bool isImport);

    // --- values
    FieldValue value(FieldType type, const ClassicTokenInfo& at);
    void elements(FieldValue& v, FieldType single, std::size_t maxElements);
    void element(FieldValue& v, FieldType single);
    double number(FieldType single);
    FieldValue unknownValue();
    void unknownItem(FieldValue& v);

    SceneBuilder& b_;
    std::string_view text_;
    ClassicLexer lex_;
    bool sawNonHeader_ = false;
};

void ClassicReader::readFile() {
    if (b_.scene().encoding != Encoding::Vrml97) headerStatements();
    while (peek().kind != T::End)
        statement(b_.scene().roots, true);
}

void ClassicReader::headerStatements() {
    Scene& s = b_.scene();
    if (!peekWord("PROFILE")) {
        b_.error(peek().pos, "an X3D file needs a PROFILE statement after its header line",
                 "add 'PROFILE Immersive' (or Interchange, Interactive, Full) on the second line");
    } else {
        next();
        ClassicTokenInfo p = expect(T::Identifier, "a profile name");
        b_.setProfile(std::string(p.text), p.pos);
    }
    while (peekWord("COMPONENT")) {
        next();
        ClassicTokenInfo c = expect(T::Identifier, "a component name");
        if (peek().kind != T::Colon) {
            b_.warning(c.pos,
                       "COMPONENT " + std::string(c.text) + " has no level; level 1 is assumed",
                       "write COMPONENT " + std::string(c.text) + ":1");
            s.components.push_back({std::string(c.text), 1});
            continue;
        }
        next();
        ClassicTokenInfo l = expect(T::Number, "a component level");
        int level = 0;
        std::from_chars(l.text.data(), l.text.data() + l.text.size(), level);
        b_.addComponent(std::string(c.text), level, l.text, c.pos, l.pos);
    }
    while (peekWord("UNIT")) {
        ClassicTokenInfo u = next();
        std::string text = "UNIT";
        for (int i = 0; i < 3; ++i) {
            text += ' '; // appended piecewise: GCC 12 warns (-Wrestrict) on " " + string
            text += expect(i == 2 ? T::Number : T::Identifier, "a UNIT part").text;
        }
        (void)u;
        s.units.push_back(text);
    }
    while (peekWord("META")) {
        next();
        std::string key = ClassicLexer::unquote(expect(T::String, "a META name").text);
        std::string val = ClassicLexer::unquote(expect(T::String, "a META value").text);
        s.meta.emplace_back(std::move(key), std::move(val));
    }
}

void ClassicReader::statement(std::vector<Node*>& roots, bool topLevel) {
    const ClassicTokenInfo& t = peek();
    if (t.kind != T::Identifier)
        b_.fail(t.pos, "expected a node, PROTO or ROUTE, found " + describe(t));
    if (t.text == "PROTO" || t.text == "EXTERNPROTO") {
        proto(next().text == "EXTERNPROTO");
        return;
    }
    if (t.text == "ROUTE") {
        route();
        return;
    }
    if (t.text == "IMPORT" || t.text == "EXPORT") {
        importExport(next().text == "IMPORT");
        return;
    }
    if (t.text == "PROFILE" || t.text == "COMPONENT" || t.text == "META" || t.text == "UNIT")
        b_.fail(t.pos, std::string(t.text) + " must come before the first node",
                "move it up, right after PROFILE");
    const FilePos at = t.pos;
    Node* n = nodeStatement(at);
    if (n && topLevel && n->spec && n->spec->containerField != "children" &&
        n->spec->family == NodeFamily::Standard) {
        const std::string msg = n->type + " cannot stand at the top of a scene; it belongs in a " +
                                std::string(n->spec->containerField) + " field";
        if (b_.vrml97())
            b_.error(at, msg);
        else
            b_.warning(at, msg);
    }
    if (n) roots.push_back(n);
}

Node* ClassicReader::nodeStatement(FilePos at) {
    if (peekWord("USE")) {
        next();
        ClassicTokenInfo id = expect(T::Identifier, "a DEF name after USE");
        return b_.use(id.text, id.pos);
    }
    if (peekWord("DEF")) {
        next();
        ClassicTokenInfo id = expect(T::Identifier, "a name after DEF");
        return node(id.text, id.pos);
    }
    (void)at;
    return node({}, {});
}

Node* ClassicReader::node(std::string_view defName, FilePos defPos) {
    ClassicTokenInfo type = expect(T::Identifier, "a node type");
    if (type.text == "NULL" || type.text == "USE" || type.text == "DEF" || type.text == "PROTO" ||
        type.text == "ROUTE")
        b_.fail(type.pos, "expected a node type, found '" + std::string(type.text) + "'");
    Node* n = b_.openNode(type.text, type.pos);
    if (!defName.empty()) b_.define(n, defName, defPos); // before the body: its ROUTEs may name it
    expect(T::LeftBrace, "'{' after " + n->type);
    nodeBody(*n);
    expect(T::RightBrace, "'}' to close " + n->type);
    b_.closeNode();
    return n;
}

void ClassicReader::nodeBody(Node& n) {
    while (peek().kind == T::Identifier) {
        const ClassicTokenInfo t = peek();
        if (t.text == "ROUTE") {
            route();
            continue;
        }
        if (t.text == "PROTO" || t.text == "EXTERNPROTO") {
            proto(next().text == "EXTERNPROTO");
            continue;
        }
        if (n.declaresFields() && isAccessKeyword(t.text)) {
            fieldDeclaration(n);
            continue;
        }
        next();
        const std::string fieldName(t.text);
        b_.checkName(fieldName, NameKind::Field, t.pos);
        FieldInfo info = b_.fieldInfo(n, fieldName);
        Field field;
        field.name = fieldName;
        field.where = t.pos;
        field.file = b_.file();
        if (peekWord("IS")) {
            next();
            ClassicTokenInfo iface = expect(T::Identifier, "an interface field name after IS");
            b_.checkIs(n, info, fieldName, iface.text, iface.pos);
            field.isReferences.emplace_back(iface.text);
            field.value.type = info.type;
            // `x IS b` after the declaration `inputOnly SFTime x IS a`: one
            // more connection of the declared field (as XML's <connect>).
            const auto declared =
                std::find_if(n.declarations.begin(), n.declarations.end(),
                             [&](const FieldDeclaration& d) { return d.name == fieldName; });
            if (declared != n.declarations.end()) {
                if (std::find(declared->isReferences.begin(), declared->isReferences.end(),
                              field.isReferences.front()) == declared->isReferences.end())
                    declared->isReferences.push_back(field.isReferences.front());
                continue;
            }
        } else if (!info.known) {
            b_.reportUnknownField(n, fieldName, t.pos);
            field.value = unknownValue();
        } else if (b_.reportUnassignable(n, info, fieldName, t.pos)) {
            throw StopReading{}; // its value cannot be read without a type to read it as
        } else {
            field.value = value(info.type, t);
        }
        if (Field* old = n.field(fieldName)) {
            // X3D 4 lets an inputOutput field have both an IS and a value,
            // and any field several IS connections: all are kept.
            const bool oldHasValue = !old->value.numbers.empty() || !old->value.strings.empty() ||
                                     !old->value.nodes.empty() || old->isReferences.empty();
            if (!field.isReferences.empty()) {
                for (std::string& is : field.isReferences)
                    if (std::find(old->isReferences.begin(), old->isReferences.end(), is) ==
                        old->isReferences.end())
                        old->isReferences.push_back(std::move(is));
            } else {
                if (oldHasValue)
                    b_.warning(t.pos,
                               "field '" + fieldName + "' is given twice; the later value is used");
                old->value = std::move(field.value);
                old->where = field.where;
            }
        } else {
            n.fields.push_back(std::move(field));
        }
    }
}

void ClassicReader::fieldDeclaration(Node& n) {
    ClassicTokenInfo accessTok = next();
    AccessType access = *parseAccessType(accessTok.text);
    if (access == AccessType::InputOutput && b_.vrml97() && n.kind() == scene::NodeKind::Script)
        b_.error(accessTok.pos, "a VRML97 Script cannot declare an exposedField",
                 "use a field with an eventIn and an eventOut");
    ClassicTokenInfo typeTok = expect(T::Identifier, "a field type");
    std::optional<FieldType> type = parseFieldType(typeTok.text);
    if (!type) b_.fail(typeTok.pos, "unknown field type '" + std::string(typeTok.text) + "'");
    ClassicTokenInfo nameTok = expect(T::Identifier, "a field name");
    b_.checkName(nameTok.text, NameKind::Field, nameTok.pos);
    FieldDeclaration d;
    d.name = std::string(nameTok.text);
    d.type = *type;
    d.access = access;
    d.where = nameTok.pos;
    d.value.type = *type;
    if (peekWord("IS")) {
        next();
        ClassicTokenInfo iface = expect(T::Identifier, "an interface field name after IS");
        FieldInfo info{*type, access, true, false, d.name};
        b_.checkIs(n, info, d.name, iface.text, iface.pos);
        d.isReferences.emplace_back(iface.text);
    } else if (hasInitialValue(access)) {
        d.value = value(*type, nameTok);
        d.hasValue = true;
    }
    for (FieldDeclaration& other : n.declarations)
        if (other.name == d.name) {
            // an IS and an initial value for the same field (X3D 4)
            if (other.type == d.type && other.access == d.access &&
                (!d.isReferences.empty() || !other.hasValue)) {
                if (d.isReferences.empty()) {
                    other.value = std::move(d.value);
                    other.hasValue = d.hasValue;
                } else {
                    for (std::string& is : d.isReferences)
                        if (std::find(other.isReferences.begin(), other.isReferences.end(), is) ==
                            other.isReferences.end())
                            other.isReferences.push_back(std::move(is));
                }
                return;
            }
            b_.error(nameTok.pos, "field '" + d.name + "' is declared twice");
        }
    n.declarations.push_back(std::move(d));
}

void ClassicReader::proto(bool external) {
    ClassicTokenInfo nameTok = expect(T::Identifier, "a PROTO name");
    b_.checkName(nameTok.text, NameKind::Proto, nameTok.pos);
    ProtoDeclaration* p = b_.scene().newProto();
    p->name = std::string(nameTok.text);
    p->external = external;
    p->where = nameTok.pos;
    p->file = b_.file();
    if (findNodeSpec(p->name))
        b_.warning(nameTok.pos, "PROTO " + p->name + " hides the built-in node of that name");
    expect(T::LeftBracket, "'[' to open the interface of " + p->name);
    interface(*p, external);
    expect(T::RightBracket, "']' to close the interface of " + p->name);
    b_.declareProto(p, nameTok.pos);
    if (ProtoDeclaration* outer = b_.currentProto())
        outer->protos.push_back(p);
    else
        b_.scene().protos.push_back(p);
    if (external) {
        FieldValue urls = value(FieldType::MFString, nameTok);
        p->urls = urls.strings;
        return;
    }
    expect(T::LeftBrace, "'{' to open the body of PROTO " + p->name);
    b_.pushScope(p);
    while (peek().kind == T::Identifier)
        statement(p->body, false);
    expect(T::RightBrace, "'}' to close the body of PROTO " + p->name);
    b_.popScope();
    if (p->body.empty()) {
        if (b_.vrml97())
            b_.error(nameTok.pos, "PROTO " + p->name + " has an empty body",
                     "a PROTO body needs at least one node");
        else
            b_.warning(nameTok.pos,
                       "PROTO " + p->name + " has an empty body; its instances show nothing");
    }
}

void ClassicReader::interface(ProtoDeclaration& p, bool external) {
    while (peek().kind == T::Identifier) {
        ClassicTokenInfo accessTok = next();
        std::optional<AccessType> access = parseAccessType(accessTok.text);
        if (!access)
            b_.fail(accessTok.pos,
                    "expected field, eventIn, eventOut or exposedField (or initializeOnly, "
                    "inputOnly, outputOnly, inputOutput), found " +
                        describe(accessTok));
        ClassicTokenInfo typeTok = expect(T::Identifier, "a field type");
        std::optional<FieldType> type = parseFieldType(typeTok.text);
        if (!type) b_.fail(typeTok.pos, "unknown field type '" + std::string(typeTok.text) + "'");
        ClassicTokenInfo nameTok = expect(T::Identifier, "a field name");
        b_.checkName(nameTok.text, NameKind::Field, nameTok.pos);
        FieldDeclaration d;
        d.name = std::string(nameTok.text);
        d.type = *type;
        d.access = *access;
        d.where = nameTok.pos;
        d.value.type = *type;
        b_.checkInterfaceField(p, d, nameTok.pos);
        if (!external && hasInitialValue(*access)) {
            b_.pushScope(nullptr); // a default value is a scope of its own
            d.value = value(*type, nameTok);
            b_.popScope();
            d.hasValue = true;
        }
        p.interface.push_back(std::move(d));
    }
}

void ClassicReader::route() {
    ClassicTokenInfo kw = next();
    std::string fromNode = name("a node name after ROUTE");
    expect(T::Period, "'.' between node and field");
    std::string fromField = name("a field name");
    if (!peekWord("TO")) b_.fail(peek().pos, "expected TO in the ROUTE, found " + describe(peek()));
    next();
    std::string toNode = name("a node name after TO");
    expect(T::Period, "'.' between node and field");
    std::string toField = name("a field name");
    b_.addRoute(fromNode, fromField, toNode, toField, kw.pos);
}

void ClassicReader::importExport(bool isImport) {
    const FilePos at = peek().pos; // after the keyword
    if (b_.vrml97())
        b_.error(at, std::string(isImport ? "IMPORT" : "EXPORT") + " is X3D only, not VRML97");
    if (!isImport && b_.currentProto()) b_.error(at, "EXPORT is not allowed inside a PROTO body");
    std::string text = isImport ? "IMPORT " : "EXPORT ";
    text += name("a node name");
    if (isImport) {
        expect(T::Period, "'.' after the Inline's name");
        text += "." + name("an exported name");
    }
    std::string localName = text.substr(text.find_last_of(". ") + 1);
    if (peekWord("AS")) {
        next();
        localName = name("a name after AS");
        text += " AS " + localName;
    }
    if (isImport) b_.declareImport(localName, at);
    if (isImport && b_.currentProto())
        b_.currentProto()->imports.push_back({text, at});
    else
        (isImport ? b_.scene().imports : b_.scene().exports).push_back({text, at});
}

// ---------------------------------------------------------------- values

double ClassicReader::number(FieldType single) {
    ClassicTokenInfo t = peek();
    if (t.kind != T::Number) {
        if (t.kind == T::Identifier && (t.text == "TRUE" || t.text == "FALSE") &&
            single == FieldType::SFBool) {
            next();
            return t.text == "TRUE" ? 1.0 : 0.0;
        }
        b_.fail(t.pos, "expected " +
                           std::string(single == FieldType::SFBool ? "TRUE or FALSE" : "a number") +
                           " for " + std::string(fieldTypeName(single)) + ", found " + describe(t));
    }
    next();
    if (single == FieldType::SFBool) b_.fail(t.pos, "expected TRUE or FALSE, found " + describe(t));
    double v = 0;
    std::string problem;
    if (!parseNumberText(t.text, single, v, problem))
        b_.fail(t.pos, problem + " (" + std::string(fieldTypeName(single)) + ")");
    return v;
}

void ClassicReader::element(FieldValue& v, FieldType single) {
    switch (single) {
    case FieldType::SFString: {
        ClassicTokenInfo t = peek();
        if (t.kind != T::String)
            b_.fail(t.pos, "expected a string in double quotes, found " + describe(t));
        next();
        std::string text = ClassicLexer::unquote(t.text);
        if (!isValidUtf8(text)) {
            b_.warning(t.pos,
                       "this string is not UTF-8 (was the file saved as Shift-JIS or Latin-1?); "
                       "its invalid bytes read as \xEF\xBF\xBD",
                       "save the file as UTF-8");
            text = replaceInvalidUtf8(text);
        }
        v.strings.push_back(std::move(text));
        v.stringOrigins.push_back({b_.file(), t.offset + 1, StringEscapes::Classic});
        return;
    }
    case FieldType::SFNode: {
        if (peekWord("NULL")) {
            next();
            return;
        }
        if (peek().kind == T::LeftBracket)
            b_.fail(peek().pos,
                    "expected a node, USE or NULL, found '[': this field holds one node",
                    "write the node without brackets; numbers go inside a node, e.g. "
                    "Coordinate { point [ ... ] } (NURBS files from before X3D 3.0 gave "
                    "control points directly)");
        if (peek().kind != T::Identifier)
            b_.fail(peek().pos, "expected a node, USE or NULL, found " + describe(peek()));
        v.nodes.push_back(nodeStatement(peek().pos));
        return;
    }
    case FieldType::SFImage: {
        const double w = number(FieldType::SFImage), h = number(FieldType::SFImage),
                     c = number(FieldType::SFImage);
        v.numbers.insert(v.numbers.end(), {w, h, c});
        if (w < 0 || h < 0 || c < 0 || c > 4)
            b_.fail(peek().pos, "an SFImage needs width, height and 0 to 4 components");
        const double pixels = w * h;
        for (double i = 0; i < pixels; ++i) {
            if (peek().kind != T::Number)
                b_.fail(peek().pos, "the image declares " +
                                        std::to_string(static_cast<long long>(pixels)) +
                                        " pixels but has fewer");
            v.numbers.push_back(number(FieldType::SFImage));
        }
        return;
    }
    default: {
        const int k = componentsPerElement(single);
        for (int i = 0; i < k; ++i)
            v.numbers.push_back(number(single));
        return;
    }
    }
}

void ClassicReader::elements(FieldValue& v, FieldType single, std::size_t) {
    while (peek().kind != T::RightBracket) {
        if (peek().kind == T::End) b_.fail(peek().pos, "this list is never closed with ']'");
        element(v, single);
    }
}

FieldValue ClassicReader::value(FieldType type, const ClassicTokenInfo& at) {
    FieldValue v;
    v.type = type;
    (void)at;
    if (type == FieldType::Unknown) return unknownValue();
    if (!isMultiple(type)) {
        element(v, type);
        return v;
    }
    const FieldType single = singleOf(type);
    if (peek().kind == T::LeftBracket) {
        next();
        elements(v, single, 0);
        next();
        return v;
    }
    // Without brackets the grammar allows one element; files in the wild list
    // several numbers or strings, which is unambiguous (a field name is never
    // a number or a string), so we read them all.
    element(v, single);
    if (single != FieldType::SFNode) {
        const T kind = single == FieldType::SFString ? T::String
                       : single == FieldType::SFBool ? T::Identifier
                                                     : T::Number;
        while (peek().kind == kind &&
               (kind != T::Identifier || peek().text == "TRUE" || peek().text == "FALSE"))
            element(v, single);
    }
    return v;
}

void ClassicReader::unknownItem(FieldValue& v) {
    const ClassicTokenInfo t = peek();
    switch (t.kind) {
    case T::Number:
        while (peek().kind == T::Number)
            next();
        return;
    case T::String: // several strings without brackets: one MFString-like value
        while (peek().kind == T::String)
            next();
        return;
    case T::Identifier:
        if (t.text == "TRUE" || t.text == "FALSE" || t.text == "NULL") {
            next();
            return;
        }
        if (t.text == "USE" || t.text == "DEF" || lex_.peekSecond().kind == T::LeftBrace) {
            v.nodes.push_back(nodeStatement(t.pos));
            return;
        }
        [[fallthrough]];
    default:
        b_.fail(t.pos, "cannot read a value starting with " + describe(t));
    }
}

FieldValue ClassicReader::unknownValue() {
    FieldValue v;
    v.type = FieldType::Unknown;
    const std::size_t begin = peek().offset;
    std::size_t end = begin;
    if (peek().kind == T::LeftBracket) {
        next();
        while (peek().kind != T::RightBracket) {
            if (peek().kind == T::End) b_.fail(peek().pos, "this list is never closed with ']'");
            unknownItem(v);
        }
        end = peek().offset + 1;
        next();
    } else {
        unknownItem(v);
        end = peek().offset; // up to the next token; trailing space trimmed below
    }
    std::string_view raw = text_.substr(begin, end - begin);
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\n' || raw.back() == '\r' ||
                            raw.back() == '\t' || raw.back() == ','))
        raw.remove_suffix(1);
    // Comments between the value and the next token are not part of it.
    if (std::size_t hash = raw.find('#'); hash != std::string_view::npos && v.nodes.empty() &&
                                          raw.find('"') == std::string_view::npos)
        raw = raw.substr(0, hash);
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\n' || raw.back() == '\r' ||
                            raw.back() == '\t' || raw.back() == ','))
        raw.remove_suffix(1);
    // Kept as text, repaired as strings are: every writer must write it back.
    v.strings.emplace_back(replaceInvalidUtf8(raw));
    return v;
}

// ---------------------------------------------------------------- header

struct Header {
    Encoding encoding = Encoding::ClassicVrml;
    std::string version;
    std::size_t bodyOffset = 0;
};

std::optional<Header> parseHeader(std::string_view text, std::string& problem) {
    std::size_t eol = text.find_first_of("\r\n");
    std::string_view line = text.substr(0, eol);
    Header h;
    h.bodyOffset = eol == std::string_view::npos ? text.size() : eol;
    auto word = [&](std::string_view& s) {
        std::size_t i = 0;
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t'))
            ++i;
        s.remove_prefix(i);
        std::size_t j = 0;
        while (j < s.size() && s[j] != ' ' && s[j] != '\t')
            ++j;
        std::string_view w = s.substr(0, j);
        s.remove_prefix(j);
        return w;
    };
    std::string_view rest = line;
    std::string_view first = word(rest);
    std::string_view version = word(rest);
    std::string_view charset = word(rest);
    if (first == "#VRML" && version == "V1.0") {
        problem = "VRML 1.0 files are not supported; convert the file to VRML97 or X3D";
        return std::nullopt;
    }
    if (first == "#VRML" && version == "V2.0" && charset == "utf8") {
        h.encoding = Encoding::Vrml97;
        h.version = "2.0";
        return h;
    }
    if (first == "#X3D" && version.size() >= 4 && version[0] == 'V' && charset == "utf8") {
        h.encoding = Encoding::ClassicVrml;
        h.version = std::string(version.substr(1));
        if (!isKnownX3dVersion(h.version)) {
            problem = "unknown X3D version '" + h.version + "'; expected 3.0 to 4.1";
            return std::nullopt;
        }
        return h;
    }
    problem = "the first line must be exactly '#VRML V2.0 utf8' (VRML97) or '#X3D V3.3 utf8' "
              "(ClassicVRML)";
    return std::nullopt;
}

} // namespace

bool looksLikeClassic(std::string_view text) {
    return text.starts_with("#"); // the header check explains what is wrong with it
}

void readClassic(SceneBuilder& builder) {
    Scene& scene = builder.scene();
    const std::string& text = scene.files[builder.file()].text;
    std::string problem;
    std::optional<Header> header = parseHeader(text, problem);
    if (!header) builder.fail({1, 1}, problem);
    scene.encoding = header->encoding;
    scene.version = header->version;
    ClassicReader reader(builder, header->bodyOffset,
                         {1, static_cast<int>(header->bodyOffset) + 1});
    reader.readFile();
}

} // namespace fl::scene
