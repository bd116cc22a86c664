// The paper's timings reproduced by the model: the figures beside the paper's, the fitted
// constant, the sensitivity and the onboard memory sweep.
#pragma once

#include "marsokhod/eval/timing/memory_sweep.hpp"
#include "marsokhod/eval/timing/sensitivity.hpp"
#include "marsokhod/eval/timing/timing_model.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// One of the paper's figures beside the model's.
struct FigureComparison {
  std::string name;
  std::string paper_says; ///< the paper's words
  double paper_seconds = 0.0;
  SceneSpread model;
  bool fitted = false;

  double error_percent() const { return (model.mean - paper_seconds) / paper_seconds * 100.0; }
};

/// The model's one fitted constant: its value as the emulation uses it and as fitted again now.
struct FittedConstant {
  std::string name;
  double value = 0.0;
  double refit = 0.0;
  std::string fitted_on;
};

/// Everything `reproduce` finds.
struct Reproduction {
  std::vector<std::uint64_t> seeds;
  std::vector<FigureComparison> figures;
  std::vector<FittedConstant> fitted;
  std::vector<SensitivityRow> sensitivity;
  std::vector<SweepPoint> sweep;
  std::uint64_t card_external_kb = 0;    ///< as shipped
  std::uint64_t onboard_external_kb = 0; ///< as shipped
};

/// Renders world `seeds`, fits the occam style factor again on the stereo figure, gives the
/// three figures at the shipped factor, the sensitivity, and the onboard cycle at each of
/// `sweep_kb`. `note` (may be empty) is told what is being done. TimingError when a scene does
/// not fit.
Reproduction reproduce(const std::vector<std::uint64_t>& seeds,
                       const std::vector<std::uint64_t>& sweep_kb,
                       const std::function<void(const std::string&)>& note);

/// `scenes`, `figures`, `fitted_constants`, `sensitivity` and `sweep` ({external_kb,
/// emulated_seconds, memory_fault, terrain_kept, zone_grid_bytes}), with no host figure: two
/// runs give the same bytes.
void to_json(nlohmann::ordered_json& json, const Reproduction& reproduction);

} // namespace marsokhod::eval
