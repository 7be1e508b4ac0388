#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits. Used to record which input
// made a file (constant/particles.vtu: the digest of system/particlesDict), not for security.

#include <string>

namespace sph
{

std::string sha256Hex(const std::string& bytes);

} // namespace sph
