// Byte, line, token and format-aware damage to valid files, reproducible from (seed, index).
#include "fuzz/mutation_engine.hpp"

#include <algorithm>
#include <random>

namespace marsokhod::fuzz {
namespace {

// splitmix64: spreads consecutive indices over unrelated mt19937_64 seeds.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class Damage {
public:
  Damage(Bytes& bytes, std::uint64_t seed) : bytes_(bytes), random_(seed) {}

  std::size_t below(std::size_t bound) {
    return bound == 0 ? 0 : static_cast<std::size_t>(random_() % bound);
  }
  std::size_t position() { return below(bytes_.size() + 1); }
  const std::string& token() {
    const auto& tokens = hostile_tokens();
    return tokens[below(tokens.size())];
  }

  void flip_bit() {
    if (!bytes_.empty())
      bytes_[below(bytes_.size())] ^= static_cast<char>(1U << below(8));
  }
  void random_byte() {
    if (!bytes_.empty())
      bytes_[below(bytes_.size())] = static_cast<char>(below(256));
  }
  void erase_range() {
    const std::size_t at = position();
    bytes_.erase(at, 1 + below(std::max<std::size_t>(16, bytes_.size() / 8)));
  }
  void duplicate_range() {
    const std::size_t at = position();
    const std::string piece = bytes_.substr(at, 1 + below(64));
    bytes_.insert(position(), piece);
  }
  void truncate() { bytes_.resize(position()); }
  void splice_token() { bytes_.insert(position(), token()); }
  void deep_nesting() { bytes_.insert(position(), std::string(10000, '[')); }
  void long_line() {
    bytes_.insert(position(), below(2) == 0 ? std::string(100000, 'x') : std::string(5000, '9'));
  }

  // Lines as [start, end) ranges, newline excluded.
  std::vector<std::pair<std::size_t, std::size_t>> lines() const {
    std::vector<std::pair<std::size_t, std::size_t>> found;
    std::size_t start = 0;
    while (start < bytes_.size()) {
      std::size_t end = bytes_.find('\n', start);
      if (end == std::string::npos)
        end = bytes_.size();
      found.emplace_back(start, end);
      start = end + 1;
    }
    return found;
  }
  void line_step(int kind) {
    const auto all = lines();
    if (all.size() < 2)
      return splice_token();
    const auto [a0, a1] = all[below(all.size())];
    const auto [b0, b1] = all[below(all.size())];
    const std::string a = bytes_.substr(a0, a1 - a0);
    const std::string b = bytes_.substr(b0, b1 - b0);
    if (kind == 0 && a0 != b0) { // swap: replace the later one first so offsets stay valid
      const bool a_first = a0 < b0;
      const auto [l0, l1] = a_first ? std::pair{b0, b1} : std::pair{a0, a1};
      const auto [f0, f1] = a_first ? std::pair{a0, a1} : std::pair{b0, b1};
      bytes_.replace(l0, l1 - l0, a_first ? a : b);
      bytes_.replace(f0, f1 - f0, a_first ? b : a);
    } else if (kind == 1) {
      bytes_.insert(b0, a + "\n");
    } else {
      bytes_.erase(a0, std::min(a1 + 1, bytes_.size()) - a0);
    }
  }

  // A run that looks like a number ([-+]digits[.digits][e[-+]digits]) within `limit` bytes.
  void replace_number(std::size_t limit) {
    std::vector<std::pair<std::size_t, std::size_t>> numbers;
    const std::size_t end = std::min(limit, bytes_.size());
    auto digit = [&](std::size_t i) {
      return i < bytes_.size() && bytes_[i] >= '0' && bytes_[i] <= '9';
    };
    for (std::size_t i = 0; i < end; ++i) {
      if (!digit(i) || (i > 0 && (digit(i - 1) || bytes_[i - 1] == '.')))
        continue;
      std::size_t start = (i > 0 && (bytes_[i - 1] == '-' || bytes_[i - 1] == '+')) ? i - 1 : i;
      std::size_t stop = i;
      while (stop < bytes_.size() &&
             (digit(stop) || bytes_[stop] == '.' || bytes_[stop] == 'e' || bytes_[stop] == 'E' ||
              ((bytes_[stop] == '-' || bytes_[stop] == '+') &&
               (bytes_[stop - 1] == 'e' || bytes_[stop - 1] == 'E'))))
        ++stop;
      numbers.emplace_back(start, stop);
      i = stop;
    }
    if (numbers.empty())
      return splice_token();
    const auto [start, stop] = numbers[below(numbers.size())];
    bytes_.replace(start, stop - start, token());
  }

