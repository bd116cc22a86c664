// The Commstime network (prefix, delta, successor, consumer) as compiled occam runs it.

#include "marsokhod/occam_port/commstime.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <memory>

namespace marsokhod::occam_port {

namespace {

using emulator::Instruction;

/// A fixed piece of compiled code: its time on the node, worked out once from the node's
/// table, as a compiler's code is fixed.
struct Code {
  emulator::Kernel* kernel = nullptr;
  emulator::Tick time = 0;
};

// What an occam compiler emits around the communications (the channel charges the operand
// loads and in/out itself): a WHILE TRUE loop ends with a j back, a counted SEQ with lend;
// successor computes x+1 into a temporary (ldl, adc, stl).
struct Overheads {
  Code while_loop;
  Code counted_loop;
  Code increment;

  explicit Overheads(emulator::Node& node) {
    const auto code = [&node](const emulator::InstructionMix& mix) {
      return Code{&node.kernel(), node.cycles(node.cycles_of(mix))};
    };
    while_loop = code(emulator::InstructionMix().add(Instruction::j));
    counted_loop = code(emulator::InstructionMix().add(Instruction::lend_loop));
    emulator::InstructionMix plus_one;
    plus_one.add(Instruction::ldl).add(Instruction::adc).add(Instruction::stl);
    increment = code(plus_one);
  }
};

void charge(const Code& code) {
  code.kernel->consume(code.time);
}

void prefix(const Overheads& costs, std::int64_t total, ChanIn<int> in, ChanOut<int> out) {
  out << 0;
  for (std::int64_t i = 1; i < total; ++i) {
    int x = 0;
    in >> x;
    out << x;
    charge(costs.while_loop);
  }
  int last = 0;
  in >> last;
}

void delta(const Overheads& costs, std::int64_t total, bool parallel, ChanIn<int> in,
           ChanOut<int> out1, ChanOut<int> out2) {
  for (std::int64_t i = 0; i < total; ++i) {
    int x = 0;
    in >> x;
    if (parallel) {
      par([out1, &x] { out1 << x; }, [out2, &x] { out2 << x; });
    } else {
      out1 << x;
      out2 << x;
    }
    charge(costs.while_loop);
  }
}

void successor(const Overheads& costs, std::int64_t total, ChanIn<int> in, ChanOut<int> out) {
  for (std::int64_t i = 0; i < total; ++i) {
    int x = 0;
    in >> x;
    charge(costs.increment);
    out << x + 1;
    charge(costs.while_loop);
  }
}

void consumer(const Overheads& costs, const CommstimeOptions& options, ChanIn<int> in,
              CommstimeResult& result) {
  emulator::Kernel& kernel = emulator::Node::current().kernel();
  int x = 0;
  for (std::int64_t i = 0; i < options.warmup_loops; ++i) {
    in >> x;
    charge(costs.counted_loop);
  }
  const emulator::Tick start = kernel.now();
  for (std::int64_t i = 0; i < options.loops; ++i) {
    in >> x;
    charge(costs.counted_loop);
  }
  result.measured_time = kernel.now() - start;
  for (std::int64_t i = 0; i < options.warmup_loops; ++i) {
    in >> x;
    charge(costs.counted_loop);
  }
}

} // namespace

double CommstimeResult::emulated_us_per_loop() const {
  return loops > 0 ? emulator::to_microseconds(measured_time) / static_cast<double>(loops) : 0.0;
}

void spawn_commstime(emulator::Node& node, const CommstimeOptions& options,
                     CommstimeResult& result) {
  const std::int64_t total = 2 * options.warmup_loops + options.loops;
  result.loops = options.loops;
  result.communications = 4 * total;
  node.spawn("commstime", [total, options, &result, &node] {
    const Overheads costs(node);
    Chan<int> a("a"), b("b"), c("c"), d("d");
    par([&] { prefix(costs, total, c, a); },
        [&] { delta(costs, total, options.parallel_delta, a, b, d); },
        [&] { successor(costs, total, b, c); }, [&] { consumer(costs, options, d, result); });
  });
}

} // namespace marsokhod::occam_port
