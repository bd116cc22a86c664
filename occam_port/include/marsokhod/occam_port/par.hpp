// PAR, replicated PAR and PRI PAR.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <type_traits>
#include <utility>

namespace marsokhod::occam_port {

/// Sizes given to the processes a PAR starts.
struct ParOptions {
  /// Host stack of each branch (0: the kernel's default).
  std::size_t stack_bytes = 0;
  /// Emulated workspace charged to the node's memory per started branch (0: none).
  std::size_t workspace_bytes = 0;
};

/// PAR: runs the branches as concurrent processes on the current node and returns when all
/// have finished. As compiled occam does, the parent runs the last branch itself and starts
/// the others (startp each); every branch ends with endp. Killing the parent kills the
/// branches it started.
void par(std::span<const std::function<void()>> branches, const ParOptions& options = {});

template <typename... Branches>
requires(sizeof...(Branches) > 0 &&
         (std::is_invocable_v<Branches&> && ...)) void par(Branches&&... branches) {
  const std::function<void()> list[] = {std::function<void()>(std::forward<Branches>(branches))...};
  par(std::span<const std::function<void()>>(list));
}

/// Replicated PAR: `PAR i = 0 FOR count`.
void par_for(std::size_t count, const std::function<void(std::size_t)>& body,
             const ParOptions& options = {});

/// PRI PAR: `high` runs at high priority (it preempts low-priority work and is never
/// timesliced), `low` at the current priority, which is low at the top level.
void pri_par(const std::function<void()>& high, const std::function<void()>& low,
             const ParOptions& options = {});

} // namespace marsokhod::occam_port
