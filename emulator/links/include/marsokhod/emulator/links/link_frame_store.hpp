// The cameras' frame store: a device that answers image requests over its links.
#pragma once

#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace marsokhod::emulator {

/// The cameras' frame store behind a device's links (platform `kind = "frame_store"`). On every
/// wired link it waits for a one-byte request, the camera number, and answers with that
/// camera's image: image_height rows of image_width pixels, one byte per pixel for 8 bits, two
/// (little-endian) for 16. The request kUploadRequest instead announces an upload: a four-byte
/// little-endian length, then that many bytes, handed to the upload sink (telemetry, the wheel
/// commands' log); an upload longer than kMaxUploadBytes is refused and the link ignored from
/// then on. The request kHeartbeat is a module's heartbeat for the overswitch that sits on
/// the device links: it is handed to the heartbeat sink and gets no answer. The request kReport
/// is followed by two bytes a module reports to the overswitch (a link of its and what went
/// wrong there): handed to the report sink, no answer. A request for a camera
/// it does not have gets no answer. It runs on the link engines alone (no process), so it never
/// shows in a deadlock report.
class FrameStore {
public:
  /// The image a camera holds now; must return exactly image_bytes() bytes.
  using ImageSource = std::function<std::vector<std::byte>(int camera)>;
  /// Receives each upload with the device link it came in on.
  using UploadSink = std::function<void(int link, std::vector<std::byte> bytes)>;

  /// Receives each heartbeat with the device link it came in on.
  using HeartbeatSink = std::function<void(int link)>;
  /// Receives each report with the device link it came in on and its two bytes.
  using ReportSink = std::function<void(int link, std::byte first, std::byte second)>;

  static constexpr std::byte kUploadRequest{0xFF};
  static constexpr std::byte kHeartbeat{0xFE};
  static constexpr std::byte kReport{0xFD};
  static constexpr std::size_t kMaxUploadBytes = std::size_t{16} << 20;

  FrameStore(LinkNetwork& network, const DeviceSpec& device, ImageSource source,
             UploadSink uploads = {});
  FrameStore(const FrameStore&) = delete;
  FrameStore& operator=(const FrameStore&) = delete;

  std::size_t image_bytes() const;
  void set_heartbeat_sink(HeartbeatSink sink) { heartbeat_sink_ = std::move(sink); }
  void set_report_sink(ReportSink sink) { report_sink_ = std::move(sink); }
  /// Resets the device's end of `link` (its engines forget what they were doing) and listens
  /// for a request again: what the overswitch does to a module's device link when it restarts
  /// the program, so that a message cut short does not run into the next.
  void reset_link(int link);
  std::size_t requests_served() const { return served_; }
  std::size_t uploads_received() const { return uploads_; }

private:
  struct Server {
    LinkPort* port = nullptr;
    int link = 0;
    std::byte request{};
    std::array<std::byte, 4> length{};
    std::array<std::byte, 2> report{};
    std::vector<std::byte> image;
  };
  void listen(Server& server);
  void answer(Server& server);
  void receive_upload(Server& server);

  DeviceSpec device_;
  ImageSource source_;
  UploadSink uploads_sink_;
  HeartbeatSink heartbeat_sink_;
  ReportSink report_sink_;
  std::size_t uploads_ = 0;
  std::vector<std::unique_ptr<Server>> servers_;
  std::size_t served_ = 0;
};

} // namespace marsokhod::emulator
