// The vcglib mesh the command-line tool loads files into: positions plus every per-vertex
// attribute MeshLab's formats carry, so that kept vertices are written back unchanged.
#pragma once

#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include "polygons.h"
#include "vcg_corner_data.h"

namespace vrs_tool {

class Vertex;
class Face;
struct Types : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex
    : public vcg::Vertex<Types, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                         vcg::vertex::Qualityf, vcg::vertex::TexCoord2f, vcg::vertex::BitFlags> {};
// Per-corner data and face colors are optional components, enabled only when a file has them
// (a 19 M-face mesh without them costs nothing more).
class Face : public vcg::Face<Types, vcg::face::InfoOcf, vcg::face::VertexRef, vcg::face::BitFlags,
                              vcg::face::Color4bOcf, vcg::face::WedgeTexCoordfOcf,
                              vcg::face::WedgeNormal3fOcf> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<Vertex>, vcg::face::vector_ocf<Face>> {};

class VcgDocument {
 public:
  VcgMesh mesh;
  int mask = 0; // vcg::tri::io::Mask bits of what the file held
  // OBJ materials: the material library named by the file, and the names of the materials,
  // indexed by the faces' texture index (WT(k).N()).
  std::string material_library;
  std::vector<std::string> materials;
  // --feature-angle: also the angle past which per-corner normals make a hard edge.
  double feature_angle_deg = 0;
  // The file's polygons, fanned into its faces; after apply(), those the run left whole.
  Polygons polygons;

  // Enables the optional components `mask` asks for (before faces are read into them).
  void enable(int mask_bits);
  // What of the per-corner and per-face data the document holds.
  vrs_vcg::CornerData corner_data() const;
};

// Readers and a writer for the formats whose vcglib 2020.09 code is broken (own_formats.cpp).
// Fill doc and return "" or an error message.
std::string read_obj(const std::string& path, VcgDocument& doc);
std::string read_stl(const std::string& path, VcgDocument& doc);
std::string read_off(const std::string& path, VcgDocument& doc);
std::string write_obj(const std::string& path, const VcgDocument& doc);
// OFF with round-trip coordinates (vcglib prints 7 digits) and the document's polygons whole.
std::string write_off(const std::string& path, const VcgDocument& doc, int mask);

} // namespace vrs_tool
