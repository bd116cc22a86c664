// The navigation program's messages: images, maps, text and lists as blocks on a channel.
#pragma once

// The protocols of the navigation program's channels (private to the layer). Every
// message is one block or a fixed sequence of blocks whose lengths both sides know from the
// cycle's image size, as occam protocols of fixed arrays do; a list is sent as its length,
// then its elements.

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav_program/channels/block_channel.hpp"

#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace marsokhod::nav_program::detail {

template <typename T>
std::span<const std::byte> bytes_of(const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  return std::as_bytes(std::span(&value, 1));
}

template <typename T>
void send_value(BlockChannel& channel, const T& value) {
  channel.send(bytes_of(value));
}

template <typename T>
T receive_value(BlockChannel& channel) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value{};
  channel.receive(std::as_writable_bytes(std::span(&value, 1)));
  return value;
}

/// An image row by row: one block per row, as `CHAN OF [width]T` would carry it.
template <typename T>
void send_image(BlockChannel& channel, imaging::ImageView<const T> image) {
  const auto row_elements = static_cast<std::size_t>(image.width() * image.channels());
  for (int y = 0; y < image.height(); ++y)
    channel.send(std::as_bytes(std::span(image.row(y), row_elements)));
}

/// Receives rows sent by send_image into the rows of `rows`, which both sides know the size of.
template <typename T>
void receive_rows(BlockChannel& channel, imaging::ImageView<T> rows) {
  const auto row_elements = static_cast<std::size_t>(rows.width() * rows.channels());
  for (int y = 0; y < rows.height(); ++y)
    channel.receive(std::as_writable_bytes(std::span(rows.row(y), row_elements)));
}

/// Receives an image of a size both sides know into a buffer from `memory`.
template <typename T>
imaging::Image<T> receive_image(BlockChannel& channel, int width, int height,
                                std::pmr::memory_resource* memory) {
  imaging::Image<T> image(width, height, 1, T{}, memory);
  receive_rows(channel, image.view());
  return image;
}

/// A list: its length, then its elements in one block.
template <typename T>
void send_list(BlockChannel& channel, std::span<const T> values) {
  send_value(channel, static_cast<std::uint32_t>(values.size()));
  if (!values.empty())
    channel.send(std::as_bytes(values));
}

template <typename T>
std::pmr::vector<T> receive_list(BlockChannel& channel, std::pmr::memory_resource* memory) {
  const auto size = receive_value<std::uint32_t>(channel);
  std::pmr::vector<T> values(size, T{}, memory);
  if (size > 0)
    channel.receive(std::as_writable_bytes(std::span(values)));
  return values;
}

inline void send_text(BlockChannel& channel, const std::string& text) {
  send_list(channel, std::span<const char>(text.data(), text.size()));
}

inline std::string receive_text(BlockChannel& channel, std::pmr::memory_resource* memory) {
  const std::pmr::vector<char> characters = receive_list<char>(channel, memory);
  return {characters.begin(), characters.end()};
}

} // namespace marsokhod::nav_program::detail
