// The cost table's map entries: range, elevation, prohibited zones, the path and its footprint
// check, as compiled occam (code notation: work_listing.hpp).

#include "costs/work_listing.hpp"

#include <array>

namespace marsokhod::nav_program::detail {
namespace {

using nav::Work;

// REAL32 scalars live in the workspace and reach the FPU through their address (ldlp k;
// fpldnlsn), as oc compiles them ([X] OCCAM_COSTS.md M5 and occam-probe traces); a REAL32
// statement ends with fpchkerr before its store (HALT mode).
constexpr std::array kMap = {
    WorkListing{
        Work::range_pixel,
        R"(-- disp: the disparity row (REAL32); b: baseline x focal; uc, vc: the pixel's
-- normalised column and row; du: one column's step; f: the focal length
SEQ x = 0 FOR W
  REAL32 d :
  SEQ
    d := disp[x]
    IF
      d > 0.0(REAL32)
        SEQ
          s := b / d
          xc := s * uc
          yc := s * vc
          zc := s * f
          ...  -- the pixel's elevation_pixel
      TRUE
        SKIP
    uc := uc + du)",
        "ldl 0; ldl 5; wsub; ldnl* 0; stl 3                             -- d := disp[x]\n"
        "ldlp 3; fpldnlsn; fpldzerosn; fpgt; fpchkerr; cj_not_taken 200 -- d > 0.0: yes\n"
        "ldlp 6; fpldnlsn; ldlp 3; fpldnlsn; fpdiv; ldlp 4; fpchkerr; fpstnlsn  -- s := b / d\n"
        "ldlp 4; fpldnlsn; ldlp 7; fpldnlmulsn; ldlp 8; fpchkerr; fpstnlsn      -- xc\n"
        "ldlp 4; fpldnlsn; ldlp 9; fpldnlmulsn; ldlp 10; fpchkerr; fpstnlsn     -- yc\n"
        "ldlp 4; fpldnlsn; ldlp 11; fpldnlmulsn; ldlp 12; fpchkerr; fpstnlsn    -- zc\n"
        "ldlp 7; fpldnlsn; ldlp 13; fpldnladdsn; ldlp 7; fpchkerr; fpstnlsn     -- uc\n"
        "ldlp 0; ldc 250; lend_loop",
        "[X] the REAL32 idioms: OCCAM_COSTS.md section 1 (M5: ldlp; fpldnlsn, combined "
        "fpldnlmulsn/fpldnladdsn for a memory operand, fpchkerr before every REAL32 store) and "
        "an occam-probe trace of g := (f / g) * f; a REAL32 copy is a word move. [I] the unit: "
        "triangulation into the camera frame; the loop's control is charged here, the rest of "
        "the pixel's work (rotation, maps) to elevation_pixel, which nav reports with it."},
    WorkListing{
        Work::elevation_pixel,
        R"(-- r00 .. r22, o0 .. o2: the camera-to-level rotation (camera and rover pitch, roll)
-- and the camera's position; fw, lt, el, rg: the forward, left, elevation and range rows
X := (((r00 * xc) + (r01 * yc)) + (r02 * zc)) + o0
Y := (((r10 * xc) + (r11 * yc)) + (r12 * zc)) + o1
Z := (((r20 * xc) + (r21 * yc)) + (r22 * zc)) + o2
fw[x] := X
lt[x] := Y
el[x] := Z
rg[x] := SQRT ((X * X) + (Y * Y)))",
        "ldlp 14; fpldnlsn; ldlp 8; fpldnlmulsn; ldlp 15; fpldnlsn; ldlp 10; fpldnlmulsn\n"
        "fpadd; ldlp 16; fpldnlsn; ldlp 12; fpldnlmulsn; fpadd; ldlp 17; fpldnladdsn\n"
        "ldlp 3; fpchkerr; fpstnlsn                                     -- X\n"
        "ldlp 18; fpldnlsn; ldlp 8; fpldnlmulsn; ldlp 19; fpldnlsn; ldlp 10; fpldnlmulsn\n"
        "fpadd; ldlp 20; fpldnlsn; ldlp 12; fpldnlmulsn; fpadd; ldlp 21; fpldnladdsn\n"
        "ldlp 4; fpchkerr; fpstnlsn                                     -- Y\n"
        "ldlp 22; fpldnlsn; ldlp 8; fpldnlmulsn; ldlp 23; fpldnlsn; ldlp 10; fpldnlmulsn\n"
        "fpadd; ldlp 24; fpldnlsn; ldlp 12; fpldnlmulsn; fpadd; ldlp 25; fpldnladdsn\n"
        "ldlp 5; fpchkerr; fpstnlsn                                     -- Z\n"
        "ldl 3; ldl 0; ldl 26; wsub; stnl* 0                            -- fw[x] := X\n"
        "ldl 4; ldl 0; ldl 27; wsub; stnl* 0                            -- lt[x] := Y\n"
        "ldl 5; ldl 0; ldl 28; wsub; stnl* 0                            -- el[x] := Z\n"
        "ldlp 3; fpldnlsn; ldlp 3; fpldnlmulsn; ldlp 4; fpldnlsn; ldlp 4; fpldnlmulsn; fpadd\n"
        "fpusqrtfirst; fpusqrtstep; fpusqrtstep; fpusqrtlast            -- SQRT, inline\n"
        "ldl 0; ldl 29; wsub; fpchkerr; fpstnlsn*                       -- rg[x] := ...",
        "[X] the REAL32 idioms as for range_pixel; SQRT compiles inline to fpusqrtfirst, two "
        "fpusqrtstep and fpusqrtlast (occam-probe trace). [I] the unit: the rotation by the "
        "camera's and the rover's pitch and roll into the level frame (a full 3x3 matrix, as "
        "nav's pose), the forward, left and elevation maps and the ground range. The square "
        "root alone is 4 instructions of 119 cycles (data book), which puts this entry's "
        "cycles per instruction above the REAL32 kernels' 3.4 unless the FPU overlaps."},
    WorkListing{
        Work::hazard_test,
        R"(-- hi.in: the highest heights along the row (REAL32); hi: the window's highest so far
SEQ i = 0 FOR n - k
  IF
    hi.in[i+k] > hi[i]
      hi[i] := hi.in[i+k]
    TRUE
      SKIP)",
        "ldl 0; ldl 2; add; ldc 64; csub0; ldl 5; fpldnlsni*            -- hi.in[i+k]\n"
        "ldl 0; ldc 64; csub0; ldl 6; fpldnlsni*                        -- hi[i]\n"
        "fpgt; fpchkerr; cj_taken 18                                    -- higher: no\n"
        "ldlp 0; ldc 40; lend_loop\n"
        "-- a third of an update of the extreme (14 instructions, 27 cycles more than this\n"
        "-- path: the maximum of a window changes in about one comparison of three), in like\n"
        "-- instructions\n"
        "ldl 0; stl 3; ldl 0; stl 3; ldl 0",
        "[X] the REAL32 comparison as an occam-probe trace shows it (fpldnlsni for each "
        "element, fpgt, fpchkerr, cj); [I] subscripts checked (variable range, a 64-cell grid "
        "row), loop 13-14. The unit is one comparison of the window extremes, which make up "
        "most of nav's hazard tests (two per cell and offset); the step, slope, gap and "
        "margin rules' comparisons are of the same size. The path is the one where the extreme "
        "does not change (18 instructions, 57 cycles, as the reference kernel's trace "
        "shows), plus a third of an update (the kernel's data changed it in 44 % of "
        "comparisons, random heights would in 36 %)."},
    WorkListing{
        Work::path_relaxation,
        R"(-- e.here, e.below: elevations (REAL32) of the row and the row below; c.below: its
-- path costs; w.len: the cost of one step's length; edges from x-1, x, x+1 below
SEQ k = -1 FOR 3
  REAL32 c :
  SEQ
    c := c.below[x+k] + ((ABS (e.here[x] - e.below[x+k])) + w.len)
    IF
      c < best
        SEQ
          best := c
          from := k
      TRUE
        SKIP)",
        "ldl 2; ldl 5; fpldnlsni*                                       -- e.here[x]\n"
        "ldl 2; ldl 0; add; ldc 128; csub0; ldl 6; fpldnlsni*           -- e.below[x+k]\n"
        "fpsub; fpuabs; ldlp 8; fpldnladdsn                             -- ABS (...) + w.len\n"
        "ldl 2; ldl 0; add; ldc 128; csub0; ldl 7; wsub; fpldnladdsn*   -- c.below[x+k] + ...\n"
        "ldlp 3; fpchkerr; fpstnlsn                                     -- c := ...\n"
        "ldlp 4; fpldnlsn; ldlp 3; fpldnlsn; fpgt; fpchkerr; cj_taken 12  -- c < best: no\n"
        "ldlp 0; ldc 70; lend_loop\n"
        "-- a third of the pixel's own instructions (best and from set, the edges' loop set up,\n"
        "-- c.here[x] := best, fr[x] := BYTE (from + 1): 25 instructions, 55 cycles for its 3\n"
        "-- edges), in like instructions\n"
        "ldl 0; stl 3; ldl 0; stl 3; ldl 0; stl 3; ldl 0; ldl 0; stl 3",
        "[X] the REAL32 idioms (OCCAM_COSTS.md M5; ABS compiles to fpuabs after the fpsub, "
        "occam-probe trace). [I] the unit: one edge of the row sweep, its weight the height "
        "step plus a fixed length cost. Approximation: nav weighs the 3-D length of the edge "
        "(a square root) and the climb above a flat tolerance; the period occam takes the "
        "step's length as a constant. e.here[x] is not checked (x is a constant-range "
        "replicator's index, reference kernel trace [X]). Assumed: this edge is not the best; "
        "a third of the pixel's set-up and store is charged to each of its edges."},
    WorkListing{
        Work::path_backtrack,
        R"(-- from: the row sweep's predecessors, the step + 1 (BYTE); px, py: the path's points
WHILE y < y.start
  SEQ
    px[n] := x
    py[n] := y
    n := n + 1
    x := (x + (INT from[y][x])) - 1
    y := y + 1)",
        "ldl 4; ldl 3; gt; cj_not_taken 60                              -- y < y.start\n"
        "ldl 2; ldl 5; ldc 256; csub0; ldl 6; wsub; stnl* 0             -- px[n] := x\n"
        "ldl 3; ldl 5; ldc 256; csub0; ldl 7; wsub; stnl* 0             -- py[n] := y\n"
        "ldl 5; adc 1; stl 5                                            -- n := n + 1\n"
        "ldl 2; ldl 3; ldc 128; csub0; ldc 128; prod 7; ldl 2; ldc 128; csub0; add\n"
        "ldl 8; bsub; lb*; add; adc -1; stl 2                           -- x := ...\n"
        "ldl 3; adc 1; stl 3                                            -- y := y + 1\n"
        "j -60",
        "[I] from OCCAM_COSTS.md section 1: the 2-D subscript L[y][x] of a [128][128]BYTE "
        "array (ldc 128; prod, 11 cycles, both subscripts checked), WHILE as a test and a "
        "backward j, INT array stores checked against a 256-point path. Unit: one step of "
        "the path from the destination back to the start."},
    WorkListing{
        Work::footprint_scan,
        R"(-- zone: a row of the zone map (BYTE); step, slope: the hazard zones' bytes (2, 3)
SEQ x = 0 FOR W
  IF
    (zone[x] = step) OR (zone[x] = slope)
      ...  -- the pixel's ground point against the legs: footprint_test
    TRUE
      SKIP)",
        "ldc 2; ldl 0; ldl 2; bsub; lb*; diff; cj_not_taken 6             -- zone[x] = step: no\n"
        "ldl 0; ldl 2; bsub; lb*; eqc 3; cj_taken 3                       -- zone[x] = slope: no\n"
        "ldlp 0; ldc 21; lend_loop",
        "[X] the reference kernel's trace: the zone byte through the row's abbreviation (ldl; "
        "bsub; lb, x a constant-range replicator's index, not checked), the first comparison "
        "as diff; cj, the second as eqc; cj, then the loop end: 16 instructions, 44 cycles on "
        "the path where the pixel is neither step nor slope (all but one pixel in 32 of the "
        "kernel's data). Unit: one pixel of a zone-map row examined; nav reports a row's width "
        "for each row the check scans, and likewise for the passes that withhold traversable "
        "pixels around a conflict and give them back, whose test of the byte is one "
        "comparison and is charged as this one (the withholding pass's test of a traversable "
        "pixel's ground point against the conflicts' box is not in the unit)."},
    WorkListing{
        Work::footprint_test,
        R"(-- px, py: the ground point (REAL32); x0, y0, cs, sn: each leg's start and heading;
-- lo, hi: the leg's extent along its heading, hw: the footprint's half-width
SEQ c = 0 FOR n.legs
  REAL32 dx, dy, along, across :
  SEQ
    dx := px - x0[c]
    dy := py - y0[c]
    along := (dx * cs[c]) + (dy * sn[c])
    across := (dy * cs[c]) - (dx * sn[c])
    IF
      (across <= hw) AND (across >= (-hw)) AND (along >= lo[c]) AND (along <= hi[c])
        hits := hits + 1
      TRUE
        SKIP)",
        "ldlp 11; fpldnlsn; ldl 0; ldc 8; csub0; ldl 14; fpldnlsni*; fpsub  -- px - x0[c]\n"
        "ldlp 5; fpchkerr; fpstnlsn                                     -- dx := ...\n"
        "ldlp 10; fpldnlsn; ldl 0; ldc 8; csub0; ldl 13; fpldnlsni*; fpsub  -- py - y0[c]\n"
        "ldlp 4; fpchkerr; fpstnlsn                                     -- dy := ...\n"
        "ldlp 5; fpldnlsn; ldl 0; ldc 8; csub0; ldl 7; wsub; fpldnlmulsn*  -- dx * cs[c]\n"
        "ldlp 4; fpldnlsn; ldl 0; ldc 8; csub0; ldl 6; wsub; fpldnlmulsn*  -- dy * sn[c]\n"
        "fpadd; ldlp 3; fpchkerr; fpstnlsn                              -- along := ...\n"
        "ldlp 4; fpldnlsn; ldl 0; ldc 8; csub0; ldl 7; wsub; fpldnlmulsn*  -- dy * cs[c]\n"
        "ldlp 5; fpldnlsn; ldl 0; ldc 8; csub0; ldl 6; wsub; fpldnlmulsn*  -- dx * sn[c]\n"
        "fpsub; ldlp 2; fpchkerr; fpstnlsn                              -- across := ...\n"
        "ldlp 2; fpldnlsn; ldlp 9; fpldnlsn; fpgt; eqc 0; fpchkerr; cj_not_taken 53  -- <= hw\n"
        "fpldzerosn; ldlp 9; fpldnlsn; fpsub                            -- -hw\n"
        "ldlp 2; fpldnlsn; fpgt; eqc 0; fpchkerr; cj_taken 36           -- >= -hw: no\n"
        "ldlp 0; ldc 163; lend_loop\n"
        "-- a quarter of the point's own instructions (px := fwd[x], py := lft[x], the legs'\n"
        "-- loop set up and checked, the points' loop end: 21 instructions, 53 cycles for its 4\n"
        "-- legs), in like instructions\n"
        "ldl 17; ldl 20; wsub; ldnl 0; stl 11",
        "[X] the instruction stream as the reference kernel's trace shows it: the point "
        "through the workspace (ldlp; fpldnlsn), the leg's values by checked subscripts (a "
        "variable number of legs: ldc 8; csub0), fpldnlsni for x0[c] and y0[c], fpldnlmulsn "
        "for the products, fpchkerr before each store; each comparison as NOT >, (fpgt; eqc "
        "0; fpchkerr; cj), -hw as 0 - hw (fpldzerosn; fpsub); AND tested left to right. The "
        "path is the kernel's most common outcome, the point beyond the leg's right side (the "
        "second test fails: 83 instructions, 264 cycles; 49 % of the kernel's tests, 27 % "
        "fail the first test, 10 instructions fewer, 24 % go on to the third and fourth or "
        "are inside, 11 to 25 more), plus a quarter of the point's own instructions. [I] a "
        "pose of a turn (along and across against the half length and width) and the "
        "withholding pass's distance test (dx * dx + dy * dy against r * r), which nav "
        "reports in this unit too, are of the same size and charged as this one."},
};

} // namespace

std::span<const WorkListing> map_listings() {
  return kMap;
}

} // namespace marsokhod::nav_program::detail
