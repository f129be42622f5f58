#include "chat_commands.h"

#include "formula/lexer.h"
#include "formula/parser.h"
#include "member_name.h"
#include "scene/field_access.h"
#include "scene/node_catalogue.h"
#include "scene/scene_edit.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "scene/source_map.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <utility>

namespace fl::classroom {

namespace {

constexpr std::string_view kClassShapeName = "CLASS";

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

// The first word of `s` (removed from it).
std::string_view takeWord(std::string_view& s) {
    s = trim(s);
    std::size_t end = 0;
    while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])))
        ++end;
    const std::string_view word = s.substr(0, end);
    s = trim(s.substr(end));
    return word;
}

bool parseUnit(std::string_view text, double& out) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc{} && end == text.data() + text.size() && out >= 0 && out <= 1;
}

constexpr std::array kColourNames{
    std::pair{"red", Colour{1, 0, 0}},        std::pair{"green", Colour{0, 0.8, 0}},
    std::pair{"blue", Colour{0, 0.3, 1}},     std::pair{"yellow", Colour{1, 0.9, 0}},
    std::pair{"orange", Colour{1, 0.5, 0}},   std::pair{"purple", Colour{0.6, 0.2, 0.8}},
    std::pair{"white", Colour{1, 1, 1}},      std::pair{"black", Colour{0, 0, 0}},
    std::pair{"grey", Colour{0.5, 0.5, 0.5}}, std::pair{"pink", Colour{1, 0.6, 0.75}},
};

// "red" or "R,G,B" with components in 0..1.
bool parseColour(std::string_view word, Colour& out) {
    for (const auto& [name, colour] : kColourNames)
        if (word == name) {
            out = colour;
            return true;
        }
    double c[3];
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = word.find(',');
        if ((i < 2) != (comma != std::string_view::npos)) return false;
        if (!parseUnit(word.substr(0, comma), c[i])) return false;
        word = i < 2 ? word.substr(comma + 1) : std::string_view{};
    }
    out = {c[0], c[1], c[2]};
    return true;
}

std::optional<ShapeOperation> operationNamed(std::string_view word) {
    if (word == "union") return ShapeOperation::Union;
    if (word == "intersection") return ShapeOperation::Intersection;
    if (word == "difference") return ShapeOperation::Difference;
    return std::nullopt;
}

ChatCommandParse fail(std::string message) {
    return {std::nullopt, std::move(message)};
}

std::string number(double v) {
    return scene::formatNumber(v);
}

// What a command changed: string fields of nodes written in the text (kept
// in place), or new nodes (the scene is then written anew).
struct ModelEdits {
    bool created = false;
    std::vector<std::pair<const scene::Node*, std::string>> strings;
};

scene::Node* makeNode(scene::Scene& s, ModelEdits& edits, const char* type) {
    edits.created = true;
    scene::Node* n = s.newNode();
    n->type = type;
    n->spec = scene::findNodeSpec(type);
    return n;
}

scene::Field& fieldOf(scene::Node& node, std::string_view name, scene::FieldType type) {
    scene::Field* f = node.field(name);
    if (!f) {
        node.fields.push_back({});
        f = &node.fields.back();
        f->name = std::string(name);
    }
    f->value = {};
    f->value.type = type;
    return *f;
}

void setStrings(ModelEdits& edits, scene::Node& node, std::string_view name,
                std::vector<std::string> strings,
                scene::FieldType type = scene::FieldType::MFString) {
    fieldOf(node, name, type).value.strings = std::move(strings);
    edits.strings.emplace_back(&node, std::string(name));
}

void setNumbers(scene::Node& node, std::string_view name, std::vector<double> numbers) {
    fieldOf(node, name, scene::FieldType::SFVec3f).value.numbers = std::move(numbers);
}

void setNode(scene::Node& node, std::string_view name, scene::Node* child) {
    fieldOf(node, name, scene::FieldType::SFNode).value.nodes = {child};
}

