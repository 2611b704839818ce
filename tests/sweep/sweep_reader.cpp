#include "sweep_reader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>

#include "mesh_io.h"

namespace vrs_sweep {

namespace {

std::string extension(const std::string& path) {
  auto dot = path.find_last_of('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

std::string read_with_assimp(const std::string& path, vrs::Mesh& out) {
  Assimp::Importer importer;
  if (!importer.IsExtensionSupported("." + extension(path))) return "not a model format";
  // Triangulated, shared vertices joined (files often repeat them per face), node transforms
  // applied so that the scene's meshes sit where the file puts them.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (!scene) return std::string("assimp: ") + importer.GetErrorString();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const uint32_t base = uint32_t(out.vertex_count());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      out.positions.insert(out.positions.end(),
                           {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z});
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue; // points and lines
      for (int c = 0; c < 3; ++c)
        out.triangles.push_back(base + face.mIndices[c]);
    }
  }
  return {};
}

} // namespace

std::string read_mesh(const std::string& path, vrs::Mesh& out, std::vector<uint32_t>& seams) {
  out = vrs::Mesh{};
  seams.clear();
  const std::string e = extension(path);
  std::string why;
  if (e == "ply" || e == "off" || e == "obj" || e == "stl") {
    vrs_tool::LoadResult r = vrs_tool::load(path);
    if (!r.doc) return "unreadable: " + r.error;
    out = vrs_tool::to_core(*r.doc);
    seams = vrs_tool::seams(*r.doc, out);
    vrs_tool::close(r.doc);
  } else {
    why = read_with_assimp(path, out);
  }
  if (why.empty() && out.face_count() == 0) why = "no triangles";
  return why;
}

} // namespace vrs_sweep
