// The --inject grammar: times and stages read exactly, and read back the same.

#include "marsokhod/overswitch/faults/fault.hpp"

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

TEST(FaultSpec, UpsetAtAnAddressInABufferOrDrawnOverMemory) {
  const Fault at = parse_fault("seu:module1@3s,addr=0x80012345,bit=3");
  EXPECT_EQ(at.kind, Fault::Kind::upset);
  EXPECT_EQ(at.memory.address, 0x80012345U);
  EXPECT_EQ(at.memory.bit, 3U);
  EXPECT_EQ(parse_fault("seu:module1@3s,addr=#80001000,bit=0").memory.address, 0x80001000U);
  const Fault in = parse_fault("seu:module0@matching+1s,buffer=left image");
  EXPECT_EQ(in.memory.buffer, "left image");
  EXPECT_EQ(in.stage, "matching");
  EXPECT_EQ(parse_fault("seu:module0@1s").memory.over, MemoryTarget::Over::allocated);
  EXPECT_EQ(parse_fault("seu:module0@1s,over=memory").memory.over, MemoryTarget::Over::memory);
  const Fault stuck = parse_fault("stuck:module0@0s,buffer=zone,value=0");
  EXPECT_EQ(stuck.kind, Fault::Kind::stuck);
  EXPECT_FALSE(stuck.memory.stuck_value);
  EXPECT_EQ(parse_fault("leak:module1@2s,bytes=4096").leak_bytes, 4096U);
}

TEST(FaultSpec, LinkFaultsNameTheModulesLinkAndTheirWire) {
  const Fault down = parse_fault("link:module0.link0@2s,dir=in,for=50ms");
  EXPECT_EQ(down.kind, Fault::Kind::link_down);
  EXPECT_EQ(down.module, "module0");
  EXPECT_EQ(down.link, 0);
  EXPECT_EQ(down.direction, LinkDirection::in);
  EXPECT_EQ(down.duration, 50 * emulator::kMillisecond);
  EXPECT_EQ(parse_fault("link:module1.link2@1s").direction, LinkDirection::both);
  const Fault bit = parse_fault("linkbit:module0.link0@matching+1s,byte=7,bit=5");
  EXPECT_EQ(bit.direction, LinkDirection::out);
  EXPECT_EQ(bit.byte, 7U);
  EXPECT_EQ(bit.data_bit, 5U);
  EXPECT_EQ(parse_fault("ackloss:module1.link0@4s,dir=in").direction, LinkDirection::in);
}

TEST(FaultSpec, OptionsReadBackToTheSameFault) {
  for (const char* spec :
       {"seu:module1@3s,addr=#80012345,bit=3", "seu:module0@matching+1s,buffer=left image",
        "seu:module0@1s,over=memory", "stuck:module0@0s,bit=2,buffer=zone,value=0",
        "leak:module1@2s,bytes=4096", "link:module0.link0@2s,dir=in,for=0.05s",
        "linkbit:module0.link0@matching+1s,dir=out,byte=7,bit=5",
        "ackloss:module1.link0@4s,dir=in"}) {
    const Fault fault = parse_fault(spec);
    EXPECT_EQ(describe(fault), spec);
    const Fault again = parse_fault(describe(fault));
    EXPECT_EQ(again.memory.address, fault.memory.address) << spec;
    EXPECT_EQ(again.memory.buffer, fault.memory.buffer) << spec;
    EXPECT_EQ(again.duration, fault.duration) << spec;
    EXPECT_EQ(again.link, fault.link) << spec;
  }
}

TEST(FaultSpec, MalformedOptionsAreRefusedNamingTheProblem) {
  const auto problem = [](const char* spec) {
    try {
      parse_fault(spec);
    } catch (const FaultSpecError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(problem("hang:module0@1s,bit=3").find("takes no 'bit'"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,colour=red").find("takes no 'colour'"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,bit=3,bit=4").find("given twice"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,bit=8").find("between 0 and 7"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,addr=0x80001000").find("needs its bit"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,addr=0x100000000,bit=1").find("not between"),
            std::string::npos);
  // Below the memory is still an address: the run, not the spec, finds it outside memory.
  EXPECT_EQ(problem("seu:module0@1s,addr=7,bit=1"), "accepted");
  EXPECT_NE(problem("seu:module0@1s,addr=0x80001000,bit=1,buffer=x").find("not both"),
            std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,over=sky").find("allocated or memory"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,buffer=").find("names no buffer"), std::string::npos);
  EXPECT_NE(problem("seu:module0@1s,bit").find("no KEY=VALUE"), std::string::npos);
  EXPECT_NE(problem("link:module0@1s").find("MODULE.linkN"), std::string::npos);
  EXPECT_NE(problem("link:module0.link4@1s").find("MODULE.linkN"), std::string::npos);
  EXPECT_NE(problem("linkbit:module0.link1@1s,dir=both").find("one wire"), std::string::npos);
  EXPECT_NE(problem("link:module0.link1@1s,for=forever").find("no time"), std::string::npos);
  EXPECT_NE(problem("stuck:module0@1s,value=2").find("between 0 and 1"), std::string::npos);
  EXPECT_NE(problem("melt:module0@1s").find("unknown fault kind"), std::string::npos);
}

} // namespace
} // namespace marsokhod::overswitch
