// The cost table's entries as written: occam, the code oc emits for it, and the source (private).
#pragma once

#include "marsokhod/nav/work/work.hpp"

#include <span>
#include <string_view>

namespace marsokhod::nav_program::detail {

/// One unit of a nav::Work kind as a listing: the occam of the unit, the instructions compiled
/// occam executes for it, and where that comes from. work_costs.cpp counts the code into an
/// InstructionMix; the entries are split by stage so that each file stays readable.
///
/// Code notation: instructions separated by ';', each a platform-file mnemonic
/// (emulator::mnemonic: "ldl", "cj_taken", "lend_loop") with, where it has one, its operand:
///  - function codes (j, ldlp, ldnl, ldc, ldnlp, ldl, adc, call, cj_*, ajw, eqc, stl, stnl):
///    the operand as encoded; the pfix/nfix bytes it needs are counted from it (ldc 128 is
///    pfix + ldc, adc -1 is nfix + adc);
///  - prod, shl, shr, bitcnt: the units of the data-book time (b or n);
///  - other operations take none; those whose operation code is 16 or more carry one pfix
///    (csub0, lend, xor), and the FPU-entry ones (fpuabs, fpusqrt*) also their ldc selector;
///  - a '*' after the mnemonic marks an access to one of the stage's buffers.
struct WorkListing {
  nav::Work kind;
  std::string_view occam;
  std::string_view code;
  std::string_view source;
};

/// Features, pyramid, search ranges, window costs, the scan-line programme and the choice of
/// disparity (work_costs_matching.cpp).
std::span<const WorkListing> matching_listings();
/// The left-right check, the fill and the median (work_costs_stereo.cpp).
std::span<const WorkListing> stereo_listings();
/// Range, elevation, zones, path and footprint check (work_costs_map.cpp).
std::span<const WorkListing> map_listings();

} // namespace marsokhod::nav_program::detail
