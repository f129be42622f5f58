// Property: writing a scene and reading it back gives the same model, for
// scenes generated at random from the node catalogue — every standard and
// function node type, nodes in node-valued fields (geometry, appearance,
// material, coord, texture ... by their containerField), every field with an
// initial value, PROTOs with IS (interfaces()), values chosen to be awkward
// (extreme and tiny numbers, quotes, backslashes, XML specials, non-ASCII
// text), DEF/USE sharing and ROUTEs — in X3D XML, ClassicVRML and, for the
// nodes it has, VRML97.
#include "scene/node_catalogue.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <random>
#include <tuple>

using namespace fl::scene;

namespace {

// Fields whose values the reader checks or follows beyond their type.
bool skipped(const NodeSpec& node, const FieldSpec& f) {
    const std::string_view n = f.name;
    return f.type == FieldType::SFImage || f.type == FieldType::MFImage || n == "url" ||
           n == "metadata" || (node.name == "Script") || holdsNodes(f.type);
}

class Generator {
  public:
    explicit Generator(unsigned seed, bool vrml97) : rng_(seed), vrml97_(vrml97) {
        for (const NodeSpec& s : nodeCatalogue()) {
            if (vrml97 && !s.inVrml97 && s.family != NodeFamily::Function) continue;
            if (s.name == "Script" || s.name == "Inline") continue; // followed or warned about
            if (s.containerField == "children")
                childTypes_.push_back(&s);
            else
                byContainer_[std::string(s.containerField)].push_back(&s);
        }
    }

    std::string scene() {
        std::string out = vrml97_ ? "#VRML V2.0 utf8\n" : "#X3D V3.3 utf8\nPROFILE Full\n";
        const int roots = pick(1, 4);
        for (int i = 0; i < roots; ++i)
            out += node(0) + "\n";
        out += routes_;
        return out;
    }

  private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }

