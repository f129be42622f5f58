#pragma once
// A graph of grouping nodes drawn from bytes, and the scene text that makes
// it with DEF and USE, in X3D XML or ClassicVRML: each node written once
// (nested under the first node that holds it when that one is written first),
// every other reference a USE — forward ones too. Grouping kinds vary
// (Transform, Switch, LOD, FTransform, a PROTO instance whose MFNode field the
// body holds as children), so a loop can run through any of them. Shared by
// the property test (tests/scene/node_loop_test.cpp) and the fuzz target
// (tests/fuzz/scene_graph_fuzz.cpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace fl::test {

struct NodeGraphText {
    enum class Kind : std::uint8_t { Group, Transform, Switch, Lod, FTransform, Proto };
    std::vector<Kind> kinds;
    std::vector<std::vector<int>> children;
    std::vector<int> rootOrder; // the order nodes are tried as roots when written
    bool xml = false;

    bool hasLoop() const {
        std::vector<int> state(children.size(), 0); // 0 new, 1 on the path, 2 done
        std::function<bool(int)> visit = [&](int n) {
            state[std::size_t(n)] = 1;
            for (int c : children[std::size_t(n)])
                if (state[std::size_t(c)] == 1 || (state[std::size_t(c)] == 0 && visit(c)))
                    return true;
            state[std::size_t(n)] = 2;
            return false;
        };
        for (std::size_t n = 0; n < children.size(); ++n)
            if (state[n] == 0 && visit(int(n))) return true;
        return false;
    }

    // 2 to 10 nodes of up to 3 children each; every byte is used, missing
    // ones read as 0.
    static NodeGraphText fromBytes(const std::uint8_t* data, std::size_t size) {
        std::size_t at = 0;
        auto next = [&]() -> unsigned { return at < size ? data[at++] : 0u; };
        NodeGraphText g;
        const unsigned header = next();
        const int n = 2 + int(header % 9);
        g.xml = (header / 9) % 2 == 1;
        g.kinds.resize(std::size_t(n));
        g.children.resize(std::size_t(n));
        for (int i = 0; i < n; ++i) {
            const unsigned b = next();
            g.kinds[std::size_t(i)] = Kind(b % 6);
            const int count = int((b / 6) % 4);
            for (int k = 0; k < count; ++k)
                g.children[std::size_t(i)].push_back(int(next() % unsigned(n)));
        }
        for (int i = 0; i < n; ++i)
            g.rootOrder.push_back(i);
        for (int i = n - 1; i > 0; --i) // a shuffle the bytes choose
            std::swap(g.rootOrder[std::size_t(i)], g.rootOrder[next() % unsigned(i + 1)]);
        return g;
    }

    std::string text() const {
        std::vector<bool> written(children.size(), false);
        std::string out;
        std::function<void(int, int)> write = [&](int node, int indent) {
            written[std::size_t(node)] = true;
            const std::string pad(std::size_t(indent), ' ');
            const std::string name = "N" + std::to_string(node);
            const Kind kind = kinds[std::size_t(node)];
            out += pad + open(kind, name) + "\n";
            for (int c : children[std::size_t(node)]) {
                if (!written[std::size_t(c)]) {
                    write(c, indent + 1);
                    continue;
                }
                const std::string use = "N" + std::to_string(c);
                out += pad + (xml ? " <Group USE='" + use + "'/>\n" : " USE " + use + "\n");
            }
            out += pad + close(kind) + "\n";
        };
        for (int root : rootOrder)
            if (!written[std::size_t(root)]) write(root, 0);
        if (xml)
            return "<X3D profile='Full'><Scene>\n"
                   "<ProtoDeclare name='P'><ProtoInterface>"
                   "<field name='kids' type='MFNode' accessType='inputOutput'/>"
                   "</ProtoInterface><ProtoBody><Group><IS>"
                   "<connect nodeField='children' protoField='kids'/></IS></Group>"
                   "</ProtoBody></ProtoDeclare>\n" +
                   out + "</Scene></X3D>\n";
        return "#X3D V3.3 utf8\nPROFILE Full\n"
               "PROTO P [ inputOutput MFNode kids [] ] { Group { children IS kids } }\n" +
               out;
    }

  private:
    std::string open(Kind kind, const std::string& name) const {
        if (xml) {
            switch (kind) {
            case Kind::Group:
                return "<Group DEF='" + name + "'>";
            case Kind::Transform:
                return "<Transform DEF='" + name + "' translation='1 0 0'>";
            case Kind::Switch:
                return "<Switch DEF='" + name + "' whichChoice='0'>";
            case Kind::Lod:
                return "<LOD DEF='" + name + "' range='10'>";
            case Kind::FTransform:
                return "<FTransform DEF='" + name + "' operation='union'>";
            case Kind::Proto:
                return "<ProtoInstance name='P' DEF='" + name + "'><fieldValue name='kids'>";
            }
        }
        switch (kind) {
        case Kind::Group:
            return "DEF " + name + " Group { children [";
        case Kind::Transform:
            return "DEF " + name + " Transform { translation 1 0 0 children [";
        case Kind::Switch:
            return "DEF " + name + " Switch { whichChoice 0 children [";
        case Kind::Lod:
            return "DEF " + name + " LOD { range 10 children [";
        case Kind::FTransform:
            return "DEF " + name + " FTransform { operation \"union\" children [";
        case Kind::Proto:
            return "DEF " + name + " P { kids [";
        }
        return {};
    }

    std::string close(Kind kind) const {
        if (!xml) return "] }";
        switch (kind) {
        case Kind::Group:
            return "</Group>";
        case Kind::Transform:
            return "</Transform>";
        case Kind::Switch:
            return "</Switch>";
        case Kind::Lod:
            return "</LOD>";
        case Kind::FTransform:
            return "</FTransform>";
        case Kind::Proto:
            return "</fieldValue></ProtoInstance>";
        }
        return {};
    }
};

} // namespace fl::test
