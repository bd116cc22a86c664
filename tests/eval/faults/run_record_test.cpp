// Run records as runs.jsonl gives them: each line read back to the same record and written
// again to the same bytes, and lines that are no record refused naming the key.

#include "marsokhod/eval/faults/fault_record.hpp"

#include <gtest/gtest.h>

#include <string>

namespace marsokhod::eval {
namespace {

// Lines in the documented form (docs/faults.md, "Campaigns"): a hang run recovered, an upset
// the EDAC corrected, and a link fault with a trouble and a halt.
const std::string kHangRun =
    R"({"run":4,"world_seed":3,"fault":{"kind":"hang","module":"module1","at_s":1.05,)"
    R"("spec":"hang:module1@1.05s"},"outcome":"recovered","activated":true,"detected":true,)"
    R"("detection_latency_s":0.150002,"recovery_s":0.012233,"failovers":[{"failed":"module1",)"
    R"("spare":"module2","boot_s":0.012233}],"restarts":1,"path_equals_golden":true,)"
    R"("unsafe":false,"golden_unsafe":false,"telemetry_lost":false,)"
    R"("wheels_commanded_while_failed":false,"emulated_s":23.745,"delay_s":1.212})";

const std::string kUpsetRun =
    R"({"run":11,"world_seed":2,"fault":{"kind":"seu","module":"module0","at_s":7.5,)"
    R"("spec":"seu:module0@7.5s,over=memory","effect":"EDAC: corrected on every read",)"
    R"("address":"#8000A010","bit":5,"check_bit":false,"region":"external",)"
    R"("buffer":"left image, 128 rows x 128 px x 1 B","owner":"acquire","edac":"corrected"},)"
    R"("outcome":"masked","activated":false,"detected":true,"detection_latency_s":null,)"
    R"("recovery_s":null,"failovers":[],"restarts":0,"path_equals_golden":true,"unsafe":false,)"
    R"("golden_unsafe":false,"telemetry_lost":false,"wheels_commanded_while_failed":false,)"
    R"("emulated_s":22.9,"delay_s":0.0})";

const std::string kLinkRun =
    R"({"run":0,"world_seed":5,"fault":{"kind":"link","module":"module0","at_s":2.0,)"
    R"("spec":"link:module0.link0@2s"},"outcome":"safe_stop","reason":"no pair",)"
    R"("activated":true,"detected":true,"detection_latency_s":0.1,"recovery_s":null,)"
    R"("failovers":[{"failed":"module1","spare":null,"boot_s":0.0}],"halts":[{"module":)"
    R"("module1","process":"zones","what":"zone map","cause":"run-time error: range",)"
    R"("time_s":3.5}],"restarts":1,"link_troubles":[{"module":"module0","link":0,"peer":)"
    R"("module1","trouble":"output not acknowledged in time","time_s":2.1}],)"
    R"("path_equals_golden":false,"unsafe":false,"golden_unsafe":false,"telemetry_lost":true,)"
    R"("wheels_commanded_while_failed":false,"emulated_s":40.0,"delay_s":17.1})";

TEST(RunRecord, ReadsBackEveryKeyOfAHangRun) {
  const RunRecord r = parse_run_record(kHangRun);
  EXPECT_EQ(r.run, 4U);
  EXPECT_EQ(r.world_seed, 3U);
  EXPECT_EQ(r.fault.kind, overswitch::Fault::Kind::hang);
  EXPECT_EQ(r.fault.spec, "hang:module1@1.05s");
  EXPECT_FALSE(r.fault.hit);
  EXPECT_EQ(r.verdict.outcome, Outcome::recovered);
  ASSERT_TRUE(r.verdict.detection_latency_s);
  EXPECT_DOUBLE_EQ(*r.verdict.detection_latency_s, 0.150002);
  ASSERT_EQ(r.verdict.failovers.size(), 1U);
  EXPECT_EQ(r.verdict.failovers[0].spare, "module2");
}

TEST(RunRecord, ReadsBackTheBitAnUpsetStruck) {
  const RunRecord r = parse_run_record(kUpsetRun);
  ASSERT_TRUE(r.fault.hit);
  EXPECT_EQ(r.fault.hit->address, 0x8000A010U);
  EXPECT_EQ(r.fault.hit->bit, 5U);
  EXPECT_EQ(r.fault.hit->owner, "acquire");
  EXPECT_EQ(r.fault.hit->edac, emulator::UpsetEffect::corrected);
  EXPECT_FALSE(r.verdict.detection_latency_s);
}

TEST(RunRecord, WritesEachLineBackByteForByte) {
  for (const std::string& line : {kHangRun, kUpsetRun, kLinkRun})
    EXPECT_EQ(run_record_line(parse_run_record(line)), line);
}

TEST(RunRecord, ReadsBackWhatItWrote) {
  const RunRecord link = parse_run_record(kLinkRun);
  EXPECT_EQ(parse_run_record(run_record_line(link)), link);
  EXPECT_EQ(link.verdict.reason, "no pair");
  EXPECT_TRUE(link.verdict.failovers[0].spare.empty());
  ASSERT_EQ(link.verdict.halts.size(), 1U);
  EXPECT_EQ(link.verdict.halts[0].process, "zones");
  ASSERT_EQ(link.verdict.link_troubles.size(), 1U);
  EXPECT_EQ(link.verdict.link_troubles[0].peer, "module1");
}

TEST(RunRecord, RefusesALineThatIsNoRecordNamingTheKey) {
  const auto refused = [](const std::string& line) {
    try {
      parse_run_record(line);
    } catch (const RecordError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused("not json"), "a run record is one JSON object on a line");
  EXPECT_EQ(refused("[1,2]"), "a run record is one JSON object on a line");
  std::string no_outcome = kHangRun;
  no_outcome.replace(no_outcome.find(R"("outcome":"recovered",)"), 22, "");
  EXPECT_EQ(refused(no_outcome), "the record has no 'outcome'");
  std::string bad_class = kHangRun;
  bad_class.replace(bad_class.find("recovered"), 9, "fine");
  EXPECT_EQ(refused(bad_class), "the record's 'outcome' 'fine' is no outcome class");
  std::string bad_kind = kHangRun;
  bad_kind.replace(bad_kind.find(R"("kind":"hang")"), 13, R"("kind":"meteor")");
  EXPECT_NE(refused(bad_kind).find("'meteor' is no fault kind"), std::string::npos);
  std::string bad_address = kUpsetRun;
  bad_address.replace(bad_address.find("#8000A010"), 9, "#8000A01G");
  EXPECT_EQ(refused(bad_address), "the record's 'address' '#8000A01G' is no #XXXXXXXX address");
  std::string wrong_type = kHangRun;
  wrong_type.replace(wrong_type.find(R"("restarts":1)"), 12, R"("restarts":"one")");
  EXPECT_NE(refused(wrong_type).find("the record's 'restarts'"), std::string::npos);
}

} // namespace
} // namespace marsokhod::eval
