#include "scene_references.h"

#include "field_access.h"
#include "scene_reader.h"

#include <fstream>
#include <sstream>

namespace fl::scene {

namespace fs = std::filesystem;

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percentDecoded(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() && hexDigit(s[i + 1]) >= 0 && hexDigit(s[i + 2]) >= 0) {
            out += char(hexDigit(s[i + 1]) * 16 + hexDigit(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// "http:", "urn:", "ftp:" ...: a scheme of two letters or more (one letter
// is a Windows drive).
std::string_view schemeOf(std::string_view url) {
    const std::size_t colon = url.find(':');
    if (colon == std::string_view::npos || colon < 2) return {};
    for (std::size_t i = 0; i < colon; ++i) {
        const char c = url[i];
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.')
            return {};
    }
    return url.substr(0, colon);
}

bool inside(const fs::path& root, const fs::path& file) {
    const fs::path rel = file.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

std::string inQuotes(std::string_view s) {
    return "'" + std::string(s) + "'";
}

} // namespace

std::optional<UrlTarget> resolveUrl(const ReferenceContext& context, const fs::path& baseDir,
                                    std::string_view url, std::string& why) {
    UrlTarget target;
    std::string_view rest = url;
    if (const std::size_t hash = rest.find('#'); hash != std::string_view::npos) {
        target.fragment = std::string(rest.substr(hash + 1));
        rest = rest.substr(0, hash);
    }
    const std::string_view scheme = schemeOf(rest);
    if (scheme == "file") {
        rest.remove_prefix(5);
        if (rest.starts_with("//")) rest.remove_prefix(2); // file:///abs or file://localhost/abs
        if (rest.starts_with("localhost/")) rest.remove_prefix(9);
    } else if (!scheme.empty()) {
        why = "not fetched: FunctionLab never uses the network (put the file beside the scene "
              "and name it by a relative path)";
        return std::nullopt;
    }
    if (rest.empty()) {
        why = "names no file";
        return std::nullopt;
    }
    std::string pathText = percentDecoded(rest);
    for (char& c : pathText)
        if (c == '\\') c = '/';
    const fs::path named(pathText);
    std::error_code ec;
    const fs::path file = fs::weakly_canonical(named.is_absolute() ? named : baseDir / named, ec);
    if (ec || !inside(context.root, file)) {
        why =
            "outside the scene's folder: only files in the folder of the scene and below are read";
        return std::nullopt;
    }
    if (!fs::is_regular_file(file, ec)) {
        why = "no such file";
        return std::nullopt;
    }
    target.file = file;
    return target;
}

ReferenceLoader::ReferenceLoader(ReferenceContext* context, Scene& scene, fs::path baseDir,
                                 const ReadOptions& options,
                                 std::vector<SceneDiagnostic>& diagnostics)
    : context_(context), scene_(scene), baseDir_(std::move(baseDir)), options_(options),
      diagnostics_(diagnostics) {}

Scene* ReferenceLoader::load(const fs::path& file, std::string& why) {
    if (auto it = loaded_.find(file); it != loaded_.end()) {
        if (!it->second) why = "it could not be read (see the warnings above)";
        return it->second;
    }
    ReferenceContext& c = *context_;
    for (const fs::path& open : c.loading)
        if (open == file) {
            why = "it includes itself (a cycle of references)";
            return nullptr;
        }
    if (c.loading.size() > options_.limits.maxInlineDepth) {
        why =
            "references nest more than " + std::to_string(options_.limits.maxInlineDepth) + " deep";
        return nullptr;
    }
    if (c.filesRead >= options_.limits.maxInlineFiles) {
        why = "the scene already pulled in " + std::to_string(options_.limits.maxInlineFiles) +
              " files";
        return nullptr;
    }
    ++c.filesRead;
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    const auto size = fs::file_size(file, ec);
    if (!in || ec) {
        why = "it cannot be opened";
        loaded_[file] = nullptr;
        return nullptr;
    }
    if (size > options_.limits.maxFileBytes) {
        why = "it is larger than " + byteSizeText(options_.limits.maxFileBytes);
        loaded_[file] = nullptr;
        return nullptr;
    }
    if (c.bytesRead + size > options_.limits.maxDecodedBytes) {
        why = "the scene's files together would exceed " +
              byteSizeText(options_.limits.maxDecodedBytes);
        loaded_[file] = nullptr;
        return nullptr;
    }
    c.bytesRead += size;
    std::ostringstream bytes;
    bytes << in.rdbuf();
    const std::string display = (c.displayRoot / file.lexically_relative(c.root)).string();
    c.loading.push_back(file);
    ReadResult child =
        readSceneIn(std::move(bytes).str(), display, options_, context_, file.parent_path());
    c.loading.pop_back();
    // The referenced file's problems are the referring scene's warnings: it
    // still opens without them.
    for (SceneDiagnostic& d : child.diagnostics) {
        d.severity = Severity::Warning;
        diagnostics_.push_back(std::move(d));
    }
    if (!child.scene) {
        why = "it has errors (see the warnings above)";
        loaded_[file] = nullptr;
        return nullptr;
    }
    if (c.nodesRead + child.scene->nodeCount() > options_.limits.maxNodes) {
        why = "the scene's files together would hold more than " +
              std::to_string(options_.limits.maxNodes) + " nodes";
        loaded_[file] = nullptr;
        return nullptr;
    }
    c.nodesRead += child.scene->nodeCount();
    // One file table for the whole tree: the child's files join ours.
    const int offset = int(scene_.files.size());
    for (SourceFile& f : child.scene->files)
        scene_.files.push_back(std::move(f));
    child.scene->files.clear();
    child.scene->shiftFileIndices(offset);
    Scene* raw = child.scene.get();
    scene_.referenced.push_back(std::move(child.scene));
    loaded_[file] = raw;
    return raw;
}

std::string
ReferenceLoader::tryUrls(const std::vector<std::string>& urls,
                         const std::function<bool(Scene&, const UrlTarget&, std::string&)>& use) {
    if (!context_) return "the scene was not read from a file, so its urls cannot be followed";
    if (urls.empty()) return "it has no url";
    std::string reasons;
    for (const std::string& url : urls) {
        std::string why;
        if (auto target = resolveUrl(*context_, baseDir_, url, why)) {
            if (Scene* s = load(target->file, why))
                if (use(*s, *target, why)) return {};
        }
        reasons += (reasons.empty() ? "" : "; ") + inQuotes(url) + ": " + why;
    }
    return reasons;
}

std::string ReferenceLoader::resolveExternProto(ProtoDeclaration& proto) {
    return tryUrls(proto.urls, [&](Scene& s, const UrlTarget& target, std::string& why) {
        const ProtoDeclaration* found = nullptr;
        for (const ProtoDeclaration* p : s.protos)
            if (target.fragment.empty() ? true : p->name == target.fragment) {
                found = p; // without a #name, the first PROTO of the file (VRML97 §4.9.3)
                break;
            }
        if (!found) {
            why = target.fragment.empty() ? "the file declares no PROTO"
                                          : "the file declares no PROTO " + target.fragment;
            return false;
        }
        const ProtoDeclaration& definition = found->definition();
        if (definition.external) {
            why = "PROTO " + found->name + " there is itself an EXTERNPROTO that was not loaded";
            return false;
        }
        for (const FieldDeclaration& d : proto.interface) {
            const FieldDeclaration* match = definition.interfaceField(d.name);
            if (!match || match->type != d.type || match->access != d.access) {
                why = "PROTO " + found->name + " there has no " +
                      std::string(accessTypeName(d.access)) + " " +
                      std::string(fieldTypeName(d.type)) + " " + d.name;
                return false;
            }
        }
        proto.resolved = &definition;
        return true;
    });
}

void ReferenceLoader::resolveInlines() {
    std::vector<Node*> inlines;
    scene_.forEachNode([&](Node& n) {
        if (n.kind() == scene::NodeKind::Inline && n.spec && !n.inProtoBody &&
            boolField(n, "load") &&
            !stringsField(n, "url").empty()) // no url: nothing to show, nothing wrong
            inlines.push_back(&n);
    });
    for (Node* n : inlines) {
        const std::string why =
            tryUrls(stringsField(*n, "url"), [&](Scene& s, const UrlTarget&, std::string&) {
                n->inlined = &s;
                return true;
            });
        if (why.empty()) continue;
        diagnostics_.push_back({Severity::Warning,
                                scene_.pathOf(n->file),
                                n->where,
                                "Inline not loaded: " + why + "; it shows nothing",
                                {}});
    }
}

} // namespace fl::scene
