// What `marsokhod reproduce` found, for people: Markdown and a chart.
#pragma once

#include "marsokhod/eval/timing/reproduction.hpp"
#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>
#include <string>

namespace marsokhod::apps {

/// The figures' table, the fitted constant, the sensitivity and the sweep, for people.
std::string reproduction_markdown(const eval::Reproduction& r);
/// Paper beside model, one group per figure.
imaging::Image<std::uint8_t> reproduction_chart(const eval::Reproduction& r);

} // namespace marsokhod::apps
