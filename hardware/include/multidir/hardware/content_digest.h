#pragma once
// A file's content as it was checked: `multidir run` takes the SHA-256 of every step's G-code when it checks
// it (before the first move), and the printer links compare the bytes they are about to send with it, so a
// file replaced in between (hours may pass before its step comes up) is never printed unchecked. SHA-256
// (FIPS 180-4) rather than a checksum: the file may be replaced on purpose, by someone who could also make
// a CRC match.
#include <string>
#include <string_view>

namespace multidir::hardware {

// The SHA-256 of `bytes` as 64 lower-case hexadecimal digits.
[[nodiscard]] std::string sha256Hex(std::string_view bytes);

}  // namespace multidir::hardware
