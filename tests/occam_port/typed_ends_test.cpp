// Typed channel ends: one direction each, at the channel's own cost, on a node and a link.

#include "occam_port/link_rig.hpp"
#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;
using testing::TwoModules;

// What an end allows, asked of the type alone.
template <typename End, typename T>
concept CanInput = requires(End end, T& value) {
  end >> value;
};
template <typename End, typename T>
concept CanOutput = requires(End end, const T& value) {
  end << value;
};
template <typename End>
concept CanBeAGuard = requires(End end) {
  input(end);
};
struct TakesInt {
  void operator()(int) const {}
};
template <typename End>
concept CanBeAHandlerGuard = requires(End end) {
  on_input(end, TakesInt{});
};

// An output end cannot read, an input end cannot write or stand in for the other end.
static_assert(CanInput<ChanIn<int>, int>);
static_assert(!CanOutput<ChanIn<int>, int>);
static_assert(CanOutput<ChanOut<int>, int>);
static_assert(!CanInput<ChanOut<int>, int>);
static_assert(CanBeAGuard<ChanIn<int>> && CanBeAHandlerGuard<ChanIn<int>>);
static_assert(!CanBeAGuard<ChanOut<int>> && !CanBeAHandlerGuard<ChanOut<int>>);
static_assert(!std::is_convertible_v<ChanIn<int>, ChanOut<int>>);
static_assert(!std::is_convertible_v<ChanOut<int>, ChanIn<int>>);
// The channel itself still does both, and hands out either end; ends are typed.
static_assert(CanInput<Chan<int>&, int> && CanOutput<Chan<int>&, int>);
static_assert(std::is_convertible_v<Chan<int>&, ChanIn<int>>);
static_assert(std::is_convertible_v<Chan<int>&, ChanOut<int>>);
static_assert(!std::is_convertible_v<Chan<long>&, ChanIn<int>>);
static_assert(!std::is_constructible_v<ChanIn<int>, Chan<int>&&>);
static_assert(!std::is_constructible_v<ChanOut<int>, Chan<int>&&>);
// Handles: one pointer, copied as plain bytes.
static_assert(sizeof(ChanIn<int>) == sizeof(void*) && sizeof(ChanOut<int>) == sizeof(void*));
static_assert(std::is_trivially_copyable_v<ChanIn<int>>);
static_assert(std::is_trivially_copyable_v<ChanOut<int>>);

// Compiled occam: each side loads its operands (ldlp 1, ldl 2, ldc 1), then in or out of a
// w-word message takes 2w+19 cycles (data book).
constexpr std::int64_t kEndOperands = 1 + 2 + 1;
constexpr std::int64_t kEndOneWordTransfer = kEndOperands + 2 * 1 + 19;

void producer(ChanOut<int> out, int count) {
  for (int i = 0; i < count; ++i)
    out << 10 * i;
}

void consumer(ChanIn<int> in, int count, std::vector<int>& received) {
  for (int i = 0; i < count; ++i) {
    int x = 0;
    in >> x;
    received.push_back(x);
  }
}

TEST(TypedEnds, EndsPassMessagesAtTheChannelsDataBookCost) {
  OccamRig rig;
  Chan<int> c("c");
  int received = 0;
  Tick writer_done = -1;
  Tick reader_done = -1;
  rig.spawn("writer", [&, out = c.out()] {
    out << 42;
    writer_done = rig.kernel.now();
  });
  rig.spawn("reader", [&, in = c.in()] {
    in >> received;
    reader_done = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, 42);
  // As with the channel itself: the writer's out ends at 25 cycles and waits, the reader's in
  // runs another 25 and releases it.
  EXPECT_EQ(reader_done, rig.cycles(2 * kEndOneWordTransfer));
  EXPECT_EQ(writer_done, rig.cycles(2 * kEndOneWordTransfer));
}

TEST(TypedEnds, ProcessesTakingOneEndEachExchangeMessagesInOrder) {
  OccamRig rig;
  Chan<int> c("c");
  std::vector<int> received;
  rig.spawn(
      "producer", [&] { producer(c, 4); }); // Chan<int>& converts to ChanOut<int>
  rig.spawn("consumer", [&] { consumer(c, 4, received); });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, (std::vector<int>{0, 10, 20, 30}));
  // Four one-word messages, each 25 cycles on either side, one processor.
  EXPECT_EQ(rig.kernel.now(), rig.cycles(4 * 2 * kEndOneWordTransfer));
}

TEST(TypedEnds, InputsChainAndEndsOfOneChannelCompareEqual) {
  OccamRig rig;
  Chan<int> c("c"), d("d");
  int first = 0;
  int second = 0;
  rig.spawn(
      "writer", [out = c.out()] { out << 1 << 2; });
  rig.spawn("reader", [&, in = c.in()] { in >> first >> second; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(second, 2);
  EXPECT_TRUE(c.in() == ChanIn<int>(c));
  EXPECT_FALSE(c.in() == d.in());
  EXPECT_TRUE(c.out() == ChanOut<int>(c));
  EXPECT_EQ(c.in().name(), "c");
  EXPECT_EQ(d.out().name(), "d");
}

TEST(TypedEnds, EndsOfAChannelOnALinkCarryTheMessageBetweenModules) {
  TwoModules rig;
  Chan<std::array<int, 4>> c("m0->m1");
  rig.wire(c, rig.m0, rig.m1);
  const std::array<int, 4> sent = {7, -7, 70, -70};
  std::array<int, 4> received{};
  rig.m0.spawn(
      "sender", [&, out = c.out()] { out << sent; });
  rig.m1.spawn("receiver", [&, in = c.in()] { in >> received; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, sent);
  // On a link each CPU pays the operand loads (ldlp 1 + ldl 2 + ldc 1) and the base of out/in
  // (19) only; the link's DMA engine moves the 16 bytes.
  const Tick base_only = (1 + 2 + 1 + 19) * rig.m0.cpu_spec().cycle;
  EXPECT_EQ(rig.m0.cpu().busy_time(), base_only);
  EXPECT_EQ(rig.m1.cpu().busy_time(), base_only);
  // 16 bytes one way at 10 Mbit/s take at least 16 data packets of 11 bits (1.1 us each).
  EXPECT_GE(rig.kernel.now(), 16 * emulator::nanoseconds(1100));
}

} // namespace
} // namespace marsokhod::occam_port
