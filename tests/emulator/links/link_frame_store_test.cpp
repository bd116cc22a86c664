// The cameras' frame store: image requests and answers over its links.

#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link_frame_store.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

/// A recognisable image per camera.
std::vector<std::byte> test_image(int camera, std::size_t bytes) {
  std::vector<std::byte> image(bytes);
  for (std::size_t i = 0; i < bytes; ++i)
    image[i] = std::byte(static_cast<unsigned char>(i % 251 + static_cast<unsigned>(camera) * 3));
  return image;
}

TEST(FrameStore, ServesTheRequestedCameraOverTheModulesDeviceLink) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  const DeviceSpec& device = *onboard.find_device("rover_io");
  Kernel kernel;
  Cpu& module1 = kernel.add_cpu("module1");
  LinkNetwork network(kernel, onboard);
  const std::size_t bytes = 128 * 128; // onboard.toml: 128 x 128, 8 bits per pixel
  FrameStore store(network, device, [&](int camera) { return test_image(camera, bytes); });
  ASSERT_EQ(store.image_bytes(), bytes);

  std::vector<std::byte> left(bytes);
  std::vector<std::byte> right(bytes);
  Tick first_done = 0;
  kernel.spawn(module1, "grab", [&] {
    LinkPort& devices = network.require_port("module1", 3);
    const std::byte camera0{0};
    const std::byte camera1{1};
    devices.output(std::span(&camera0, 1));
    devices.input(left);
    first_done = kernel.now();
    devices.output(std::span(&camera1, 1));
    devices.input(right);
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(left, test_image(0, bytes));
  EXPECT_EQ(right, test_image(1, bytes));
  EXPECT_EQ(store.requests_served(), 2U);
  // Request byte then 16384 image bytes, each 11 bits at 100 ns, plus the handshakes between
  // the request and the answer: within 1 % of (1 + 16384) x 1.1 us.
  EXPECT_NEAR(to_microseconds(first_done), (1 + 16384) * 1.1, 0.01 * 16385 * 1.1);
}

TEST(FrameStore, RequestForAMissingCameraGetsNoAnswer) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  Cpu& module0 = kernel.add_cpu("module0");
  LinkNetwork network(kernel, onboard);
  FrameStore store(network, *onboard.find_device("rover_io"),
                   [](int camera) { return test_image(camera, 128 * 128); });
  bool answered = false;
  kernel.spawn(module0, "grab", [&] {
    const std::byte camera{7};
    std::byte pixel{};
    network.require_port("module0", 3).output(std::span(&camera, 1));
    network.require_port("module0", 3).input(std::span(&pixel, 1));
    answered = true;
  });
  EXPECT_EQ(kernel.run().reason, StopReason::deadlock);
  EXPECT_FALSE(answered);
  EXPECT_EQ(store.requests_served(), 0U);
}

TEST(FrameStore, OnlyFrameStoreDevicesQualify) {
  const PlatformSpec card = load_platform(kPlatforms / "pc-card.toml");
  Kernel kernel;
  LinkNetwork network(kernel, card);
  EXPECT_THROW(FrameStore(network, *card.find_device("host"), {}), std::invalid_argument);
}

TEST(FrameStore, HandsEachUploadToTheSinkWithItsLink) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  Cpu& module1 = kernel.add_cpu("module1");
  LinkNetwork network(kernel, onboard);
  std::vector<std::pair<int, std::vector<std::byte>>> received;
  FrameStore store(
      network, *onboard.find_device("rover_io"),
      [](int camera) { return test_image(camera, 128 * 128); },
      [&](int link, std::vector<std::byte> bytes) {
        received.emplace_back(link, std::move(bytes));
      });
  const std::vector<std::byte> payload = test_image(2, 300);
  kernel.spawn(module1, "telemetry", [&] {
    LinkPort& devices = network.require_port("module1", 3);
    // 300 = 0x012C, little-endian after the request byte; then an empty upload.
    const std::byte header[] = {FrameStore::kUploadRequest, std::byte{0x2C}, std::byte{0x01},
                                std::byte{0}, std::byte{0}};
    devices.output(header);
    devices.output(payload);
    const std::byte empty[] = {FrameStore::kUploadRequest, std::byte{0}, std::byte{0}, std::byte{0},
                               std::byte{0}};
    devices.output(empty);
    // The store still answers image requests afterwards.
    const std::byte camera0{0};
    std::vector<std::byte> left(128 * 128);
    devices.output(std::span(&camera0, 1));
    devices.input(left);
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  ASSERT_EQ(received.size(), 2U);
  EXPECT_EQ(received[0].first, 1); // module1.link3 is wired to rover_io.link1
  EXPECT_EQ(received[0].second, payload);
  EXPECT_TRUE(received[1].second.empty());
  EXPECT_EQ(store.uploads_received(), 2U);
  EXPECT_EQ(store.requests_served(), 1U);
  // Each end counts what it sent: two headers, the payload and the request; the image back.
  const LinkPort& module1_end = network.require_port("module1", 3);
  const LinkPort& store_end = network.require_port("rover_io", 1);
  EXPECT_EQ(module1_end.bytes_sent(), 5U + 300U + 5U + 1U);
  EXPECT_EQ(store_end.bytes_sent(), 128U * 128U);
  // Data packets of 11 bits at 10 Mbit/s follow each other on the wire without overlapping, so
  // every byte but the last holds the wire at least 1.1 us (the last one's acknowledge may come
  // back before its stop bit).
  EXPECT_GE(to_microseconds(store_end.output_busy_time()), (128 * 128 - 1) * 1.1);
  EXPECT_LE(store_end.output_busy_time(), kernel.now());
}

} // namespace
} // namespace marsokhod::emulator
