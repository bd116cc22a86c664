// `marsokhod eval <evaluation>`: the evaluations, and the evaluation errors as exit codes.

#include "cli/command.hpp"

#include "marsokhod/eval/common/errors.hpp"

#include <memory>
#include <vector>

namespace marsokhod::apps {

Command add_stereo_evaluation(CLI::App& parent);   // eval_stereo_command.cpp
Command add_terrain_evaluation(CLI::App& parent);  // eval_terrain_command.cpp
Command add_traverse_evaluation(CLI::App& parent); // traverse/eval_traverse_command.cpp

namespace {

// Every evaluation, in --help order.
const std::vector<CommandFactory> kEvaluations = {add_stereo_evaluation, add_terrain_evaluation,
                                                  add_traverse_evaluation};

// Bad option values are usage errors (exit 2). Bad files and data (EvaluationError) reach the
// command line as any other runtime error does, and exit 1.
int run_evaluation(const Command& evaluation) {
  try {
    return evaluation.run();
  } catch (const eval::OptionError& error) {
    throw UsageError(error.what());
  }
}

} // namespace

Command make_eval_command(CLI::App& parent) {
  CLI::App* evaluate =
      parent.add_subcommand("eval", "Score the navigation software against ground truth.");
  evaluate->require_subcommand(1);
  auto evaluations = std::make_shared<std::vector<Command>>();
  for (CommandFactory factory : kEvaluations)
    evaluations->push_back(factory(*evaluate));
  return {evaluate, [evaluations] {
            for (const Command& evaluation : *evaluations)
              if (evaluation.app->parsed())
                return run_evaluation(evaluation);
            return static_cast<int>(kUsageError);
          }};
}

} // namespace marsokhod::apps
