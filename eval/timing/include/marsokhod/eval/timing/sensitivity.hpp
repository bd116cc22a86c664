// How the model's figures move with the parameters the paper does not give.
#pragma once

#include "marsokhod/eval/timing/timing_model.hpp"

#include <string>
#include <vector>

namespace marsokhod::eval {

/// One row of the sensitivity table: a parameter the paper does not give, at one value.
struct SensitivityRow {
  std::string parameter;
  std::string value;
  bool shipped = false; ///< the value the loaded platform files give
  ModelFigures figures;
};

/// The three figures as each parameter the paper does not give moves over its period range,
/// the others as shipped and the fitted constant held: the PC card's speed grade (every grade
/// the processor file lists), its memory's wait states, its memory size, the onboard memory's
/// wait states, the link speed; then the fitted constant itself at x0.9 and x1.1. Each
/// parameter's first row is its value in the loaded platform files, marked shipped, with
/// `shipped` (the model's figures as shipped at that constant) rather than run again.
/// TimingError when a scene does not fit a variant.
std::vector<SensitivityRow> sensitivity(const TimingModel& model, double occam_style,
                                        const ModelFigures& shipped);

} // namespace marsokhod::eval
