#pragma once
// The bits of JSON fgdwa_node writes (its events and its config), by hand:
// a number to 17 digits, and a string with its quotes, backslashes and
// control characters escaped.
#include <cmath>
#include <cstdio>
#include <string>

namespace fgdwa_ros {

// JSON of a number that may be infinite or NaN (Python's json reads these words).
inline std::string json_number(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// A JSON string of `text`.
inline std::string json_text(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace fgdwa_ros