    std::string number(bool integral) {
        if (integral) return std::to_string(pick(-100000, 100000));
        static const char* const special[] = {
            "0", "-0", "1e-300", "1.7976931348623157e308", "4.9e-324", "0.1", "-123456.789", "3"};
        if (chance(0.2)) return special[pick(0, 7)];
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g",
                      std::uniform_real_distribution<double>(-1e6, 1e6)(rng_));
        return buf;
    }

    std::string text() {
        static const char* const pieces[] = {
            "a", "Zz", " ", "\\\"",         "\\\\", "&", "<", ">",  "'",
            ",", "#",  "é", "\xE2\x82\xAC", "日本", "]", "[", "{}", "x y"};
        std::string s;
        const int n = pick(0, 6);
        for (int i = 0; i < n; ++i)
            s += pieces[pick(0, 17)];
        return "\"" + s + "\"";
    }

    std::string element(FieldType single) {
        if (single == FieldType::SFBool) return chance(0.5) ? "TRUE" : "FALSE";
        if (holdsStrings(single)) return text();
        std::string out;
        const int n = componentsPerElement(single);
        for (int i = 0; i < n; ++i)
            out += (i ? " " : "") + number(isIntegral(single));
        return out;
    }

    std::string value(FieldType type) {
        if (!isMultiple(type)) return element(type);
        std::string out = "[";
        const int n = pick(0, 4);
        for (int i = 0; i < n; ++i)
            out += (i ? ", " : "") + element(singleOf(type));
        return out + "]";
    }

    std::string node(int depth) {
        if (!defs_.empty() && chance(0.1))
            return "USE " + defs_[std::size_t(pick(0, int(defs_.size()) - 1))].first;
        // Shapes a third of the time: what carries geometry, appearance and
        // materials, standard and function-defined alike.
        const NodeSpec& spec =
            chance(0.35) ? *findNodeSpec(chance(0.5) ? "Shape" : "FShape")
                         : *childTypes_[std::size_t(pick(0, int(childTypes_.size()) - 1))];
        std::string out;
        std::string def;
        if (chance(0.3)) {
            def = "N" + std::to_string(nextDef_++);
            out += "DEF " + def + " ";
        }
        out += std::string(spec.name) + " {\n";
        const FieldSpec* children = nullptr;
        for (const FieldSpec& f : spec.fields) {
            if (f.name == "children" && f.type == FieldType::MFNode) children = &f;
            if (holdsNodes(f.type) && f.name != "children" && hasInitialValue(f.access) &&
                f.name != "metadata" && depth < 3 && chance(0.7)) {
                // geometry, appearance, material, coord, texture ...: a node
                // whose default containerField is this field's name.
                const auto fitting = byContainer_.find(std::string(f.name));
                if (fitting != byContainer_.end() && !fitting->second.empty()) {
                    const int n = f.type == FieldType::SFNode ? 1 : pick(1, 2);
                    std::string nodes;
                    for (int i = 0; i < n; ++i)
                        nodes += (i ? " " : "") +
                                 valueNode(*fitting->second[std::size_t(
                                               pick(0, int(fitting->second.size()) - 1))],
                                           depth + 1);
                    out += "  " + std::string(f.name) + " " +
                           (f.type == FieldType::MFNode ? "[ " + nodes + " ]" : nodes) + "\n";
                }
                continue;
            }
            if (!hasInitialValue(f.access) || skipped(spec, f) || !chance(0.5)) continue;
            out += "  " + std::string(f.name) + " " + value(f.type) + "\n";
        }
        if (children && depth < 3 && chance(0.6)) {
            out += "  children [\n";
            const int n = pick(1, 3);
            for (int i = 0; i < n; ++i)
                out += node(depth + 1) + "\n";
            out += "  ]\n";
        }
        out += "}";
        if (!def.empty()) {
            defs_.emplace_back(def, &spec);
            addRoute(def, spec);
        }
        return out;
    }

    // A node in a node-valued field: its own fields with values, recursively.
    std::string valueNode(const NodeSpec& spec, int depth) {
        std::string out = std::string(spec.name) + " {\n";
        for (const FieldSpec& f : spec.fields) {
            if (holdsNodes(f.type)) {
                const auto fitting = byContainer_.find(std::string(f.name));
                if (f.type == FieldType::SFNode && f.name != "metadata" &&
                    hasInitialValue(f.access) && depth < 4 && fitting != byContainer_.end() &&
                    !fitting->second.empty() && chance(0.6))
                    out +=
                        "  " + std::string(f.name) + " " +
                        valueNode(
                            *fitting->second[std::size_t(pick(0, int(fitting->second.size()) - 1))],
                            depth + 1) +
                        "\n";
                continue;
            }
            if (!hasInitialValue(f.access) || skipped(spec, f) || !chance(0.5)) continue;
            out += "  " + std::string(f.name) + " " + value(f.type) + "\n";
        }
        return out + "}";
    }

    // A ROUTE from an output of an earlier DEF'd node to an input of the same
    // type on this one, when there is such a pair.
    void addRoute(const std::string& def, const NodeSpec& to) {
        if (defs_.size() < 2 || !chance(0.5)) return;
        const auto& [fromDef, from] = defs_[std::size_t(pick(0, int(defs_.size()) - 2))];
        for (const FieldSpec& out : from->fields) {
            if (!canRead(out.access) || holdsNodes(out.type) || out.name == "metadata") continue;
            for (const FieldSpec& in : to.fields)
                if (canWrite(in.access) && in.type == out.type && in.name != "metadata" &&
                    !holdsNodes(in.type)) {
                    routes_ += "ROUTE " + fromDef + "." + std::string(out.name) + " TO " + def +
                               "." + std::string(in.name) + "\n";
                    return;
                }
        }
    }

  public:
    // Issue 20: nodes that carry an interface — Script, ComposedShader,
    // PackagedShader, ShaderProgram, and a node type FunctionLab does not
    // know — each declaring fields of every type and access with values
    // (nodes in SFNode/MFNode ones too), some inside a PROTO body connected
    // to its interface by IS.
    std::string interfaces() {
        std::string out = "#X3D V3.3 utf8\nPROFILE Full\n";
        std::vector<std::tuple<std::string, FieldType, AccessType>> iface;
        std::string protoHead = "PROTO Carrier [\n";
        for (int i = 0; i < pick(1, 6); ++i) {
            const FieldType type = anyType();
            const AccessType access = anyAccess();
            const std::string name = "i" + std::to_string(i);
            iface.emplace_back(name, type, access);
            protoHead += "  " + std::string(accessTypeName(access)) + " " +
                         std::string(fieldTypeName(type)) + " " + name +
                         (hasInitialValue(access) ? " " + anyValue(type) : "") + "\n";
        }
        out += protoHead + "] {\n  Shape {\n    appearance Appearance {\n      shaders " +
               declaring("ComposedShader", "language \"GLSL\"", &iface) +
               "\n    }\n    geometry Box { }\n  }\n}\n";
        out += "Carrier { }\n";
        out += declaring("Script", "url \"ecmascript: function f() {}\"", nullptr) + "\n";
        out += "Shape {\n  appearance Appearance {\n    shaders [\n" +
               declaring("PackagedShader", "url \"effect.fx\"", nullptr) + "\n" +
               "ProgramShader { programs " +
               declaring("ShaderProgram", "type \"FRAGMENT\" url \"p.glsl\"", nullptr) +
               " }\n    ]\n  }\n  geometry Sphere { }\n}\n";
        out += declaring("SomeoneElsesNode", "", nullptr) + "\n";
        return out;
    }

  private:
    FieldType anyType() {
        FieldType t;
        do {
            t = FieldType(pick(0, int(FieldType::MFNode)));
        } while (t == FieldType::SFImage || t == FieldType::MFImage);
        return t;
    }
    AccessType anyAccess() { return AccessType(pick(0, 3)); }
    std::string anyValue(FieldType type) {
        if (type == FieldType::SFNode) return chance(0.3) ? "NULL" : "Box { size 1 2 3 }";
        if (type == FieldType::MFNode)
            return chance(0.3) ? "[]" : "[ Box { } Sphere { radius 2 } ]";
        return value(type);
    }

    // `type { own... declarations... }`; inside a PROTO body, some connected
    // by IS to an interface field they may connect to (same type; the same
    // access, or any for an inputOutput field).
    std::string
    declaring(const std::string& type, const std::string& own,
              const std::vector<std::tuple<std::string, FieldType, AccessType>>* iface) {
        std::string out = type + " {\n";
        if (!own.empty()) out += "  " + own + "\n";
        for (int i = 0; i < pick(1, 8); ++i) {
            const FieldType t = anyType();
            const AccessType a = anyAccess();
            std::string line = "  " + std::string(accessTypeName(a)) + " " +
                               std::string(fieldTypeName(t)) + " f" + std::to_string(i);
            const std::tuple<std::string, FieldType, AccessType>* partner = nullptr;
            if (iface)
                for (const auto& f : *iface)
                    if (std::get<1>(f) == t &&
                        (a == AccessType::InputOutput || std::get<2>(f) == a))
                        partner = &f;
            if (partner && chance(0.7))
                line += " IS " + std::get<0>(*partner);
            else if (hasInitialValue(a))
                line += " " + anyValue(t);
            out += line + "\n";
        }
        return out + "}";
    }

    std::mt19937 rng_;
    bool vrml97_;
    std::vector<const NodeSpec*> childTypes_;
    std::map<std::string, std::vector<const NodeSpec*>> byContainer_;
    std::vector<std::pair<std::string, const NodeSpec*>> defs_;
    std::string routes_;
    int nextDef_ = 0;
};

