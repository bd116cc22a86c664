// The cost table's stereo entries after matching: the left-right check, the fill and the median,
// as compiled occam (code notation: work_listing.hpp).

#include "costs/work_listing.hpp"

#include <array>

namespace marsokhod::nav_program::detail {
namespace {

using nav::Work;

// Workspace slots are small numbers (one-byte ldl/stl), as oc gives a PROC's first locals; the
// replicator's index is slot 0 and its count slot 1 (OCCAM_COSTS.md section 1). A loop's `ldc`
// operand is the byte length of its body, 16..255 here: one prefix byte.
constexpr std::array kStereo = {
    WorkListing{
        Work::consistency_check,
        R"(-- dl, dr: left and right disparities of the line (BYTE); ok: the validity row
SEQ x = 0 FOR W
  INT d, r :
  SEQ
    d := INT dl[x]
    r := x - d
    IF
      r < 0
        ok[x] := 0(BYTE)
      (((INT dr[r]) - d) > tol) OR ((d - (INT dr[r])) > tol)
        ok[x] := 0(BYTE)
      TRUE
        ok[x] := 255(BYTE))",
        "ldl 0; ldl 5; bsub; lb*; stl 3                                 -- d := INT dl[x]\n"
        "ldl 0; ldl 3; sub; stl 4                                       -- r := x - d\n"
        "ldc 0; ldl 4; gt; cj_taken 10                                  -- r < 0: no\n"
        "ldl 4; ldc 128; csub0; ldl 6; bsub; lb*; ldl 3; sub; ldl 7; gt; eqc 0; cj_not_taken 13\n"
        "ldl 3; ldl 4; ldc 128; csub0; ldl 6; bsub; lb*; sub; ldl 7; gt; cj_taken 10\n"
        "ldc 255; ldl 0; ldl 8; bsub; sb*                               -- ok[x] := 255\n"
        "ldlp 0; ldc 90; lend_loop",
        "[I] from OCCAM_COSTS.md section 1: IF compare 7 (+2 when cj jumps), row[r] checked "
        "(csub0), dr[r] loaded twice (no common subexpressions, no hoisting [X]), loop 13-14. "
        "Assumed: the pixel passes, so each test falls through to the next branch, and OR "
        "compiles to one cj per operand (not traced)."},
    WorkListing{
        Work::fill_pixel,
        R"(-- the scan counts a run of unreliable pixels; at its end the run is filled
SEQ x = 0 FOR W
  IF
    ok[x] = 0(BYTE)
      n := n + 1
    ...  -- a reliable pixel: fill the run before it, start a new one
SEQ i = start FOR n       -- one pass of this loop per pixel written
  d.row[i] := v           -- v: the farther (smaller) of the run's two ends)",
        "ldl 0; ldl 5; bsub; lb*; eqc 0; cj_not_taken 10                -- ok[x] = 0: yes\n"
        "ldl 3; adc 1; stl 3; j 60                                      -- n := n + 1\n"
        "ldlp 0; ldc 70; lend_loop                                      -- the scan's loop\n"
        "ldl 4; ldl 0; ldc 128; csub0; ldl 6; wsub; stnl* 0             -- d.row[i] := v\n"
        "ldlp 0; ldc 13; lend_loop                                      -- the fill's loop",
        "[I] from OCCAM_COSTS.md section 1 (ba[i] 10 cycles, M3; IF, loop 13-14); a REAL32 "
        "copy is a word move with ldnl/stnl, as an occam-probe trace shows [X]. A written "
        "pixel passes through two loops, the scan and the fill, so its unit holds two loop "
        "ends. nav reports only the pixels written; the scan over reliable pixels is not "
        "reported, so it is not charged."},
    WorkListing{
        Work::median_pixel,
        R"(-- up, here, down: disparity rows y-1, y, y+1; lo, mi, hi: the rows of sorted columns
SEQ x = 1 FOR W-2
  REAL32 a, b, c, l, m, h, t :
  SEQ
    a := up[x+1]
    ...  -- b := here[x+1]; c := down[x+1]; sort a, b, c: IF a > b (swap) and so on
    lo[x+1] := a
    ...  -- mi[x+1] := b; hi[x+1] := c
    l := lo[x-1]
    IF
      lo[x] > l
        l := lo[x]
      TRUE
        SKIP
    ...  -- lo[x+1]; h, the smallest hi; m, the middle of mi[x-1..x+1]
    ...  -- median := the middle of l, m, h
    out[x] := median)",
        "ldl 0; adc 1; ldc 128; csub0; ldl 5; wsub; ldnl* 0; stl 3      -- a := up[x+1]\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 6; wsub; ldnl* 0; stl 4      -- b\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 7; wsub; ldnl* 0; stl 5      -- c\n"
        "ldlp 3; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_taken 8 -- sorted: no swap\n"
        "ldlp 4; fpldnlsn; ldlp 5; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldlp 3; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldl 3; ldl 0; adc 1; ldc 128; csub0; ldl 8; wsub; stnl* 0      -- lo[x+1] := a\n"
        "ldl 4; ldl 0; adc 1; ldc 128; csub0; ldl 9; wsub; stnl* 0      -- mi[x+1] := b\n"
        "ldl 5; ldl 0; adc 1; ldc 128; csub0; ldl 10; wsub; stnl* 0     -- hi[x+1] := c\n"
        "ldl 0; adc -1; ldc 128; csub0; ldl 8; wsub; ldnl* 0; stl 11    -- l := lo[x-1]\n"
        "ldl 0; ldl 8; fpldnlsni*; ldlp 11; fpldnlsn; fpgt; fpchkerr; cj_not_taken 8\n"
        "ldl 0; ldl 8; wsub; ldnl* 0; stl 11                            -- l := lo[x]\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 8; fpldnlsni*; ldlp 11; fpldnlsn; fpgt; fpchkerr\n"
        "cj_taken 8                                                     -- lo[x+1]: no\n"
        "ldl 0; adc -1; ldc 128; csub0; ldl 10; wsub; ldnl* 0; stl 12   -- h, the same\n"
        "ldl 0; ldl 10; fpldnlsni*; ldlp 12; fpldnlsn; fpgt; fpchkerr; cj_not_taken 8\n"
        "ldl 0; ldl 10; wsub; ldnl* 0; stl 12\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 10; fpldnlsni*; ldlp 12; fpldnlsn; fpgt; fpchkerr\n"
        "cj_taken 8\n"
        "ldl 0; adc -1; ldc 128; csub0; ldl 9; wsub; ldnl* 0; stl 3     -- m: mi[x-1..x+1]\n"
        "ldl 0; ldl 9; wsub; ldnl* 0; stl 4\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 9; wsub; ldnl* 0; stl 5\n"
        "ldlp 3; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_not_taken 8\n"
        "ldl 3; stl 13; ldl 4; stl 3; ldl 13; stl 4                     -- swap\n"
        "ldlp 4; fpldnlsn; ldlp 5; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldlp 3; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldlp 11; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_not_taken 8  -- of l, m, h\n"
        "ldl 11; stl 4\n"
        "ldlp 4; fpldnlsn; ldlp 12; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldlp 11; fpldnlsn; ldlp 4; fpldnlsn; fpgt; fpchkerr; cj_taken 8\n"
        "ldl 4; ldl 0; ldl 14; wsub; stnl* 0                            -- out[x] := m\n"
        "ldlp 0; ldc 240; lend_loop",
        "[I] from OCCAM_COSTS.md section 1 and occam-probe traces [X] of the REAL32 idioms: a "
        "REAL32 copy is a word move (ldnl/stl), a comparison loads both values onto the FPU "
        "(fpldnlsni for an element) and is followed by fpchkerr before its cj. The median of "
        "nine from sorted columns as nav computes it (Paeth): each pixel sorts one new column "
        "and merges three. Assumed: the columns come sorted (disparity grows down the image), "
        "one comparison in each group of three changes its value."},
};

} // namespace

std::span<const WorkListing> stereo_listings() {
  return kStereo;
}

} // namespace marsokhod::nav_program::detail
