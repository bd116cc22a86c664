// The paper's rig at another image size, for the navigation's tests.
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"

namespace marsokhod::nav::test_rigs {

/// The paper's rig with square images `side` pixels wide.
inline imaging::StereoRig rig_of_side(int side) {
  imaging::RigParameters p;
  p.width_px = p.height_px = side;
  return imaging::StereoRig(p);
}

} // namespace marsokhod::nav::test_rigs
