#include "gfield/printable.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace gfield {
namespace {

/// Length of the valid UTF-8 sequence starting at `s` (1 to 4), or 0 when it is not one (overlong
/// forms, surrogates and code points above U+10FFFF are not valid).
size_t utf8_sequence(std::string_view s) {
  const auto byte = [&](size_t i) { return std::uint8_t(s[i]); };
  const std::uint8_t b0 = byte(0);
  size_t length = 0;
  std::uint32_t lowest = 0;
  if (b0 < 0x80) {
    return 1;
  } else if ((b0 & 0xE0) == 0xC0) {
    length = 2;
    lowest = 0x80;
  } else if ((b0 & 0xF0) == 0xE0) {
    length = 3;
    lowest = 0x800;
  } else if ((b0 & 0xF8) == 0xF0) {
    length = 4;
    lowest = 0x10000;
  } else {
    return 0;
  }
  if (s.size() < length) {
    return 0;
  }
  std::uint32_t code = b0 & (0x7F >> length);
  for (size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) {
      return 0;
    }
    code = (code << 6) | (byte(i) & 0x3F);
  }
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  return code < lowest || code > 0x10FFFF || surrogate ? 0 : length;
}

}  // namespace

std::string printable(std::string_view text) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size()) {
    const std::uint8_t c = std::uint8_t(text[i]);
    const size_t length = utf8_sequence(text.substr(i));
    if (length > 1) {
      out.append(text.substr(i, length));
      i += length;
      continue;
    }
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (length == 0 || c < 0x20 || c == 0x7F) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    } else {
      out += char(c);
    }
    ++i;
  }
  return out;
}

std::string float_text(float value) {
  char text[32] = "";
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, double(value));
    if (std::strtof(text, nullptr) == value)
      break;
  }
  return text;
}

std::string double_text(double value) {
  char text[40] = "";
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value)
      break;
  }
  return text;
}

}  // namespace gfield
