// The paper's timings, the figures the timing model is compared with.
#pragma once

namespace marsokhod::eval {

/// One timing the paper gives (Kolesnik 1995, Conclusions): what it times, its words, seconds.
struct PaperFigure {
  const char* name;
  const char* paper_says;
  double seconds;
};

/// "the stereo reconstruction algorithm takes 8 sec" on one T805 at 128x128: the figure the
/// model's one constant is fitted on.
inline constexpr PaperFigure kPaperStereo{"stereo 128x128 on one T805",
                                          "the stereo reconstruction algorithm takes 8 sec", 8.0};
/// The whole cycle on a PC transputer card.
inline constexpr PaperFigure kPaperCardCycle{
    "whole cycle on the PC card", "the overall processing time on such card equals 10 sec", 10.0};
/// The whole cycle on the rover's modules: "1.3 min".
inline constexpr PaperFigure kPaperOnboardCycle{"whole cycle onboard",
                                                "versus 1.3 min in onboard processing", 78.0};

/// The paper's image size: "image resolution is 128x128 pixels".
inline constexpr int kPaperImageSide = 128;

} // namespace marsokhod::eval
