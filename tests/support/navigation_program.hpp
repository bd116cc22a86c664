// Test support: the navigation program's shape (processes, channels, device uses) that the
// placement tests and the placement reader's mutation harness check files against.
#pragma once

#include "marsokhod/occam_port/navigation/placement.hpp"

namespace marsokhod::testing {

/// The navigation cycle as OCCAM processes: the stereo half (acquire, features, matching), the
/// map and path half (range, zones, path, drive, motion) and telemetry, which reports both.
inline occam_port::ProgramShape navigation_program() {
  occam_port::ProgramShape shape;
  shape.processes = {"acquire", "features", "matching", "range",    "zones",
                     "path",    "drive",    "motion",   "telemetry"};
  shape.channels = {{"images", "acquire", "features"},  {"features", "features", "matching"},
                    {"disparity", "matching", "range"}, {"terrain", "range", "zones"},
                    {"zones", "zones", "path"},         {"path", "path", "drive"},
                    {"commands", "drive", "motion"},    {"disparity_out", "matching", "telemetry"},
                    {"plan_out", "drive", "telemetry"}, {"wheels", "motion", "telemetry"}};
  shape.devices = {{"acquire", "images from the frame store"},
                   {"telemetry", "telemetry to the host or ground"}};
  return shape;
}

} // namespace marsokhod::testing
