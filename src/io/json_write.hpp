// JSON number and string output, shared by the result writer
// (result_json.cpp), the readers' messages and the web facade
// (web/api). Internal: not installed.
//
// Two number forms, each the shortest text that reads back as the same
// double, and each kept because bytes already written depend on it:
//  - JsonWriter::number (std::to_chars, integral values with ".0"): the
//    result file (the contract) and everything written with JsonWriter;
//  - format_number (nlohmann::json's printing): messages, and the game
//    records and web replies, which are nlohmann::ordered_json dumps.

#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "breakshot/vec.hpp"

namespace breakshot::json_io {

/// Shortest text that reads back as the same double, as nlohmann::json
/// prints it ("1.0", "1e-05", "100000.0"); "null" for infinity and NaN.
std::string format_number(double v);

/// Writes JSON text straight into a string: no tree, no heap node per
/// number (a gas run's result has a million events).
class JsonWriter {
 public:
  explicit JsonWriter(std::string& out) : out_(out) {}

  void raw(std::string_view s) { out_.append(s); }

  /// A number that reads back as exactly `v`. Integral values keep a
  /// ".0" so that readers in typed languages see a float every time.
  /// JSON has no infinity or NaN: they are written as null, which is
  /// still valid JSON (the command line refuses such a result anyway).
  void number(double v) {
    if (!std::isfinite(v)) {
      out_.append("null");
      return;
    }
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    const std::string_view text(buf, static_cast<std::size_t>(res.ptr - buf));
    out_.append(text);
    if (text.find_first_of(".e") == std::string_view::npos) out_.append(".0");
  }

  void string(std::string_view s) {
    static constexpr char kHex[] = "0123456789abcdef";
    out_.push_back('"');
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      switch (c) {
        case '"': out_.append("\\\""); break;
        case '\\': out_.append("\\\\"); break;
        case '\n': out_.append("\\n"); break;
        case '\r': out_.append("\\r"); break;
        case '\t': out_.append("\\t"); break;
        case '\b': out_.append("\\b"); break;
        case '\f': out_.append("\\f"); break;
        default:
          if (u < 0x20) {
            out_.append("\\u00");
            out_.push_back(kHex[u >> 4]);
            out_.push_back(kHex[u & 0xf]);
          } else {
            out_.push_back(c);
          }
      }
    }
    out_.push_back('"');
  }

  void vec2(Vec2 v) {
    out_.push_back('[');
    number(v.x);
    out_.append(", ");
    number(v.y);
    out_.push_back(']');
  }

  void vec3(Vec3 v) {
    out_.push_back('[');
    number(v.x);
    out_.append(", ");
    number(v.y);
    out_.append(", ");
    number(v.z);
    out_.push_back(']');
  }

 private:
  std::string& out_;
};

}  // namespace breakshot::json_io
