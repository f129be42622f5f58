#pragma once
// The instructor's signature on a gradebook's log (Ed25519, libsodium): a
// secret key kept outside the gradebook signs the log's head; anyone with the
// public key checks that the log up to there is the one the instructor had.
// Keys travel as hex text: a secret key file holds one line of 128 hex
// digits (libsodium's 64-byte secret key), its public key 64.
#include <optional>
#include <string>
#include <string_view>

namespace fl::grading {

struct SigningKey {
    std::string secretHex; // 128 hex digits
    std::string publicHex; // 64 hex digits
};

// A new key pair.
SigningKey newSigningKey();

// Writes the secret key to `path` (created, mode 0600; an existing file is
// never overwritten) and its public key to `path`.pub. False with `why`.
bool writeSigningKey(const SigningKey& key, const std::string& path, std::string& why);

// Reads a secret key file; nullopt with `why` (missing, not a key, readable
// by others).
std::optional<SigningKey> readSigningKey(const std::string& path, std::string& why);

// A public key given as 64 hex digits, or as a file holding them; nullopt
// with `why`.
std::optional<std::string> readPublicKey(std::string_view textOrPath, std::string& why);

// The signature (128 hex digits) of `message`.
std::string sign(const SigningKey& key, std::string_view message);
bool signatureHolds(std::string_view publicHex, std::string_view message,
                    std::string_view signatureHex);

// Where a signing key is looked for when a command is not told: the
// FUNCTIONLAB_GRADING_KEY environment variable, else
// ~/.config/functionlab/grading.key when it exists; empty when neither.
std::string defaultSigningKeyPath();

} // namespace fl::grading
