// The cameras' frame store: answers an image request on each of its links.

#include "marsokhod/emulator/links/link_frame_store.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace marsokhod::emulator {

FrameStore::FrameStore(LinkNetwork& network, const DeviceSpec& device, ImageSource source,
                       UploadSink uploads)
    : device_(device), source_(std::move(source)), uploads_sink_(std::move(uploads)) {
  if (device_.kind != DeviceKind::frame_store)
    throw std::invalid_argument(
        fmt::format("device {} is a {}, not a frame store", device_.name, to_string(device_.kind)));
  for (int link = 0; link < device_.links; ++link) {
    LinkPort* port = network.port(device_.name, link);
    if (port == nullptr)
      continue;
    servers_.push_back(std::make_unique<Server>(Server{port, link, std::byte{}, {}, {}, {}}));
    listen(*servers_.back());
  }
}

std::size_t FrameStore::image_bytes() const {
  const auto pixels = static_cast<std::size_t>(device_.image_width) *
                      static_cast<std::size_t>(device_.image_height);
  return pixels * (device_.bits_per_pixel > 8 ? 2 : 1);
}

void FrameStore::listen(Server& server) {
  server.port->start_input(
      std::span(&server.request, 1), [this, &server] { answer(server); });
}

void FrameStore::answer(Server& server) {
  if (server.request == kUploadRequest) {
    server.port->start_input(server.length, [this, &server] { receive_upload(server); });
    return;
  }
  if (server.request == kReport) {
    server.port->start_input(server.report, [this, &server] {
      if (report_sink_)
        report_sink_(server.link, server.report[0], server.report[1]);
      listen(server);
    });
    return;
  }
  if (server.request == kHeartbeat) {
    if (heartbeat_sink_)
      heartbeat_sink_(server.link);
    listen(server);
    return;
  }
  const int camera = std::to_integer<int>(server.request);
  if (camera >= device_.cameras) {
    listen(server);
    return;
  }
  server.image = source_(camera);
  if (server.image.size() != image_bytes())
    throw std::logic_error(fmt::format("frame store {}: camera {} gave {} bytes, not {}",
                                       device_.name, camera, server.image.size(), image_bytes()));
  ++served_;
  server.port->start_output(server.image, [this, &server] { listen(server); });
}

void FrameStore::reset_link(int link) {
  for (const auto& server : servers_) {
    if (server->link != link)
      continue;
    Link& wire = server->port->link();
    wire.set_powered(server->port->end(), false);
    wire.set_powered(server->port->end(), true);
    server->image.clear();
    listen(*server);
  }
}

void FrameStore::receive_upload(Server& server) {
  std::size_t bytes = 0;
  for (std::size_t i = server.length.size(); i-- > 0;)
    bytes = bytes << 8 | std::to_integer<std::size_t>(server.length[i]);
  if (bytes > kMaxUploadBytes)
    return; // a sender gone wrong: this link is no longer listened to
  server.image.assign(bytes, std::byte{});
  const auto deliver = [this, &server] {
    ++uploads_;
    if (uploads_sink_)
      uploads_sink_(server.link, std::move(server.image));
    server.image.clear();
    listen(server);
  };
  if (bytes == 0) {
    deliver();
    return;
  }
  server.port->start_input(server.image, deliver);
}

} // namespace marsokhod::emulator
