// What `marsokhod reproduce` found, as JSON, Markdown and a chart.
#pragma once

#include "reproduce_model.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::apps {

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

struct Reproduction {
  std::vector<std::uint64_t> seeds;
  std::vector<FigureComparison> figures;
  std::vector<FittedConstant> fitted;
  std::vector<SensitivityRow> sensitivity;
  std::vector<SweepPoint> sweep;
  std::uint64_t card_external_kb = 0;    ///< as shipped
  std::uint64_t onboard_external_kb = 0; ///< as shipped
};

/// `figures`, `fitted_constants`, `sensitivity` and `sweep` ({external_kb, emulated_seconds,
/// memory_fault}), with no host figure: two runs give the same bytes.
nlohmann::ordered_json reproduction_json(const Reproduction& r);
/// The figures' table, the fitted constant, the sensitivity and the sweep, for people.
std::string reproduction_markdown(const Reproduction& r);
/// Paper beside model, one group per figure.
imaging::Image<std::uint8_t> reproduction_chart(const Reproduction& r);

} // namespace marsokhod::apps
