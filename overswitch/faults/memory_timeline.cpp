// Recording the blocks of a run and asking whether a byte was free.

#include "marsokhod/overswitch/faults/memory_timeline.hpp"

namespace marsokhod::overswitch {

void MemoryTimeline::record(const std::string& module, emulator::MemoryArena& arena,
                            emulator::Kernel& kernel) {
  std::vector<Span>& spans = spans_[module];
  for (const emulator::BlockInfo& block : arena.blocks())
    spans.push_back({block, kernel.now(), emulator::kNever});
  arena.set_block_listener(
      [&spans, &kernel, &arena](emulator::Address start, std::size_t, bool allocated) {
        if (allocated) {
          spans.push_back({*arena.block_at(start), kernel.now(), emulator::kNever});
          return;
        }
        for (auto span = spans.rbegin(); span != spans.rend(); ++span)
          if (span->block.start == start && span->to == emulator::kNever) {
            span->to = kernel.now();
            return;
          }
      });
  recording_.push_back(&arena);
}

void MemoryTimeline::stop() {
  for (emulator::MemoryArena* arena : recording_)
    arena->set_block_listener({});
  recording_.clear();
}

MemoryTimeline::Holding MemoryTimeline::holding(const std::string& module,
                                                emulator::Address address,
                                                emulator::Tick time) const {
  Holding answer;
  const auto found = spans_.find(module);
  if (found == spans_.end())
    return answer;
  for (const Span& span : found->second) {
    if (address < span.block.start || address - span.block.start >= span.block.bytes ||
        time < span.from || time > span.to)
      continue;
    if (time == span.from || time == span.to)
      answer.sure = false;
    else
      answer.block = span.block;
  }
  return answer;
}

} // namespace marsokhod::overswitch
