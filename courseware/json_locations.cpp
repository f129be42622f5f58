#include "json_locations.h"

#include <cctype>

namespace fl::courseware {
namespace {

class Scanner {
  public:
    Scanner(std::string_view text, std::map<std::string, std::size_t>& out) : s_(text), out_(out) {}

    void run() { value("", 0); }

  private:
    void space() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_])))
            ++i_;
    }
    // A string's content (escapes kept as written: keys are plain words).
    std::string string() {
        std::string v;
        if (i_ >= s_.size() || s_[i_] != '"') return v;
        for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_) {
            if (s_[i_] == '\\' && i_ + 1 < s_.size()) ++i_;
            v += s_[i_];
        }
        ++i_;
        return v;
    }
    // RFC 6901: ~ and / inside a key are escaped.
    static std::string escaped(const std::string& key) {
        std::string out;
        for (char c : key)
            out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        return out;
    }
    void value(const std::string& pointer, int depth) {
        space();
        if (i_ >= s_.size() || depth > 64) return;
        out_[pointer] = i_;
        const char c = s_[i_];
        if (c == '{' || c == '[') {
            members(pointer, depth, c == '{');
        } else if (c == '"') {
            string();
        } else {
            while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) &&
                   s_[i_] != ',' && s_[i_] != '}' && s_[i_] != ']')
                ++i_;
        }
    }

    // The members of an object ("key": value, ...) or the items of an array.
    void members(const std::string& pointer, int depth, bool object) {
        const char close = object ? '}' : ']';
        ++i_;
        int index = 0;
        for (space(); i_ < s_.size() && s_[i_] != close; space()) {
            const std::size_t start = i_;
            std::string name = std::to_string(index++);
            if (object) {
                name = escaped(string());
                space();
                if (i_ < s_.size() && s_[i_] == ':') ++i_;
            }
            value(pointer + "/" + name, depth + 1);
            space();
            if (i_ < s_.size() && s_[i_] == ',')
                ++i_;
            else
                break;
            if (i_ == start) break; // text Qt would have refused: stop, never spin
        }
        ++i_;
    }

    std::string_view s_;
    std::map<std::string, std::size_t>& out_;
    std::size_t i_ = 0;
};

} // namespace

JsonLocations::JsonLocations(std::string_view text) : text_(text) {
    Scanner(text, offsets_).run();
}

TextPosition JsonLocations::at(std::size_t offset) const {
    TextPosition p;
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
        if (text_[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) {
            ++p.column; // columns count characters, not UTF-8 bytes
        }
    }
    return p;
}

TextPosition JsonLocations::of(const std::string& pointer) const {
    for (std::string p = pointer;; p = p.substr(0, p.rfind('/'))) {
        if (auto it = offsets_.find(p); it != offsets_.end()) return at(it->second);
        if (p.empty()) return {};
    }
}

} // namespace fl::courseware