bool isShown(const scene::Node& n) {
    return !n.inProtoBody && n.instance == nullptr;
}

// The FShape CLASS, else the first FShape written in the scene.
scene::Node* classShape(scene::Scene& s) {
    scene::Node* first = nullptr;
    scene::Node* named = nullptr;
    s.forEachNode([&](scene::Node& n) {
        if (n.kind() != scene::NodeKind::FShape || !isShown(n)) return;
        if (!first) first = &n;
        if (!named && n.defName == kClassShapeName) named = &n;
    });
    return named ? named : first;
}

scene::Node* childNode(scene::Node& node, std::string_view field) {
    scene::Field* f = node.field(field);
    return f && f->value.nodes.size() == 1 ? f->value.nodes[0] : nullptr;
}

std::string_view operatorOf(ShapeOperation op) {
    switch (op) {
    case ShapeOperation::Union:
        return "|";
    case ShapeOperation::Intersection:
        return "&";
    case ShapeOperation::Difference:
        return "\\";
    }
    return "|";
}

// Formula text read by the formula lexer, so that what a comment holds (a
// `;`, a `return`, a `)`) is never taken for code.
struct FormulaTokens {
    std::string_view text;
    std::vector<formula::Token> tokens; // without the End token

    explicit FormulaTokens(std::string_view t) : text(t) {
        std::vector<formula::Diagnostic> ignored; // the class checks the result in full
        tokens = formula::tokenize(t, ignored);
        if (!tokens.empty() && tokens.back().kind == formula::TokenKind::End) tokens.pop_back();
    }
    bool has(formula::TokenKind kind) const {
        return std::any_of(tokens.begin(), tokens.end(),
                           [&](const formula::Token& t) { return t.kind == kind; });
    }
    // Whether a `//` comment runs to the end of a line somewhere between
    // `from` and `to` (byte offsets): what follows on that line is hidden.
    bool lineCommentIn(std::size_t from, std::size_t to) const {
        std::size_t at = from;
        for (const formula::Token& t : tokens) {
            if (t.range.begin.offset >= to) break;
            if (t.range.end.offset <= from) continue;
            if (text.substr(at, t.range.begin.offset - at).find("//") != std::string_view::npos)
                return true;
            at = t.range.end.offset;
        }
        return text.substr(at, to - std::min(at, to)).find("//") != std::string_view::npos;
    }
};

// `text` closed so that a following `)` is not inside a line comment.
std::string closable(std::string_view text, const FormulaTokens& t, std::size_t from,
                     std::size_t to) {
    return std::string(text) + (t.lineCommentIn(from, to) ? "\n" : "");
}

// `old OP (tool)`: a plain expression is wrapped whole; a script's final
// `return EXPR;` becomes `return (EXPR) OP (tool);`. Comments stay where they
// were written and are never read as code.
std::string combined(const std::string& old, ShapeOperation op, const std::string& tool,
                     std::string& why) {
    const std::string opText(operatorOf(op));
    const FormulaTokens toolTokens(tool);
    const std::string toolText = closable(tool, toolTokens, 0, tool.size());
    const FormulaTokens t(old);
    if (!t.has(formula::TokenKind::Semicolon))
        return "(" + closable(old, t, 0, old.size()) + ") " + opText + " (" + toolText + ")";
    // A script: the last `return`, then its expression up to the final `;`.
    const auto last = std::find_if(t.tokens.rbegin(), t.tokens.rend(), [](const formula::Token& k) {
        return k.kind == formula::TokenKind::KwReturn;
    });
    const bool endsWithReturn = last != t.tokens.rend() &&
                                t.tokens.back().kind == formula::TokenKind::Semicolon &&
                                std::none_of(last.base(), t.tokens.end() - 1,
                                             [](const formula::Token& k) {
                                                 return k.kind == formula::TokenKind::Semicolon ||
                                                        k.kind == formula::TokenKind::RBrace ||
                                                        k.kind == formula::TokenKind::LBrace;
                                             }) &&
                                last.base() != t.tokens.end() - 1;
    if (!endsWithReturn) {
        why = "the class shape's script does not end with `return EXPRESSION;`, so there is "
              "nothing to combine the new shape with";
        return {};
    }
    const std::size_t exprBegin = last->range.end.offset;
    const std::size_t exprEnd = t.tokens.back().range.begin.offset;
    const std::string_view expression =
        std::string_view(old).substr(exprBegin, exprEnd - exprBegin);
    return old.substr(0, exprBegin) + " (" + closable(trim(expression), t, exprBegin, exprEnd) +
           ") " + opText + " (" + toolText + ")" + old.substr(exprEnd);
}

