#include "submission_hash.h"

#include <QCryptographicHash>

#include <algorithm>
#include <fstream>
#include <vector>

namespace fl::grading {
namespace {

bool addFile(QCryptographicHash& h, const std::filesystem::path& file, std::uintmax_t& total) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return false;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        const std::streamsize n = in.gcount();
        total += std::uintmax_t(n);
        if (total > (std::uintmax_t(1) << 30)) return false;
        h.addData(QByteArrayView(buffer, qsizetype(n)));
    }
    return true;
}

} // namespace

std::optional<std::string> submissionHash(const std::filesystem::path& path) {
    QCryptographicHash h(QCryptographicHash::Sha256);
    std::uintmax_t total = 0;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
        if (!addFile(h, path, total)) return std::nullopt;
        return h.result().toHex().toStdString();
    }
    if (!std::filesystem::is_directory(path, ec)) return std::nullopt;
    std::vector<std::filesystem::path> files;
    for (auto it = std::filesystem::recursive_directory_iterator(
             path, std::filesystem::directory_options::none, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_symlink(ec)) { // a link could point anywhere: its target is not hashed
            if (it->is_directory(ec)) it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file(ec)) files.push_back(it->path().lexically_relative(path));
        if (files.size() > 10000) return std::nullopt;
    }
    if (ec) return std::nullopt;
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        const std::string name = f.generic_string();
        h.addData(QByteArrayView(name.data(), qsizetype(name.size() + 1))); // with its NUL
        if (!addFile(h, path / f, total)) return std::nullopt;
    }
    return h.result().toHex().toStdString();
}

} // namespace fl::grading