void expectRoundTrip(const std::string& text, bool vrml97, unsigned seed) {
    ReadOptions options;
    options.compileFunctions = false;
    ReadResult original = readSceneBytes(text, vrml97 ? "random.wrl" : "random.x3dv", options);
    std::string problems;
    for (const auto& d : original.diagnostics)
        if (d.severity == Severity::Error) problems += formatSceneDiagnostic(d) + "\n";
    ASSERT_TRUE(original.ok()) << "seed " << seed << ": the generated scene does not load\n"
                               << problems << text;
    for (Encoding e : {Encoding::Xml, Encoding::ClassicVrml, Encoding::Vrml97}) {
        if (e == Encoding::Vrml97 && !vrml97) continue;
        const std::string written = writeScene(*original.scene, e);
        ReadResult back = readSceneBytes(written, e == Encoding::Xml ? "w.x3d" : "w.x3dv", options);
        ASSERT_TRUE(back.ok()) << "seed " << seed << ": written scene does not read back\n"
                               << written;
        std::string difference;
        EXPECT_TRUE(sameModel(*original.scene, *back.scene, &difference))
            << "seed " << seed << ", encoding " << int(e) << ": " << difference << "\n"
            << text;
    }
}

} // namespace

TEST(RandomScenes, X3dWritingThenReadingIsTheIdentity) {
    for (unsigned seed = 1; seed <= 1000; ++seed) {
        expectRoundTrip(Generator(seed, false).scene(), false, seed);
        if (HasFailure()) return;
    }
}

