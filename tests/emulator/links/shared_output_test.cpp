// A device link's output shared by processes of one node: whole messages in the order asked,
// and a killed process gives its turn up.

#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link_frame_store.hpp"
#include "marsokhod/emulator/links/shared_output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

std::vector<std::byte> upload_of(char tag, std::size_t payload) {
  std::vector<std::byte> message{FrameStore::kUploadRequest};
  for (std::size_t i = 0; i < 4; ++i)
    message.push_back(std::byte(static_cast<unsigned char>(payload >> (8 * i))));
  message.insert(message.end(), payload, std::byte(static_cast<unsigned char>(tag)));
  return message;
}

struct Rig {
  PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  Cpu& module0 = kernel.add_cpu("module0");
  LinkNetwork network{kernel, onboard};
  std::vector<std::vector<std::byte>> uploads;
  FrameStore store{
      network, *onboard.find_device("rover_io"),
      [](int) { return std::vector<std::byte>(128 * 128); },
      [this](int, std::vector<std::byte> bytes) { uploads.push_back(std::move(bytes)); }};
  SharedOutput output{network.require_port("module0", 3)};
};

TEST(SharedOutput, MessagesGoWholeInTheOrderTheyWereAsked) {
  Rig rig;
  for (const char tag : std::string("abc"))
    rig.kernel.spawn(rig.module0, std::string(1, tag), [&rig, tag] {
      const std::vector<std::byte> header_and_payload = upload_of(tag, 100);
      const std::span<const std::byte> all(header_and_payload);
      // The header and the payload as two parts of one turn: nothing may come between them.
      rig.output.output({all.first(5), all.subspan(5)});
    });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  ASSERT_EQ(rig.uploads.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(rig.uploads[i], std::vector<std::byte>(100, std::byte('a' + i))) << i;
}

TEST(SharedOutput, KilledWaiterGivesItsTurnUp) {
  Rig rig;
  rig.kernel.spawn(
      rig.module0, "first", [&rig] { rig.output.output(upload_of('a', 1000)); });
  Process& doomed = rig.kernel.spawn(
      rig.module0, "doomed", [&rig] { rig.output.output(upload_of('b', 10)); });
  rig.kernel.spawn(rig.module0, "third", [&rig] { rig.output.output(upload_of('c', 10)); });
  // 1000 bytes take about 1.1 ms: the other two are waiting their turn at 100 us.
  rig.kernel.run_until(100 * kMicrosecond);
  EXPECT_EQ(rig.output.waiting(), 2U);
  rig.kernel.kill(doomed);
  EXPECT_EQ(rig.output.waiting(), 1U);
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  ASSERT_EQ(rig.uploads.size(), 2U);
  EXPECT_EQ(rig.uploads[0], std::vector<std::byte>(1000, std::byte('a')));
  EXPECT_EQ(rig.uploads[1], std::vector<std::byte>(10, std::byte('c')));
}

TEST(SharedOutput, HeartbeatByteReachesTheHeartbeatSinkWithItsLink) {
  Rig rig;
  std::vector<int> beats;
  rig.store.set_heartbeat_sink([&beats](int link) { beats.push_back(link); });
  rig.kernel.spawn(rig.module0, "beat", [&rig] {
    const std::byte beat = FrameStore::kHeartbeat;
    rig.output.output(std::span(&beat, 1));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(beats, std::vector<int>{0}); // onboard.toml: module0.link3 is rover_io.link0
  EXPECT_TRUE(rig.uploads.empty());
}

} // namespace
} // namespace marsokhod::emulator