  // One value of the format replaced: after '=' (TOML), after ':' (JSON), between tabs (TSV).
  void replace_value(Syntax syntax) {
    const auto all = lines();
    if (all.empty())
      return splice_token();
    std::vector<std::pair<std::size_t, std::size_t>> values;
    for (const auto& [start, end] : all) {
      const std::string line = bytes_.substr(start, end - start);
      if (syntax == Syntax::toml) {
        const std::size_t equals = line.find('=');
        if (equals != std::string::npos && line.find('#') > equals)
          values.emplace_back(start + equals + 1, start + std::min(line.find('#'), line.size()));
      } else if (syntax == Syntax::json) {
        for (std::size_t colon = line.find(':'); colon != std::string::npos;
             colon = line.find(':', colon + 1)) {
          const std::size_t stop = line.find_first_of(",}\n", colon);
          values.emplace_back(start + colon + 1, start + std::min(stop, line.size()));
        }
      } else {
        std::size_t field = 0;
        for (std::size_t tab = 0; tab <= line.size(); ++tab) {
          if (tab == line.size() || line[tab] == '\t') {
            values.emplace_back(start + field, start + tab);
            field = tab + 1;
          }
        }
      }
    }
    if (values.empty())
      return splice_token();
    const auto [start, stop] = values[below(values.size())];
    std::string value = token();
    if (syntax != Syntax::tsv && below(3) == 0)
      value = "\"" + value + "\"";
    else if (syntax == Syntax::toml)
      value = " " + value;
    bytes_.replace(start, stop - start, value);
  }

  void step(Syntax syntax) {
    const bool text = syntax != Syntax::binary;
    // Binary inputs get fewer line steps and keep number replacement to the header.
    switch (below(text ? 14 : 11)) {
    case 0:
      return flip_bit();
    case 1:
      return random_byte();
    case 2:
      return erase_range();
    case 3:
      return duplicate_range();
    case 4:
      return below(4) == 0 ? truncate() : flip_bit();
    case 5:
      return splice_token();
    case 6:
      return replace_number(text ? bytes_.size() : 64);
    case 7:
      return replace_number(text ? bytes_.size() : 64);
    case 8:
      return line_step(static_cast<int>(below(3)));
    case 9:
      return below(8) == 0 ? deep_nesting() : splice_token();
    case 10:
      return below(8) == 0 ? long_line() : random_byte();
    default:
      return replace_value(syntax);
    }
  }

private:
  Bytes& bytes_;
  std::mt19937_64 random_;
};

} // namespace

const std::vector<std::string>& hostile_tokens() {
  static const std::vector<std::string> tokens = {"nan",
                                                  "-nan",
                                                  "inf",
                                                  "-inf",
                                                  "1e308",
                                                  "1e309",
                                                  "-0",
                                                  "2147483648",
                                                  "4294967296",
                                                  "4294967297",
                                                  "9223372036854775807",
                                                  "9223372036854775808",
                                                  "-1",
                                                  "18446744073709551615",
                                                  "",
                                                  "[",
                                                  "]]",
                                                  "[[x]]",
                                                  "=",
                                                  "\"",
                                                  "\\",
                                                  "\n",
                                                  "../",
                                                  "/",
                                                  "\t",
                                                  "0",
                                                  "-2147483649",
                                                  "1e-320",
                                                  "0x7fffffff",
                                                  "{",
                                                  "}",
                                                  "\"\"",
                                                  ":",
                                                  ",",
                                                  "#",
                                                  "'",
                                                  "\"\\u0000\"",
                                                  "null",
                                                  "true",
                                                  "[]",
                                                  "{}",
                                                  "../../../../etc/passwd",
                                                  "-",
                                                  "1.5",
                                                  "1e400"};
  return tokens;
}

std::uint64_t stable_hash(std::string_view text, std::uint64_t start) {
  std::uint64_t hash = start;
  for (const char c : text)
    hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return hash;
}

Bytes MutationEngine::mutate(const Bytes& base, Syntax syntax, std::uint64_t index) const {
  Bytes bytes = base;
  Damage damage(bytes, mix(seed_ ^ mix(index)));
  const std::size_t steps = 1 + damage.below(4);
  for (std::size_t i = 0; i < steps; ++i)
    damage.step(syntax);
  return bytes;
}

} // namespace marsokhod::fuzz