TEST(RandomScenes, Vrml97WritingThenReadingIsTheIdentity) {
    for (unsigned seed = 1; seed <= 500; ++seed) {
        expectRoundTrip(Generator(seed, true).scene(), true, seed);
        if (HasFailure()) return;
    }
}

TEST(RandomScenes, InterfacesAndTheirIsSurviveEveryEncoding) {
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const std::string text = Generator(seed, false).interfaces();
        expectRoundTrip(text, false, seed);
        // And the ClassicVRML text is a fixed point through X3D XML (issue 20).
        ReadOptions options;
        options.compileFunctions = false;
        ReadResult a = readSceneBytes(text, "i.x3dv", options);
        ASSERT_TRUE(a.ok());
        const std::string classic = writeScene(*a.scene, Encoding::ClassicVrml);
        ReadResult x = readSceneBytes(writeScene(*a.scene, Encoding::Xml), "i.x3d", options);
        ASSERT_TRUE(x.ok()) << "seed " << seed;
        EXPECT_EQ(writeScene(*x.scene, Encoding::ClassicVrml), classic) << "seed " << seed;
        if (HasFailure()) return;
    }
}

TEST(RandomScenes, TheGeneratorReallyMakesWhatItClaims) {
    // A generator that silently stopped making node-valued fields or function
    // nodes would leave the round-trip tests above checking less.
    std::size_t geometry = 0, appearance = 0, material = 0, functionNodes = 0, uses = 0, routes = 0;
    for (unsigned seed = 1; seed <= 200; ++seed) {
        const std::string text = Generator(seed, false).scene();
        auto count = [&](const std::string& what) {
            std::size_t n = 0;
            for (std::size_t at = text.find(what); at != std::string::npos;
                 at = text.find(what, at + 1))
                ++n;
            return n;
        };
        geometry += count("  geometry ");
        appearance += count("  appearance ");
        material += count("  material ");
        functionNodes += count("FShape {") + count("FGeometry {") + count("FTransform {");
        uses += count("USE ");
        routes += count("ROUTE ");
    }
    EXPECT_GT(geometry, 20u);
    EXPECT_GT(appearance, 20u);
    EXPECT_GT(material, 5u);
    EXPECT_GT(functionNodes, 20u);
    EXPECT_GT(uses, 10u);
    EXPECT_GT(routes, 2u);
    std::cout << geometry << " geometry, " << appearance << " appearance, " << material
              << " material, " << functionNodes << " function nodes, " << uses << " USE, " << routes
              << " ROUTE in 200 scenes\n";
}
