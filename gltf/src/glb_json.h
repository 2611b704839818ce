// The JSON chunk of a levels-of-detail .glb (glb.h): buffer views, accessors, one mesh and
// node per level, MSFT_lod on the finest level's node, the material. Text only: the binary
// layout is the writer's.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "json_text.h"
#include "vrs/glb.h"

namespace vrs {

class GlbJson {
 public:
  GlbJson(const GlbAttributes& a, size_t stride, int normal_at, int color_at, int uv_at)
      : a_(a), stride_(stride), normal_at_(normal_at), color_at_(color_at), uv_at_(uv_at) {}

  void buffer(size_t bytes) { buffer_bytes_ = bytes; }

  int view(size_t offset, size_t bytes, size_t stride, int target) {
    std::string v = "{\"buffer\":0,\"byteOffset\":" + num(offset) + ",\"byteLength\":" + num(bytes);
    if (stride) v += ",\"byteStride\":" + num(stride);
    if (target) v += ",\"target\":" + num(size_t(target));
    views_.push_back(v + "}");
    return int(views_.size() - 1);
  }

  // An extension object on the next level's primitive, declared in extensionsUsed (not
  // required: a reader without it draws the level alone).
  void primitive_extension(const std::string& name, const std::string& object) {
    extension_name_ = name;
    extension_ = object;
  }

  // A view decoded by EXT_meshopt_compression into the fallback buffer (buffer 1, no bytes) at
  // `offset`, from `compressed_bytes` of the binary chunk at `compressed_offset`. `stride`:
  // the record's size (an index's for TRIANGLES). A vertex stream's `tail` goes in the view's
  // extras: with it the stream's first bytes decode alone (meshopt_streams.h).
  int compressed_view(size_t offset, size_t bytes, size_t stride, int target,
                      size_t compressed_offset, size_t compressed_bytes, const char* mode,
                      size_t count, const std::vector<uint8_t>& tail) {
    const bool vertices = target == 34962;
    std::string v = "{\"buffer\":1,\"byteOffset\":" + num(offset) + ",\"byteLength\":" + num(bytes);
    if (vertices) v += ",\"byteStride\":" + num(stride);
    v += ",\"target\":" + num(size_t(target)) +
         ",\"extensions\":{\"EXT_meshopt_compression\":{\"buffer\":0,\"byteOffset\":" +
         num(compressed_offset) + ",\"byteLength\":" + num(compressed_bytes) +
         ",\"byteStride\":" + num(stride) + ",\"mode\":\"" + mode + "\",\"count\":" + num(count) +
         "}}";
    if (!tail.empty()) v += ",\"extras\":{\"vrsimplify\":{\"tail\":\"" + base64(tail) + "\"}}";
    views_.push_back(v + "}");
    compressed_ = true;
    return int(views_.size() - 1);
  }
  void fallback(size_t bytes) { fallback_bytes_ = bytes; }

  // One level: its accessors over the shared vertex view (count = its prefix), its indices,
  // its mesh and node.
  // `stream_bytes` (compressed files): the bytes of the vertex stream that hold its prefix.
  void level(int vertex_view, size_t vertices, const float* bounds, int index_view,
             size_t index_count, bool wide, double ratio, double error, size_t stream_bytes) {
    std::string attributes =
        "\"POSITION\":" + accessor(vertex_view, 0, 5126, vertices, "VEC3", false, bounds);
    if (normal_at_ >= 0)
      attributes += ",\"NORMAL\":" +
                    accessor(vertex_view, normal_at_, 5126, vertices, "VEC3", false, nullptr);
    if (color_at_ >= 0)
      attributes +=
          ",\"COLOR_0\":" + accessor(vertex_view, color_at_, 5121, vertices, "VEC4", true, nullptr);
    if (uv_at_ >= 0)
      attributes += ",\"TEXCOORD_0\":" +
                    accessor(vertex_view, uv_at_, 5126, vertices, "VEC2", false, nullptr);
    const std::string idx =
        accessor(index_view, 0, wide ? 5125 : 5123, index_count, "SCALAR", false, nullptr);
    const size_t k = meshes_.size();
    std::string extras = "{\"vrsimplify\":{\"ratio\":" + real(ratio) +
                         ",\"faces\":" + num(index_count / 3) + ",\"vertices\":" + num(vertices);
    if (error >= 0 && std::isfinite(error)) extras += ",\"error\":" + real(error);
    if (stream_bytes) extras += ",\"streamBytes\":" + num(stream_bytes);
    extras += "}}";
    std::string extension;
    if (!extension_.empty()) {
      extension = ",\"extensions\":{\"" + extension_name_ + "\":" + extension_ + "}";
      used_.push_back(extension_name_);
      extension_.clear();
    }
    meshes_.push_back("{\"name\":\"level " + num(k) + "\",\"primitives\":[{\"attributes\":{" +
                      attributes + "},\"indices\":" + idx + ",\"material\":0,\"mode\":4" +
                      extension + "}]," + "\"extras\":" + extras + "}");
    ratios_.push_back(ratio);
  }

