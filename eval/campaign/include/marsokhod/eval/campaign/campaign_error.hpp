// CampaignRunError: a campaign that cannot be run.
#pragma once

#include <stdexcept>

namespace marsokhod::eval {

/// A campaign cannot be run or goes wrong in the model: a fault-free cycle that does not
/// finish, a module of the file's mix the platform lacks, a run the model fails on, a worker
/// lost. The message names the run or world seed that reproduces it.
class CampaignRunError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace marsokhod::eval
