// HeaderScanner, the netpbm-style header reader (private to the image room's codecs).
#pragma once

// Internal: reads the ASCII headers shared by PNM and PFM files.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace marsokhod::imaging::detail {

/// Walks the text header of a netpbm-style file. With comments enabled, '#' through the next CR
/// or LF is cut out of the header wherever it appears before the raster, as the netpbm
/// specification says, even in the middle of a number.
class HeaderScanner {
public:
  /// `cut`: the file goes on beyond `bytes` (its first kImageHeaderWindow bytes), so running
  /// out of bytes means the header is too long, not that the file is truncated.
  HeaderScanner(std::span<const std::uint8_t> bytes, std::string_view name, bool comments,
                bool cut = false)
      : bytes_(bytes), name_(name), comments_(comments), cut_(cut) {}

  /// Offset of the next unread byte.
  std::size_t position() const { return position_; }

  /// Skips whitespace and comments; at least one whitespace byte must be there.
  void skip_separator(std::string_view after);

  /// Reads an unsigned decimal number that must lie in lo..hi; `what` names it in messages.
  int read_number(std::string_view what, int lo, int hi);

  /// Skips the separator after the magic number, then reads the width and the height (each
  /// 1..kMaxImageSide) and the separator after them, as PNM and PFM headers put them.
  void read_size(int& width, int& height);

  /// Reads bytes up to the next whitespace (at most max_length of them).
  std::string read_token(std::string_view what, std::size_t max_length);

  /// Consumes exactly one whitespace byte: the delimiter before binary data.
  void expect_single_whitespace(std::string_view after);

private:
  bool at_end() const { return position_ >= bytes_.size(); }
  std::uint8_t peek() const { return bytes_[position_]; }
  void skip_comment();
  std::string describe_next() const;
  [[noreturn]] void fail_here(std::string_view problem) const;

  std::span<const std::uint8_t> bytes_;
  std::string_view name_;
  bool comments_;
  bool cut_;
  std::size_t position_ = 0;
};

/// The whitespace bytes of the netpbm specification.
bool is_header_whitespace(std::uint8_t byte);

} // namespace marsokhod::imaging::detail