  std::string finish() const {
    const size_t n = meshes_.size();
    std::string s = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"" +
                    vrs_common::json_text(a_.generator) + "\"}";
    std::string used;
    if (n > 1) used += "\"MSFT_lod\"";
    if (compressed_) used += std::string(used.empty() ? "" : ",") + "\"EXT_meshopt_compression\"";
    for (const std::string& name : used_)
      used += std::string(used.empty() ? "" : ",") + "\"" + name + "\"";
    if (!used.empty()) s += ",\"extensionsUsed\":[" + used + "]";
    if (compressed_) s += ",\"extensionsRequired\":[\"EXT_meshopt_compression\"]";
    s += ",\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[";
    for (size_t k = 0; k < n; ++k) {
      if (k) s += ",";
      s += "{\"name\":\"level " + num(k) + "\",\"mesh\":" + num(k);
      if (k == 0 && n > 1) {
        // Lower levels in order, and where each takes over: screen coverage falls with the
        // square root of the face ratio (the edge length a triangle keeps on screen); the
        // coarsest one is drawn down to nothing.
        s += ",\"extensions\":{\"MSFT_lod\":{\"ids\":[";
        for (size_t i = 1; i < n; ++i)
          s += (i > 1 ? "," : "") + num(i);
        s += "]}},\"extras\":{\"MSFT_screencoverage\":[";
        for (size_t i = 0; i < n; ++i)
          s += (i ? "," : "") +
               (i + 1 == n ? std::string("0") : real(0.5 * std::sqrt(ratios_[i] / ratios_[0])));
        s += "]}";
      }
      s += "}";
    }
    s += "],\"meshes\":[" + join(meshes_) + "]";
    s += ",\"materials\":[{\"pbrMetallicRoughness\":{\"metallicFactor\":0,\"roughnessFactor\":1";
    if (!a_.texture_uri.empty()) s += ",\"baseColorTexture\":{\"index\":0}";
    s += "},\"doubleSided\":false}]";
    if (!a_.texture_uri.empty())
      s += ",\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987}],\"textures\":[{\"sampler\":0,"
           "\"source\":0}],\"images\":[{\"uri\":\"" +
           vrs_common::json_text(uri_escaped(a_.texture_uri)) + "\"}]";
    s += ",\"accessors\":[" + join(accessors_) + "],\"bufferViews\":[" + join(views_) +
         "],\"buffers\":[{\"byteLength\":" + num(buffer_bytes_) + "}";
    if (compressed_)
      s += ",{\"byteLength\":" + num(fallback_bytes_) +
           ",\"extensions\":{\"EXT_meshopt_compression\":{\"fallback\":true}}}";
    s += "]}";
    return s;
  }

 private:
  std::string accessor(int view, size_t offset, int type, size_t count, const char* shape,
                       bool normalized, const float* bounds) {
    std::string x = "{\"bufferView\":" + num(size_t(view)) + ",\"byteOffset\":" + num(offset) +
                    ",\"componentType\":" + num(size_t(type)) + ",\"count\":" + num(count) +
                    ",\"type\":\"" + shape + "\"";
    if (normalized) x += ",\"normalized\":true";
    if (bounds)
      x += ",\"min\":[" + real(bounds[0]) + "," + real(bounds[1]) + "," + real(bounds[2]) +
           "],\"max\":[" + real(bounds[3]) + "," + real(bounds[4]) + "," + real(bounds[5]) + "]";
    accessors_.push_back(x + "}");
    return num(accessors_.size() - 1);
  }
  static std::string num(size_t x) { return std::to_string(x); }
  static std::string base64(const std::vector<uint8_t>& b) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < b.size(); i += 3) {
      const uint32_t x = uint32_t(b[i]) << 16 | (i + 1 < b.size() ? uint32_t(b[i + 1]) << 8 : 0) |
                         (i + 2 < b.size() ? b[i + 2] : 0);
      out += abc[x >> 18 & 63];
      out += abc[x >> 12 & 63];
      out += i + 1 < b.size() ? abc[x >> 6 & 63] : '=';
      out += i + 2 < b.size() ? abc[x & 63] : '=';
    }
    return out;
  }
  // Shortest text that reads back as the same float (glTF's min/max must match the data).
  static std::string real(double x) {
    char b[32];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(b, sizeof b, "%.*g", digits, x);
      if (float(std::strtod(b, nullptr)) == float(x)) break;
    }
    return b;
  }
  static std::string join(const std::vector<std::string>& parts) {
    std::string s;
    for (size_t i = 0; i < parts.size(); ++i)
      s += (i ? "," : "") + parts[i];
    return s;
  }
  // A relative path as a URI reference: spaces and other reserved bytes percent-encoded.
  static std::string uri_escaped(const std::string& s) {
    std::string out;
    for (unsigned char c : s) {
      if (std::isalnum(c) || std::strchr("-._~/", c)) {
        out += char(c);
      } else {
        char b[4];
        std::snprintf(b, sizeof b, "%%%02X", c);
        out += b;
      }
    }
    return out;
  }

  const GlbAttributes& a_;
  size_t stride_;
  int normal_at_, color_at_, uv_at_;
  size_t buffer_bytes_ = 0, fallback_bytes_ = 0;
  bool compressed_ = false;
  std::vector<std::string> views_, accessors_, meshes_;
  std::string extension_name_, extension_; // for the next level's primitive
  std::vector<std::string> used_;          // extensions the primitives use
  std::vector<double> ratios_;
};

} // namespace vrs
