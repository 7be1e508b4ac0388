#pragma once
// Small math kernels for the hot loops.

#include <cstdint>
#include <cstring>

namespace sph
{

// x^(-1/3) for 1e-30 < x < 1e30, to a few ulp (relative difference to 1/cbrt(x) below 7e-16):
// an initial guess from the bits of x as a float (about 3 % off; 32-bit integer arithmetic,
// so a loop over many x vectorises) and four Newton steps y <- y (4 - x y^3)/3, which
// converge quadratically. glibc's cbrt is an out-of-line call through frexp and ldexp, about
// twice as slow, and does not vectorise.
inline double inverseCubeRoot(double x)
{
    const float single = static_cast<float>(x);
    std::uint32_t bits;
    std::memcpy(&bits, &single, sizeof bits);
    bits = 0x54a21d2au - bits / 3u;
    float guess;
    std::memcpy(&guess, &bits, sizeof guess);
    double y = guess;
    for (int i = 0; i < 4; ++i)
    {
        y = y * (4.0 - x * y * y * y) * (1.0 / 3.0);
    }
    return y;
}

} // namespace sph