std::string addShape(scene::Scene& s, ModelEdits& edits, const ChatCommand& c, std::string& why) {
    scene::Node* shape = classShape(s);
    if (!shape) {
        if (c.operation != ShapeOperation::Union) {
            why = "the scene has no shape to cut or intersect yet; start with /add FORMULA";
            return {};
        }
        shape = makeNode(s, edits, "FShape");
        shape->defName = std::string(kClassShapeName);
        scene::Node* geometry = makeNode(s, edits, "FGeometry");
        setStrings(edits, *geometry, "type", {"implicit"}, scene::FieldType::SFString);
        setStrings(edits, *geometry, "definition", {c.formula});
        setNumbers(*geometry, "domainMin", {-2, -2, -2});
        setNumbers(*geometry, "domainMax", {2, 2, 2});
        setNode(*shape, "geometry", geometry);
        s.roots.push_back(shape);
        return "ok";
    }
    scene::Node* geometry = childNode(*shape, "geometry");
    if (!geometry || geometry->kind() != scene::NodeKind::FGeometry) {
        why = "the class shape has no FGeometry to change";
        return {};
    }
    const std::string type = scene::stringField(*geometry, "type");
    if (type == "parametric") {
        why = "the class shape is parametric; /add combines implicit shapes";
        return {};
    }
    scene::Field* definition = geometry->field("definition");
    if (!definition || definition->value.strings.empty()) {
        setStrings(edits, *geometry, "definition", {c.formula});
        return "ok";
    }
    const std::string next = combined(scene::formulaText(*definition), c.operation, c.formula, why);
    if (next.empty()) return {};
    setStrings(edits, *geometry, "definition", {next});
    return "ok";
}

// The material to paint on: the class shape's parametric FMaterial, made
// from a standard Material's diffuse colour (or grey) when it has none.
scene::Node* paintableMaterial(scene::Scene& s, ModelEdits& edits, scene::Node& shape,
                               std::string& why) {
    scene::Node* appearance = childNode(shape, "appearance");
    scene::Node* material = appearance ? childNode(*appearance, "material") : nullptr;
    if (material && material->kind() == scene::NodeKind::FMaterial) {
        if (scene::stringField(*material, "type") != "parametric") {
            why = "the class shape's FMaterial is not parametric (r = ...; g = ...; b = ...;)";
            return nullptr;
        }
        return material;
    }
    std::vector<double> base{0.8, 0.8, 0.8};
    if (material && material->kind() == scene::NodeKind::Material)
        if (auto d = scene::numbersField(*material, "diffuseColor"); d.size() == 3) base = d;
    if (!appearance || appearance->kind() != scene::NodeKind::FAppearance) {
        appearance = makeNode(s, edits, "FAppearance");
        setNode(shape, "appearance", appearance);
    }
    material = makeNode(s, edits, "FMaterial");
    setStrings(edits, *material, "type", {"parametric"}, scene::FieldType::SFString);
    setStrings(edits, *material, "definition",
               {"r = " + number(base[0]) + ";", "g = " + number(base[1]) + ";",
                "b = " + number(base[2]) + ";"});
    // The material's x, y, z are the geometry's when both have the same box.
    if (scene::Node* geometry = childNode(shape, "geometry");
        geometry && geometry->spec && geometry->kind() == scene::NodeKind::FGeometry) {
        setNumbers(*material, "domainMin", scene::numbersField(*geometry, "domainMin"));
        setNumbers(*material, "domainMax", scene::numbersField(*geometry, "domainMax"));
    }
    setNode(*appearance, "material", material);
    return material;
}

