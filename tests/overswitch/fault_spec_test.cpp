// The --inject grammar: times and stages read exactly, and read back the same.

#include "marsokhod/overswitch/fault.hpp"

#include <gtest/gtest.h>

namespace marsokhod::overswitch {
namespace {

TEST(FaultSpec, TimeFromTheCycleStartInEachUnit) {
  EXPECT_EQ(parse_fault("hang:module1@1.05s").offset, 1'050'000'000'000);
  EXPECT_EQ(parse_fault("hang:module1@250ms").offset, 250'000'000'000);
  EXPECT_EQ(parse_fault("power:module0@900us").offset, 900'000'000);
  const Fault fault = parse_fault("power:module0@0s");
  EXPECT_EQ(fault.kind, Fault::Kind::power_loss);
  EXPECT_EQ(fault.module, "module0");
  EXPECT_TRUE(fault.stage.empty());
}

TEST(FaultSpec, StageWithAndWithoutAnOffset) {
  const Fault later = parse_fault("hang:module0@matching+0.5s");
  EXPECT_EQ(later.stage, "matching");
  EXPECT_EQ(later.offset, 500'000'000'000);
  const Fault at_start = parse_fault("hang:module1@zones");
  EXPECT_EQ(at_start.stage, "zones");
  EXPECT_EQ(at_start.offset, 0);
}

TEST(FaultSpec, DescribeReadsBackToTheSameFault) {
  for (const char* spec : {"hang:module1@1.05s", "power:module0@matching+0.5s", "hang:m@zones"}) {
    const Fault fault = parse_fault(spec);
    const Fault again = parse_fault(describe(fault));
    EXPECT_EQ(again.kind, fault.kind) << spec;
    EXPECT_EQ(again.module, fault.module) << spec;
    EXPECT_EQ(again.stage, fault.stage) << spec;
    EXPECT_EQ(again.offset, fault.offset) << spec;
  }
}

TEST(FaultSpec, MalformedSpecsAreRefused) {
  for (const char* spec : {"", "hang", "hang:module1", "hang:@1s", "hang:module1@", "hang:1x@1s",
                           "hang:module1@1", "hang:module1@1.5", "hang:module1@+1s",
                           "hang:module1@zones+", "hang:module1@zones+-1s", "hang:module1@nan s"})
    EXPECT_THROW(parse_fault(spec), FaultSpecError) << spec;
}

} // namespace
} // namespace marsokhod::overswitch
