#include "geometry/text_scan.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "gfield/printable.hpp"

namespace gfield::text {

bool Lines::next(std::string_view& line) {
  if (position_ >= data_.size()) {
    return false;
  }
  const size_t end = data_.find('\n', position_);
  line_ended_ = end != std::string_view::npos;
  const size_t stop = line_ended_ ? end : data_.size();
  line = data_.substr(position_, stop - position_);
  if (!line.empty() && line.back() == '\r') {
    line.remove_suffix(1);
  }
  position_ = line_ended_ ? end + 1 : data_.size();
  ++number_;
  return true;
}

bool Words::next(std::string_view& word) {
  size_t start = 0;
  while (start < rest_.size() && is_space(rest_[start])) {
    ++start;
  }
  size_t end = start;
  while (end < rest_.size() && !is_space(rest_[end])) {
    ++end;
  }
  word = rest_.substr(start, end - start);
  rest_.remove_prefix(end);
  return !word.empty();
}

bool Words::empty() const {
  for (const char c : rest_) {
    if (!is_space(c)) {
      return false;
    }
  }
  return true;
}

bool WordStream::next(std::string_view& word) {
  while (position_ < data_.size() && (is_space(data_[position_]) || data_[position_] == '\n')) {
    line_ += data_[position_] == '\n' ? 1 : 0;
    ++position_;
  }
  const size_t start = position_;
  while (position_ < data_.size() && !is_space(data_[position_]) && data_[position_] != '\n') {
    ++position_;
  }
  word = data_.substr(start, position_ - start);
  return !word.empty();
}

void WordStream::skip_line() {
  const size_t end = data_.find('\n', position_);
  position_ = end == std::string_view::npos ? data_.size() : end;
}

bool parse_double(std::string_view word, double& value) {
  if (!word.empty() && word[0] == '+') {
    word.remove_prefix(1);
    if (!word.empty() && (word[0] == '+' || word[0] == '-')) {
      return false;
    }
  }
  if (word.empty()) {
    return false;
  }
  const char* first = word.data();
  const char* last = first + word.size();
  const auto result = std::from_chars(first, last, value, std::chars_format::general);
  if (result.ptr != last) {
    return false;
  }
  if (result.ec == std::errc::result_out_of_range) {
    // from_chars leaves `value` alone when out of range: tell overflow from underflow by the
    // exponent's sign, as strtod would.
    const size_t e = word.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < word.size() && word[e + 1] == '-';
    const bool negative = word[0] == '-';
    value = tiny ? (negative ? -0.0 : 0.0)
                 : (negative ? -std::numeric_limits<double>::infinity()
                             : std::numeric_limits<double>::infinity());
    return true;
  }
  return result.ec == std::errc();
}

bool parse_int64(std::string_view word, std::int64_t& value) {
  if (!word.empty() && word[0] == '+') {
    word.remove_prefix(1);
    if (!word.empty() && word[0] == '-') {
      return false;
    }
  }
  if (word.empty()) {
    return false;
  }
  const char* last = word.data() + word.size();
  const auto result = std::from_chars(word.data(), last, value);
  return result.ec == std::errc() && result.ptr == last;
}

std::string quoted(std::string_view word) {
  constexpr size_t kMax = 40;
  const bool cut = word.size() > kMax;
  std::string out = "'";
  out += printable(word.substr(0, kMax));
  out += cut ? "...'" : "'";
  return out;
}

}  // namespace gfield::text