std::string paintShape(scene::Scene& s, ModelEdits& edits, const ChatCommand& c, std::string& why) {
    scene::Node* shape = classShape(s);
    if (!shape) {
        why = "the scene has no shape to paint";
        return {};
    }
    scene::Node* material = paintableMaterial(s, edits, *shape, why);
    if (!material) return {};
    scene::Field* definition = material->field("definition");
    std::vector<std::string> lines =
        definition ? definition->value.strings : std::vector<std::string>{};
    for (const std::string& line : lines)
        if (FormulaTokens(line).has(formula::TokenKind::KwReturn)) {
            why = "the class shape's colour script returns early; paint is added after it";
            return {};
        }
    const FormulaTokens tool(c.formula);
    lines.push_back("paint = " + number(c.opacity) + " * step(0, " +
                    closable(c.formula, tool, 0, c.formula.size()) + ");");
    lines.push_back("r = mix(r, " + number(c.colour.r) + ", paint);");
    lines.push_back("g = mix(g, " + number(c.colour.g) + ", paint);");
    lines.push_back("b = mix(b, " + number(c.colour.b) + ", paint);");
    setStrings(edits, *material, "definition", std::move(lines));
    return "ok";
}

} // namespace

bool isChatCommand(std::string_view text) {
    return !text.empty() && text.front() == '/';
}

std::string chatCommandHelp() {
    return "Modelling commands (each changes the class shape, the FShape named CLASS or the "
           "first one):\n"
           "  /add FORMULA [union|intersection|difference]  combine a shape (f >= 0 inside) "
           "with the class shape (union when not said)\n"
           "  /remove FORMULA        cut a shape away (difference)\n"
           "  /paint COLOUR [N%] FORMULA  paint where the shape meets the object; COLOUR is a "
           "name (red, green, blue, yellow, orange, purple, white, black, grey, pink) or "
           "R,G,B in 0..1; N% the tool's opacity (100% when not said)\n"
           "  /undo                  take back your own last command, if nobody changed the "
           "scene since\n"
           "  /save [LABEL]          keep a snapshot of the scene as it is now\n"
           "  /help                  this list\n"
           "Example: /add sphere(0.5, 0, 0, 0.4) difference";
}

