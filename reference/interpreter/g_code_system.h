#pragma once
// The G code systems a lathe program can be written in (PROG.GSYS.* in specs/rules.json). FANUC's
// lathes have three lists, chosen by parameter 3401#6 GSB and #7 GSC (FANUC 0i-F G code list):
// system A (the default: X/Z absolute, U/W incremental, G50 coordinate setting, G90/G92/G94 the
// single cycles, G98/G99 feed per minute/revolution), system B (G90/G91 absolute/incremental, G92
// coordinate setting, G94/G95 feed modes, G98/G99 canned cycle return level, G77/G78/G79 the
// single cycles, G33 threading) and system C (as B, with G70/G71 inch/metric, the multiple
// repetitive cycles renumbered G72–G78 and the single cycles G20/G21/G24). Huazhong (seed 003) has
// a list of its own: system A's but with G90/G91 and G94/G95 as modes.
#include <cstdint>

namespace cyclecert {

enum class GCodeSystem : std::uint8_t { A, B, C, Huazhong };

inline constexpr int kGCodeSystems = 4;

}  // namespace cyclecert
