// The cost table's feature and matching entries: census features, pyramid, search ranges, window
// costs, the scan-line programme and the choice of disparity, as compiled occam (code notation:
// work_listing.hpp).

#include "costs/work_listing.hpp"

#include <array>

namespace marsokhod::nav_program::detail {
namespace {

using nav::Work;

// Workspace slots are small numbers (one-byte ldl/stl), as oc gives a PROC's first locals; the
// replicator's index is slot 0 and its count slot 1 (OCCAM_COSTS.md section 1). A loop's `ldc`
// operand is the byte length of its body, 16..255 here: one prefix byte.
constexpr std::array kMatching = {
    WorkListing{
        Work::feature_pixel,
        R"(-- a, h, b: image rows y-1, y, y+1 (VAL []BYTE); f: the census row
SEQ x = 1 FOR W-2
  INT c, bits :
  SEQ
    c := INT h[x]
    bits := INT (c > (INT a[x-1]))
    bits := (bits << 1) \/ (INT (c > (INT a[x])))
    ...  -- the same for a[x+1], h[x-1], h[x+1], b[x-1], b[x], b[x+1]
    f[x] := BYTE bits)",
        "ldl 0; ldl 6; bsub; lb*; stl 3                                 -- c := INT h[x]\n"
        "ldl 3; ldl 0; adc -1; ldc 128; csub0; ldl 5; bsub; lb*; gt; stl 4  -- a[x-1]\n"
        "ldl 3; ldl 0; ldl 5; bsub; lb*; gt; ldl 4; ldc 1; shl 1; or; stl 4  -- a[x]\n"
        "ldl 3; ldl 0; adc 1; ldc 128; csub0; ldl 5; bsub; lb*; gt\n"
        "ldl 4; ldc 1; shl 1; or; stl 4                                 -- a[x+1]\n"
        "ldl 3; ldl 0; adc -1; ldc 128; csub0; ldl 6; bsub; lb*; gt\n"
        "ldl 4; ldc 1; shl 1; or; stl 4                                 -- h[x-1]\n"
        "ldl 3; ldl 0; adc 1; ldc 128; csub0; ldl 6; bsub; lb*; gt\n"
        "ldl 4; ldc 1; shl 1; or; stl 4                                 -- h[x+1]\n"
        "ldl 3; ldl 0; adc -1; ldc 128; csub0; ldl 7; bsub; lb*; gt\n"
        "ldl 4; ldc 1; shl 1; or; stl 4                                 -- b[x-1]\n"
        "ldl 3; ldl 0; ldl 7; bsub; lb*; gt; ldl 4; ldc 1; shl 1; or; stl 4  -- b[x]\n"
        "ldl 3; ldl 0; adc 1; ldc 128; csub0; ldl 7; bsub; lb*; gt\n"
        "ldl 4; ldc 1; shl 1; or; stl 4                                 -- b[x+1]\n"
        "ldl 4; ldc 256; csub0; ldl 0; ldl 8; bsub; sb*                 -- f[x] := BYTE bits\n"
        "ldlp 0; ldc 180; lend_loop",
        "[I] from OCCAM_COSTS.md section 1: row abbreviations, csub0 on every offset subscript "
        "(row[x+dx], 18 cycles [X]), none on a plain index of a constant-range replicator (M3 "
        "[X]), BYTE conversion checked (M8 [X]), loop 13-14. The branch-free "
        "bits := (bits << 1) \\/ (INT (c > n)) and the csub0 on a[x-1] in a constant range were "
        "read in an occam-probe trace [X]. Unit: one byte of nav's census3x3 feature."},
    WorkListing{
        Work::pyramid_pixel,
        R"(-- t, b: image rows 2y, 2y+1 (VAL []BYTE); h: the half-size row
SEQ x = 0 FOR W/2
  INT x2, s :
  SEQ
    x2 := x << 1
    s := (INT t[x2]) + (INT t[x2+1])
    s := (s + (INT b[x2])) + (INT b[x2+1])
    h[x] := BYTE ((s + 2) >> 2))",
        "ldl 0; ldc 1; shl 1; stl 3                                     -- x2 := x << 1\n"
        "ldl 3; ldc 128; csub0; ldl 5; bsub; lb*\n"
        "ldl 3; adc 1; ldc 128; csub0; ldl 5; bsub; lb*; add; stl 4     -- s := t[x2] + t[x2+1]\n"
        "ldl 4; ldl 3; ldc 128; csub0; ldl 6; bsub; lb*; add\n"
        "ldl 3; adc 1; ldc 128; csub0; ldl 6; bsub; lb*; add; stl 4     -- + b[x2] + b[x2+1]\n"
        "ldl 4; adc 2; ldc 2; shr 2; ldc 256; csub0; ldl 0; ldl 7; bsub; sb*  -- h[x] := ...\n"
        "ldlp 0; ldc 80; lend_loop",
        "[I] from OCCAM_COSTS.md section 1 (row[x+dx] with csub0, 18 cycles; BYTE conversion "
        "checked, M8; loop 13-14). Two statements into s, because oc keeps no more than three "
        "values on the stack. Unit: one pixel of halve_image (remove_vertical_parallax reports "
        "the same unit for its interpolated pixel: a few loads and one store too)."},
    WorkListing{
        Work::search_range_pixel,
        R"(-- c.row: the coarser layer's disparities of row y >> 1 (VAL []BYTE, 64 wide)
SEQ x = 0 FOR W
  INT c :
  SEQ
    c := (INT c.row[x >> 1]) << 1
    IF
      c < band
        lo[x] := 0
      TRUE
        lo[x] := c - band
    hi[x] := c + band)",
        "ldl 0; ldc 1; shr 1; ldc 64; csub0; ldl 5; bsub; lb*; ldc 1; shl 1; stl 3  -- c\n"
        "ldl 4; ldl 3; gt; cj_taken 12                                  -- IF c < band: no\n"
        "ldl 3; ldl 4; sub; ldl 0; ldl 6; wsub; stnl* 0                 -- lo[x] := c - band\n"
        "ldl 3; ldl 4; add; ldl 0; ldl 7; wsub; stnl* 0                 -- hi[x] := c + band\n"
        "ldlp 0; ldc 50; lend_loop",
        "[I] from OCCAM_COSTS.md section 1 (IF compare 7, +2 when cj jumps; INT array store "
        "unchecked on a plain index, M2); the csub0 on c.row[x >> 1] was read in an occam-probe "
        "trace [X]. Assumed: the window does not reach 0. Approximation: nav widens each 8-pixel "
        "tile's window to the extremes of the 3x3 coarse neighbourhood; the period occam takes "
        "the pixel's own coarse disparity."},
    WorkListing{
        Work::column_distance,
        R"(-- l0, l1, l2 / r0, r1, r2: census rows y-1, y, y+1, left / right (VAL []BYTE)
SEQ x = d FOR W-d
  INT c :
  SEQ
    c := BITCOUNT ((INT l0[x]) >< (INT r0[x-d]), 0)
    c := BITCOUNT ((INT l1[x]) >< (INT r1[x-d]), c)
    col[x] := BITCOUNT ((INT l2[x]) >< (INT r2[x-d]), c))",
        "ldl 0; ldc 128; csub0; ldl 5; bsub; lb*\n"
        "ldl 0; ldl 2; sub; ldc 128; csub0; ldl 8; bsub; lb*; xor; ldc 0; rev; bitcnt 6; stl 3\n"
        "ldl 0; ldc 128; csub0; ldl 6; bsub; lb*\n"
        "ldl 0; ldl 2; sub; ldc 128; csub0; ldl 9; bsub; lb*; xor; ldl 3; rev; bitcnt 6; stl 3\n"
        "ldl 0; ldc 128; csub0; ldl 7; bsub; lb*\n"
        "ldl 0; ldl 2; sub; ldc 128; csub0; ldl 10; bsub; lb*; xor; ldl 3; rev; bitcnt 6\n"
        "ldl 0; ldc 128; csub0; ldl 11; wsub; stnl* 0                  -- col[x] := ...\n"
        "ldlp 0; ldc 87; lend_loop",
        "[X] instruction stream: an occam-probe trace of this loop (the box kernel of "
        "OCCAM_COSTS.md with BITCOUNT of the census bytes for |L-R|; BITCOUNT is inline bitcnt): "
        "65 instructions, 65.5 and 152.4 cycles per unit measured with the row set-up, the kit "
        "pricing bitcnt at 2. [I] bitcnt is b+2 with b = 6, the mean highest bit of a random "
        "byte: 169 cycles. Box form of OCCAM_COSTS.md section 2: 121 instructions, 285 cycles "
        "per pixel x disparity for one |L-R| column and one row sum; nav counts 10 column "
        "distances per 8 candidates (each 8-pixel tile recomputes the 2 columns at its edges)."},
    WorkListing{
        Work::match_candidate,
        R"(-- col: the column distances at disparity d; cost: [W][ND]INT, the band's costs
SEQ x = d+1 FOR (W-d)-2
  []INT cx IS cost[x] :
  cx[d] := (col[x-1] + col[x]) + col[x+1])",
        "ldl 0; ldc 128; csub0; bcnt; bcnt; ldl 12; wsub; stl 3        -- cx IS cost[x]\n"
        "ldl 0; adc -1; ldc 128; csub0; ldl 11; wsub; ldnl* 0\n"
        "ldl 0; ldc 128; csub0; ldl 11; wsub; ldnl* 0; add\n"
        "ldl 0; adc 1; ldc 128; csub0; ldl 11; wsub; ldnl* 0; add\n"
        "ldl 2; ldl 3; wsub; stnl* 0                                    -- cx[d] := ...\n"
        "ldlp 0; ldc 50; lend_loop",
        "[X] an occam-probe trace of this loop: 37 instructions, 84.1 cycles per unit measured "
        "(cost[x] scaled by bcnt; bcnt, cx[d] unchecked: d is the outer replicator, of constant "
        "range). With column_distance weighted as nav reports them (10 per 8 candidates): "
        "1.25 x 169 + 84 = 295 cycles per pixel x disparity, 3.6 % above the 285 of the box "
        "form in OCCAM_COSTS.md section 2, which differs in comparing |L-R| and keeping the "
        "running minimum instead of storing the cost."},
    WorkListing{
        Work::dp_transition,
        R"(-- prev, cur: [ND+2]INT path costs of pixels x-1 and x (guards at 0 and ND+1);
-- cx: pixel x's costs; m.prev: prev's smallest; p1, p2: small and large step penalties
SEQ d = 0 FOR ND
  INT m :
  SEQ
    m := prev[d+1]
    IF
      (prev[d] + p1) < m
        m := prev[d] + p1
      TRUE
        SKIP
    ...  -- the same for prev[d+2] + p1, then for m.prev + p2
    m := (m - m.prev) + cx[d]
    cur[d+1] := m
    IF
      m < m.cur
        m.cur := m
      TRUE
        SKIP)",
        "ldl 0; adc 1; ldc 18; csub0; ldl 5; wsub; ldnl* 0; stl 3        -- m := prev[d+1]\n"
        "ldl 3; ldl 0; ldl 5; wsub; ldnl* 0; ldl 7; add; gt; cj_taken 12  -- prev[d]: no\n"
        "ldl 3; ldl 0; adc 2; ldc 18; csub0; ldl 5; wsub; ldnl* 0; ldl 7; add; gt\n"
        "cj_not_taken 14                                                -- prev[d+2]: yes\n"
        "ldl 0; adc 2; ldc 18; csub0; ldl 5; wsub; ldnl* 0; ldl 7; add; stl 3\n"
        "ldl 3; ldl 9; ldl 8; add; gt; cj_taken 6                       -- m.prev + p2: no\n"
        "ldl 3; ldl 9; sub; ldl 0; ldl 6; wsub; ldnl* 0; add; stl 3\n"
        "ldl 3; ldl 0; adc 1; ldc 18; csub0; ldl 4; wsub; stnl* 0       -- cur[d+1] := m\n"
        "ldl 10; ldl 3; gt; cj_taken 4                                  -- m < m.cur: no\n"
        "ldlp 0; ldc 140; lend_loop",
        "[X] an occam-probe trace of this loop, one pass over 128 x 127 pixels x 16 states of "
        "synthetic costs: 68.3 instructions, 142.5 cycles per state; here 69 and 143, with "
        "the outcomes assumed: one of the three ways in beats staying, the running minimum "
        "stays. OCCAM_COSTS.md section 2 dp (3-way min and a back-pointer): 69 instructions, "
        "150 cycles per pixel x disparity state. One unit is one state of one pass, the dp "
        "row's unit: nav runs the programme forwards and backwards (S = Lf + Lb - C) and "
        "reports 2 transitions per candidate cell, so a cell costs two units."},
    WorkListing{
        Work::dp_backtrack,
        R"(SEQ i = 0 FOR W
  INT x :
  SEQ
    x := (W-1) - i
    d.row[x] := BYTE k
    k := INT from[x][k])",
        "ldc 127; ldl 0; sub; stl 3                                     -- x := (W-1) - i\n"
        "ldl 4; ldc 256; csub0; ldl 3; ldc 128; csub0; ldl 5; bsub; sb* -- d.row[x] := BYTE k\n"
        "ldl 3; ldc 128; csub0; bcnt; bcnt; ldl 4; ldc 16; csub0; add; ldl 6; bsub; lb*; stl 4\n"
        "ldlp 0; ldc 44; lend_loop",
        "[X] the back-track of OCCAM_COSTS.md's dp kernel as an occam-probe trace shows it: 29 "
        "instructions (from[x][k] scaled by bcnt; bcnt for rows of 16 states), 73 cycles. nav "
        "reports none: its programme runs both ways and chooses by minimum (disparity_choice); "
        "the entry prices the single-pass programme of the period."},
    WorkListing{
        Work::disparity_choice,
        R"(-- fc, bc: forward (less the cost) and backward path costs of the pixel's states
SEQ d = 0 FOR ND
  INT s :
  SEQ
    s := fc[d] + bc[d]
    IF
      s < best
        SEQ
          best := s
          best.d := d
      TRUE
        SKIP)",
        "ldl 0; ldl 5; wsub; ldnl* 0; ldl 0; ldl 6; wsub; ldnl* 0; add; stl 3  -- s\n"
        "ldl 4; ldl 3; gt; cj_taken 8                                   -- s < best: no\n"
        "ldlp 0; ldc 24; lend_loop\n"
        "-- a 16th of the pixel's own instructions (its two row abbreviations, best := MOSTPOS\n"
        "-- INT, the loop's set-up, d.row[x] := BYTE best.d: 31 instructions, 66 cycles) and of\n"
        "-- its ~2.8 changes of the best (4 instructions, 4 cycles each), in like instructions\n"
        "ldl 3; stl 4; ldl 0",
        "[I] from OCCAM_COSTS.md section 1: ia[i] unchecked on a plain index of a constant "
        "range (M2, 8 cycles), IF compare 7 (+2 when cj jumps), loop 13-14. Assumed: the best "
        "does not change (a running minimum over ND values changes about ln ND times). nav "
        "also reports one unit per candidate of the right view's choice, the same comparison."},
};

} // namespace

std::span<const WorkListing> matching_listings() {
  return kMatching;
}

} // namespace marsokhod::nav_program::detail
