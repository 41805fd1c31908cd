// Rgba: one 8-bit colour with straight (not premultiplied) alpha, as PNG files store it.
#pragma once
#include <array>
#include <cstdint>

namespace shapevo {

using Rgba = std::array<std::uint8_t, 4>;

}  // namespace shapevo
