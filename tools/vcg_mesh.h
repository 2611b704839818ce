// The vcglib mesh the command-line tool loads files into: positions plus every per-vertex
// attribute MeshLab's formats carry, so that kept vertices are written back unchanged.
#pragma once

#include <string>

#include <vcg/complex/complex.h>

namespace vrs_tool {

class Vertex;
class Face;
struct Types : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex
    : public vcg::Vertex<Types, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                         vcg::vertex::Qualityf, vcg::vertex::TexCoord2f, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<Types, vcg::face::VertexRef, vcg::face::BitFlags> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

class VcgDocument {
 public:
  VcgMesh mesh;
  int mask = 0;
};

// Readers for the formats whose vcglib 2020.09 importer is broken (see own_readers.cpp).
// Fill doc and return "" or an error message.
std::string read_obj(const std::string& path, VcgDocument& doc);
std::string read_stl(const std::string& path, VcgDocument& doc);
std::string read_off(const std::string& path, VcgDocument& doc);

} // namespace vrs_tool
