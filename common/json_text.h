// Text as the content of a JSON string: quotes and backslashes escaped, control characters as
// \uXXXX. Shared by the CLI's JSON report and the .glb writer's JSON chunk. Header-only.
#pragma once

#include <cstdio>
#include <string>

namespace vrs_common {

inline std::string json_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      out += b;
      continue;
    }
    out += c;
  }
  return out;
}

} // namespace vrs_common
