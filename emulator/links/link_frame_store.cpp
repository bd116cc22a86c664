// The cameras' frame store: answers an image request on each of its links.

#include "marsokhod/emulator/links/link_frame_store.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace marsokhod::emulator {

FrameStore::FrameStore(LinkNetwork& network, const DeviceSpec& device, ImageSource source)
    : device_(device), source_(std::move(source)) {
  if (device_.kind != DeviceKind::frame_store)
    throw std::invalid_argument(
        fmt::format("device {} is a {}, not a frame store", device_.name, to_string(device_.kind)));
  for (int link = 0; link < device_.links; ++link) {
    LinkPort* port = network.port(device_.name, link);
    if (port == nullptr)
      continue;
    servers_.push_back(std::make_unique<Server>(Server{port, std::byte{}, {}}));
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

} // namespace marsokhod::emulator