ChatCommandParse parseChatCommand(std::string_view text) {
    if (!isChatCommand(text)) return fail("a command starts with '/'");
    std::string_view rest = text.substr(1);
    const std::string_view word = takeWord(rest);
    ChatCommand c;
    if (word == "help") {
        c.kind = ChatCommandKind::Help;
        return {c, {}};
    }
    if (word == "undo" || word == "save") {
        c.kind = word == "undo" ? ChatCommandKind::Undo : ChatCommandKind::Save;
        if (c.kind == ChatCommandKind::Undo && !rest.empty())
            return fail("/undo takes nothing after it");
        c.label = std::string(rest);
        return {c, {}};
    }
    if (word == "add" || word == "remove") {
        c.kind = ChatCommandKind::Add;
        c.operation = word == "add" ? ShapeOperation::Union : ShapeOperation::Difference;
        if (word == "add") {
            const std::size_t space = rest.find_last_of(" \t");
            if (space != std::string_view::npos)
                if (auto op = operationNamed(trim(rest.substr(space)))) {
                    c.operation = *op;
                    rest = trim(rest.substr(0, space));
                }
        }
        if (rest.empty())
            return fail("/" + std::string(word) + " needs a formula, e.g. /" + std::string(word) +
                        " sphere(0, 0, 0, 0.5)");
        c.formula = std::string(rest);
        return {c, {}};
    }
    if (word == "paint") {
        c.kind = ChatCommandKind::Paint;
        const std::string_view colour = takeWord(rest);
        if (!parseColour(colour, c.colour))
            return fail("/paint COLOUR [N%] FORMULA: '" + std::string(colour) +
                        "' is no colour name or R,G,B in 0..1");
        std::string_view probe = rest;
        if (const std::string_view w = takeWord(probe); !w.empty() && w.back() == '%') {
            double percent = 0;
            const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size() - 1, percent);
            if (ec != std::errc{} || end != w.data() + w.size() - 1 || percent < 0 || percent > 100)
                return fail("/paint: the opacity '" + std::string(w) + "' is not 0% to 100%");
            c.opacity = percent / 100;
            rest = probe;
        }
        if (rest.empty())
            return fail("/paint needs the tool's shape, e.g. /paint red sphere(0, 0, 0, 0.3)");
        c.formula = std::string(rest);
        return {c, {}};
    }
    return fail("unknown command '/" + std::string(word) + "'; /help lists them");
}

std::string CommandMistake::said() const {
    return "column " + std::to_string(column) + " of your command: " + message +
           (suggestion.empty() ? "" : " (" + suggestion + ")");
}

std::optional<CommandMistake> formulaMistakeInCommand(const ChatCommand& command,
                                                      std::string_view text) {
    if (command.kind != ChatCommandKind::Add && command.kind != ChatCommandKind::Paint)
        return std::nullopt;
    std::vector<formula::Diagnostic> diagnostics;
    (void)formula::parse(command.formula, diagnostics);
    for (const formula::Diagnostic& d : diagnostics) {
        if (d.severity != formula::Severity::Error) continue;
        // The formula is the end of the command: its columns are counted on.
        const std::size_t at = text.rfind(command.formula);
        const std::size_t bytes = (at == std::string_view::npos ? 0 : at) + d.range.begin.offset;
        return CommandMistake{characterCount(text.substr(0, std::min(bytes, text.size()))) + 1,
                              d.message, d.suggestion};
    }
    return std::nullopt;
}

std::string applyChatCommand(const ChatCommand& command, const std::string& sceneText,
                             std::string& why) {
    scene::ReadOptions options;
    options.followReferences = false;
    options.compileFunctions = false; // the result is checked in full afterwards
    scene::ReadResult read = scene::readSceneBytes(sceneText, "scene", options);
    if (!read.ok()) {
        why = "the class scene cannot be read";
        return {};
    }
    scene::Scene& s = *read.scene;
    ModelEdits edits;
    std::string done;
    if (command.kind == ChatCommandKind::Add)
        done = addShape(s, edits, command, why);
    else if (command.kind == ChatCommandKind::Paint)
        done = paintShape(s, edits, command, why);
    else
        why = "this command does not change the scene";
    if (done.empty()) return {};
    const std::string rewritten = scene::writeScene(s, s.encoding);
    if (edits.created) return rewritten; // new nodes: the writer places them
    // Only definitions changed: each replaced where it is written, so the
    // class scene keeps its comments and layout. Kept only when it reads
    // back as the same model as the rewritten scene.
    scene::SceneEdit inPlace(s);
    for (const auto& [node, field] : edits.strings) {
        const scene::Field* f = node->field(field);
        if (!f || !inPlace.setStrings(*node, field, f->value.strings)) return rewritten;
    }
    const std::string text = inPlace.appliedTo(sceneText);
    scene::ReadResult again = scene::readSceneBytes(text, "scene", options);
    if (!again.ok() || scene::writeScene(*again.scene, again.scene->encoding) != rewritten)
        return rewritten;
    return text;
}

} // namespace fl::classroom
