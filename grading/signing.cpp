#include "signing.h"

#include <sodium.h>

#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fl::grading {

namespace {

bool ready() {
    static const bool ok = ::sodium_init() >= 0;
    return ok;
}

std::string hex(const unsigned char* bytes, std::size_t n) {
    std::string out(n * 2 + 1, '\0');
    ::sodium_bin2hex(out.data(), out.size(), bytes, n);
    out.pop_back();
    return out;
}

std::optional<std::vector<unsigned char>> bytesOf(std::string_view hexText, std::size_t n) {
    if (hexText.size() != n * 2) return std::nullopt;
    std::vector<unsigned char> out(n);
    std::size_t length = 0;
    if (::sodium_hex2bin(out.data(), n, hexText.data(), hexText.size(), nullptr, &length,
                         nullptr) != 0 ||
        length != n)
        return std::nullopt;
    return out;
}

std::string firstLine(const std::string& path, bool& readable) {
    std::ifstream in(path);
    readable = bool(in);
    std::string line;
    std::getline(in, line);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
        line.pop_back();
    return line;
}

} // namespace

SigningKey newSigningKey() {
    ready();
    unsigned char pk[crypto_sign_PUBLICKEYBYTES], sk[crypto_sign_SECRETKEYBYTES];
    ::crypto_sign_keypair(pk, sk);
    SigningKey key{hex(sk, sizeof sk), hex(pk, sizeof pk)};
    ::sodium_memzero(sk, sizeof sk);
    return key;
}

bool writeSigningKey(const SigningKey& key, const std::string& path, std::string& why) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        why = std::filesystem::exists(path) ? path + " exists; a key is never overwritten"
                                            : "cannot create " + path;
        return false;
    }
    const std::string text = key.secretHex + "\n";
    const bool written = ::write(fd, text.data(), text.size()) == ssize_t(text.size());
    ::close(fd);
    std::ofstream pub(path + ".pub");
    pub << key.publicHex << "\n";
    if (!written || !pub) {
        why = "cannot write " + path + " and " + path + ".pub";
        return false;
    }
    return true;
}

std::optional<SigningKey> readSigningKey(const std::string& path, std::string& why) {
    ready();
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        why = "no signing key at " + path + " (functionlab grade key new makes one)";
        return std::nullopt;
    }
    if (st.st_mode & (S_IRWXG | S_IRWXO)) {
        why = path + " can be read by others: chmod 600 it (it is a secret)";
        return std::nullopt;
    }
    bool readable = false;
    const std::string text = firstLine(path, readable);
    const auto sk = bytesOf(text, crypto_sign_SECRETKEYBYTES);
    if (!readable || !sk) {
        why = path + " is not a signing key (one line of " +
              std::to_string(2 * crypto_sign_SECRETKEYBYTES) + " hex digits)";
        return std::nullopt;
    }
    unsigned char pk[crypto_sign_PUBLICKEYBYTES];
    ::crypto_sign_ed25519_sk_to_pk(pk, sk->data());
    return SigningKey{text, hex(pk, sizeof pk)};
}

std::optional<std::string> readPublicKey(std::string_view textOrPath, std::string& why) {
    std::string text(textOrPath);
    if (!bytesOf(text, crypto_sign_PUBLICKEYBYTES)) {
        bool readable = false;
        text = firstLine(std::string(textOrPath), readable);
        if (!readable) {
            why = "'" + std::string(textOrPath) + "' is neither a public key (" +
                  std::to_string(2 * crypto_sign_PUBLICKEYBYTES) + " hex digits) nor a file";
            return std::nullopt;
        }
    }
    if (!bytesOf(text, crypto_sign_PUBLICKEYBYTES)) {
        why = "not a public key: " + std::to_string(2 * crypto_sign_PUBLICKEYBYTES) +
              " hex digits are needed";
        return std::nullopt;
    }
    return text;
}

std::string sign(const SigningKey& key, std::string_view message) {
    ready();
    const auto sk = bytesOf(key.secretHex, crypto_sign_SECRETKEYBYTES);
    if (!sk) return {};
    unsigned char signature[crypto_sign_BYTES];
    ::crypto_sign_detached(signature, nullptr,
                           reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                           sk->data());
    return hex(signature, sizeof signature);
}

bool signatureHolds(std::string_view publicHex, std::string_view message,
                    std::string_view signatureHex) {
    ready();
    const auto pk = bytesOf(publicHex, crypto_sign_PUBLICKEYBYTES);
    const auto signature = bytesOf(signatureHex, crypto_sign_BYTES);
    return pk && signature &&
           ::crypto_sign_verify_detached(signature->data(),
                                         reinterpret_cast<const unsigned char*>(message.data()),
                                         message.size(), pk->data()) == 0;
}

std::string defaultSigningKeyPath() {
    if (const char* env = std::getenv("FUNCTIONLAB_GRADING_KEY"); env && *env) return env;
    if (const char* home = std::getenv("HOME"); home && *home) {
        const std::string path = std::string(home) + "/.config/functionlab/grading.key";
        if (std::filesystem::exists(path)) return path;
    }
    return {};
}

} // namespace fl::grading
