// The scan-line dynamic programme over one line of matching costs, and its penalties.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace marsokhod::nav {

/// Largest matching cost and penalty the dynamic programme accepts (16-bit path costs).
inline constexpr int kMaxMatchingCost = 255;
inline constexpr int kMaxPenalty = 255;

/// Regularisation of the scan-line dynamic programme, in units of the matching cost. A change of
/// one pixel between neighbours (a slanted surface) costs `small_step`; a larger jump (an
/// object's edge) costs `large_step`, or `large_step_at_edge` where the grey level changes by
/// more than `edge_threshold` between the two neighbours, since depth edges follow grey edges.
/// The three penalties lie within 0..kMaxPenalty.
struct DpPenalties {
  int small_step = 12;
  int large_step = 64;
  int large_step_at_edge = 16;
  int edge_threshold = 10;
};

/// The dynamic programme of the matcher on one scan line with a full table of matching costs
/// (costs[x * candidates + d] for disparities d = 0 .. candidates - 1, each within
/// 0..kMaxMatchingCost) and, optionally, the line's grey levels for the edge-dependent P2.
/// Two passes accumulate, pixel by pixel, the cheapest path cost
///   L(x, d) = C(x, d) + min(L(x-1, d), L(x-1, d+-1) + P1, min L(x-1, .) + P2) - min L(x-1, .)
/// (continuity, with penalised jumps), one from each end; each pixel takes the disparity with
/// the smallest S = L_forward + L_backward - C, the smaller one on a tie. Returns one
/// disparity per pixel. Throws std::invalid_argument for inconsistent sizes or values out of
/// range. (The matcher runs the same code on eight scan lines at once.)
std::vector<int> scanline_disparities(std::span<const std::uint16_t> costs, int width,
                                      int candidates, const DpPenalties& penalties,
                                      std::span<const std::uint8_t> intensity = {});

} // namespace marsokhod::nav
