// The netpbm-style ASCII header scanner shared by the PNM and PFM codecs.

#include "image/header_scanner.hpp"

#include "image/image_codec.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace marsokhod::imaging::detail {
namespace {

bool is_digit(std::uint8_t byte) {
  return byte >= '0' && byte <= '9';
}

// Digits beyond this many are elided in messages: the number is wrong anyway.
constexpr std::size_t kMaxQuotedDigits = 24;

} // namespace

bool is_header_whitespace(std::uint8_t byte) {
  return byte == ' ' || byte == '\t' || byte == '\n' || byte == '\r' || byte == '\v' ||
         byte == '\f';
}

void HeaderScanner::skip_comment() {
  while (!at_end()) {
    const std::uint8_t byte = peek();
    ++position_;
    if (byte == '\n' || byte == '\r')
      return;
  }
  fail_here("truncated header: comment runs to the end of the file");
}

void HeaderScanner::skip_separator(std::string_view after) {
  int whitespace = 0;
  bool comment = false;
  while (!at_end()) {
    if (comments_ && peek() == '#') {
      skip_comment();
      comment = true;
    } else if (is_header_whitespace(peek())) {
      ++whitespace;
      ++position_;
    } else {
      break;
    }
  }
  if (whitespace == 0)
    fail_here(fmt::format("expected whitespace after {}, found {}{}", after, describe_next(),
                          comment ? " (a comment is cut out with its line end, which therefore "
                                    "does not count as whitespace)"
                                  : ""));
}

int HeaderScanner::read_number(std::string_view what, int lo, int hi) {
  if (at_end() || !is_digit(peek()))
    fail_here(fmt::format("expected {} (a decimal number), found {}", what, describe_next()));
  std::string text;
  long long value = 0;
  while (!at_end()) {
    if (comments_ && peek() == '#') {
      skip_comment();
      continue;
    }
    if (!is_digit(peek()))
      break;
    if (text.size() < kMaxQuotedDigits)
      text.push_back(static_cast<char>(peek()));
    else if (text.size() == kMaxQuotedDigits)
      text += "...";
    // Saturating keeps overflowing numbers out of range instead of wrapping into it.
    value = std::min<long long>(value * 10 + (peek() - '0'), 1LL << 40);
    ++position_;
  }
  if (value < lo || value > hi)
    fail_here(fmt::format("{} {} is out of range {}..{}", what, text, lo, hi));
  return static_cast<int>(value);
}

std::string HeaderScanner::read_token(std::string_view what, std::size_t max_length) {
  std::string token;
  while (!at_end() && !is_header_whitespace(peek())) {
    if (token.size() == max_length)
      fail_here(fmt::format("{} is longer than {} characters", what, max_length));
    token.push_back(static_cast<char>(peek()));
    ++position_;
  }
  if (token.empty() || (cut_ && at_end()))
    fail_here(fmt::format("expected {}, found {}", what, describe_next()));
  return token;
}

void HeaderScanner::expect_single_whitespace(std::string_view after) {
  if (at_end() || !is_header_whitespace(peek()))
    fail_here(
        fmt::format("expected one whitespace byte after {}, found {}", after, describe_next()));
  ++position_;
}

std::string HeaderScanner::describe_next() const {
  if (at_end())
    return "the end of the file (truncated header)";
  const std::uint8_t byte = peek();
  if (byte >= 0x21 && byte < 0x7f)
    return fmt::format("'{}'", static_cast<char>(byte));
  return fmt::format("byte 0x{:02x}", byte);
}

void HeaderScanner::fail_here(std::string_view problem) const {
  if (cut_ && at_end())
    fail(name_, fmt::format("the header (comments included) runs past the first {} bytes; longer "
                            "headers are not read",
                            kImageHeaderWindow));
  fail(name_, problem);
}

void HeaderScanner::read_size(int& width, int& height) {
  skip_separator("the magic number");
  width = read_number("width", 1, kMaxImageSide);
  skip_separator("the width");
  height = read_number("height", 1, kMaxImageSide);
  skip_separator("the height");
}

} // namespace marsokhod::imaging::detail
