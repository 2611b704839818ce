#include "glb_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace vrs {

void put_u32(std::vector<uint8_t>& out, uint32_t x) {
  for (int i = 0; i < 4; ++i)
    out.push_back(uint8_t(x >> (8 * i)));
}

std::vector<uint8_t> index_bytes(const std::vector<uint32_t>& idx, size_t vertices, bool& wide) {
  wide = vertices >= 65535;
  std::vector<uint8_t> out(idx.size() * (wide ? 4 : 2));
  for (size_t i = 0; i < idx.size(); ++i)
    if (wide)
      std::memcpy(out.data() + 4 * i, &idx[i], 4);
    else {
      const uint16_t s = uint16_t(idx[i]);
      std::memcpy(out.data() + 2 * i, &s, 2);
    }
  out.resize(pad4(out.size()), 0);
  return out;
}

std::string write_glb_file(const std::string& path, const std::string& json,
                           const std::vector<const std::vector<uint8_t>*>& pieces,
                           size_t* json_bytes_out) {
  size_t bin_bytes = 0;
  for (const auto* p : pieces)
    bin_bytes += pad4(p->size());
  std::vector<uint8_t> head;
  const size_t json_bytes = pad4(json.size());
  const size_t total = 12 + 8 + json_bytes + 8 + bin_bytes;
  if (total > 0xffffffffu) return "the file would need more than the 4 GiB a .glb can hold";
  put_u32(head, 0x46546C67); // "glTF"
  put_u32(head, 2);
  put_u32(head, uint32_t(total));
  put_u32(head, uint32_t(json_bytes));
  put_u32(head, 0x4E4F534A); // "JSON"
  head.insert(head.end(), json.begin(), json.end());
  head.resize(12 + 8 + json_bytes, ' ');
  put_u32(head, uint32_t(bin_bytes));
  put_u32(head, 0x004E4942); // "BIN\0"
  if (json_bytes_out) *json_bytes_out = json_bytes;

  const size_t slash = path.rfind('/');
  const std::string tmp = path.substr(0, slash + 1) + ".vrsimplify-" + std::to_string(getpid()) +
                          "-" + path.substr(slash + 1);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return "cannot write " + path + ": " + std::strerror(errno);
  static const uint8_t zeros[4] = {0, 0, 0, 0};
  bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
  for (const auto* p : pieces) {
    ok = ok && std::fwrite(p->data(), 1, p->size(), f) == p->size();
    const size_t pad = pad4(p->size()) - p->size();
    ok = ok && std::fwrite(zeros, 1, pad, f) == pad;
  }
  ok = std::fclose(f) == 0 && ok;
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return "cannot write " + path + ": " + why;
  }
  return "";
}

} // namespace vrs
