// A small recursive-descent JSON parser that records value locations.

#include "gfield/located_json.hpp"

#include "gfield/limits.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace gfield {
namespace {

class Parser {
 public:
  Parser(const std::string& text, LocatedJson& out) : text_(text), out_(out) {}

  bool parse(std::string& error) {
    skip_space();
    if (!value(out_.value, "", 0)) {
      error = message_;
      return false;
    }
    skip_space();
    if (pos_ != text_.size()) {
      fail("unexpected text after the JSON value");
      error = message_;
      return false;
    }
    return true;
  }

 private:
  bool fail(const std::string& what) {
    if (message_.empty()) {
      message_ = std::to_string(line_) + ":" + std::to_string(pos_ - line_start_ + 1) + ": " + what;
    }
    return false;
  }

  JsonLocation here() const { return {line_, int(pos_ - line_start_ + 1)}; }

  void skip_space() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        line_start_ = pos_ + 1;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        return;
      }
      ++pos_;
    }
  }

  bool literal(const char* word, nlohmann::json value, nlohmann::json& out) {
    const std::string w(word);
    if (text_.compare(pos_, w.size(), w) != 0)
      return fail("invalid literal");
    pos_ += w.size();
    out = std::move(value);
    return true;
  }

  bool value(nlohmann::json& out, const std::string& pointer, int depth) {
    if (depth > kMaxJsonDepth)
      return fail("nesting deeper than " + std::to_string(kMaxJsonDepth));
    if (pos_ >= text_.size())
      return fail("unexpected end of file, expected a value");
    out_.locations[pointer] = here();
    const char c = text_[pos_];
    switch (c) {
      case '{':
        return object(out, pointer, depth);
      case '[':
        return array(out, pointer, depth);
      case '"': {
        std::string s;
        if (!string(s))
          return false;
        out = std::move(s);
        return true;
      }
      case 't':
        return literal("true", true, out);
      case 'f':
        return literal("false", false, out);
      case 'n':
        return literal("null", nullptr, out);
      default:
        if (c == '-' || (c >= '0' && c <= '9'))
          return number(out);
        return fail(std::string("unexpected character '") + c + "'");
    }
  }

  bool object(nlohmann::json& out, const std::string& pointer, int depth) {
    out = nlohmann::json::object();
    ++pos_;  // {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '}') {
      ++pos_;
      return true;
    }
    while (true) {
      skip_space();
      if (pos_ >= text_.size() || text_[pos_] != '"')
        return fail("expected a key string");
      const JsonLocation key_location = here();
      std::string key;
      if (!string(key))
        return false;
      if (out.contains(key))
        return fail_at(key_location, "duplicate key \"" + key + "\"");
      skip_space();
      if (pos_ >= text_.size() || text_[pos_] != ':')
        return fail("expected ':' after a key");
      ++pos_;
      skip_space();
      nlohmann::json child;
      if (!value(child, json_pointer_child(pointer, key), depth + 1))
        return false;
      out[key] = std::move(child);
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == '}') {
        ++pos_;
        return true;
      }
      return fail("expected ',' or '}' in an object");
    }
  }

  bool fail_at(JsonLocation location, const std::string& what) {
    if (message_.empty()) {
      message_ =
          std::to_string(location.line) + ":" + std::to_string(location.column) + ": " + what;
    }
    return false;
  }

  bool array(nlohmann::json& out, const std::string& pointer, int depth) {
    out = nlohmann::json::array();
    ++pos_;  // [
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == ']') {
      ++pos_;
      return true;
    }
    while (true) {
      skip_space();
      nlohmann::json child;
      if (!value(child, json_pointer_child(pointer, out.size()), depth + 1))
        return false;
      out.push_back(std::move(child));
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == ']') {
        ++pos_;
        return true;
      }
      return fail("expected ',' or ']' in an array");
    }
  }

  static void append_utf8(std::string& s, std::uint32_t cp) {
    if (cp < 0x80) {
      s += char(cp);
    } else if (cp < 0x800) {
      s += char(0xC0 | (cp >> 6));
      s += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += char(0xE0 | (cp >> 12));
      s += char(0x80 | ((cp >> 6) & 0x3F));
      s += char(0x80 | (cp & 0x3F));
    } else {
      s += char(0xF0 | (cp >> 18));
      s += char(0x80 | ((cp >> 12) & 0x3F));
      s += char(0x80 | ((cp >> 6) & 0x3F));
      s += char(0x80 | (cp & 0x3F));
    }
  }

  bool hex4(std::uint32_t& v) {
    if (pos_ + 4 > text_.size())
      return fail("truncated \\u escape");
    v = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = text_[pos_++];
      v <<= 4;
      if (c >= '0' && c <= '9') {
        v |= std::uint32_t(c - '0');
      } else if (c >= 'a' && c <= 'f') {
        v |= std::uint32_t(c - 'a' + 10);
      } else if (c >= 'A' && c <= 'F') {
        v |= std::uint32_t(c - 'A' + 10);
      } else {
        return fail("invalid \\u escape");
      }
    }
    return true;
  }

  bool string(std::string& out) {
    ++pos_;  // opening quote
    while (true) {
      if (pos_ >= text_.size())
        return fail("unterminated string");
      const char c = text_[pos_];
      if (c == '"') {
        ++pos_;
        return true;
      }
      if (static_cast<unsigned char>(c) < 0x20)
        return fail("control character in a string");
      if (c != '\\') {
        out += c;
        ++pos_;
        continue;
      }
      ++pos_;
      if (pos_ >= text_.size())
        return fail("unterminated string");
      const char e = text_[pos_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          std::uint32_t cp = 0;
          if (!hex4(cp))
            return false;
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            std::uint32_t low = 0;
            if (text_.compare(pos_, 2, "\\u") != 0)
              return fail("unpaired surrogate in \\u escape");
            pos_ += 2;
            if (!hex4(low))
              return false;
            if (low < 0xDC00 || low > 0xDFFF)
              return fail("invalid surrogate pair");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            return fail("unpaired surrogate in \\u escape");
          }
          append_utf8(out, cp);
          break;
        }
        default:
          return fail(std::string("invalid escape '\\") + e + "'");
      }
    }
  }

  bool number(nlohmann::json& out) {
    const size_t start = pos_;
    auto digits = [&] {
      const size_t s = pos_;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9')
        ++pos_;
      return pos_ > s;
    };
    bool integer = true;
    if (text_[pos_] == '-')
      ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '0') {
      ++pos_;
    } else if (!digits()) {
      return fail("invalid number");
    }
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      integer = false;
      if (!digits())
        return fail("invalid number: digits expected after '.'");
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      integer = false;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-'))
        ++pos_;
      if (!digits())
        return fail("invalid number: digits expected in the exponent");
    }
    const char* first = text_.data() + start;
    const char* last = text_.data() + pos_;
    if (integer) {
      std::int64_t v = 0;
      const auto r = std::from_chars(first, last, v);
      if (r.ec == std::errc() && r.ptr == last) {
        out = v;
        return true;
      }
    }
    double d = 0.0;
    const auto r = std::from_chars(first, last, d);
    if (r.ec == std::errc::result_out_of_range || !std::isfinite(d)) {
      pos_ = start;
      return fail("number " + std::string(first, last) + " is out of range (not finite)");
    }
    if (r.ec != std::errc() || r.ptr != last) {
      pos_ = start;
      return fail("invalid number");
    }
    out = d;
    return true;
  }

  const std::string& text_;
  LocatedJson& out_;
  size_t pos_ = 0;
  int line_ = 1;
  size_t line_start_ = 0;
  std::string message_;
};

}  // namespace

std::string json_pointer_child(const std::string& pointer, const std::string& key) {
  std::string escaped;
  for (const char c : key) {
    if (c == '~') {
      escaped += "~0";
    } else if (c == '/') {
      escaped += "~1";
    } else {
      escaped += c;
    }
  }
  return pointer + "/" + escaped;
}

std::string json_pointer_child(const std::string& pointer, size_t index) {
  return pointer + "/" + std::to_string(index);
}

JsonLocation LocatedJson::at(const std::string& pointer) const {
  std::string p = pointer;
  while (true) {
    const auto it = locations.find(p);
    if (it != locations.end())
      return it->second;
    if (p.empty())
      return {1, 1};
    p = p.substr(0, p.rfind('/'));
  }
}

bool parse_located_json(const std::string& text, LocatedJson& out, std::string& error) {
  LocatedJson result;
  Parser parser(text, result);
  if (!parser.parse(error))
    return false;
  out = std::move(result);
  return true;
}

}  // namespace gfield
