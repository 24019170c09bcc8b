#pragma once
// Scanning text formats held in memory: lines, whitespace-separated words, numbers. Shared by the
// mesh readers and the parameterised-mesh reader. Words are views into the data (no copies).

#include <cstdint>
#include <string>
#include <string_view>

namespace gfield::text {

/// The lines of `data`, ended by "\n" (a "\r" before it is dropped); the last line may lack its
/// "\n".
class Lines {
 public:
  explicit Lines(std::string_view data) : data_(data) {}
  /// The next line without its line end; false at the end of the data.
  bool next(std::string_view& line);
  /// 1-based number of the line `next` returned last.
  size_t number() const { return number_; }
  /// Bytes not yet returned.
  size_t remaining() const { return data_.size() - position_; }
  /// True when the line `next` returned last was ended by "\n" (not cut off by the end of data).
  bool line_ended() const { return line_ended_; }

 private:
  std::string_view data_;
  size_t position_ = 0;
  size_t number_ = 0;
  bool line_ended_ = false;
};

/// The words of one line, separated by spaces, tabs, \v, \f or \r.
class Words {
 public:
  explicit Words(std::string_view line) : rest_(line) {}
  /// The next word; false when none is left.
  bool next(std::string_view& word);
  /// True when no word is left.
  bool empty() const;

 private:
  std::string_view rest_;
};

/// Whitespace-separated words across lines (PLY and STL text data), with the line of each.
class WordStream {
 public:
  explicit WordStream(std::string_view data) : data_(data) {}
  /// The next word; false at the end of the data.
  bool next(std::string_view& word);
  /// Drops what is left of the current line (after the last word returned).
  void skip_line();
  /// 1-based line of the word `next` returned last.
  size_t line() const { return line_; }
  /// Bytes not yet read.
  size_t remaining() const { return data_.size() - position_; }

 private:
  std::string_view data_;
  size_t position_ = 0;
  size_t line_ = 1;
};

/// True for the separators `Words` and `WordStream` split at (besides "\n").
inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// The whole word as a decimal number: optional sign, digits, fraction, exponent. "nan" and "inf"
/// parse too (callers refuse non-finite values with their own message); out-of-range magnitudes
/// come back as +-infinity or 0.
bool parse_double(std::string_view word, double& value);
/// The whole word as a decimal integer with an optional sign; false on overflow of 64 bits.
bool parse_int64(std::string_view word, std::int64_t& value);
/// The word quoted for an error message: 'word', cut to 40 bytes, printable (see printable.hpp).
std::string quoted(std::string_view word);

}  // namespace gfield::text
