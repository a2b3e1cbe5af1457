//--------------------------------------------------------------------------
// readGmsh — a background mesh drawn in Gmsh, read from a .msh file
//--------------------------------------------------------------------------
// Gmsh 4.1 ASCII. See readGmsh.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "readGmsh.h"
#include "ample/errors.h"
#include "generalMesh.h"
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace ample {

namespace {
using Key = std::pair<int, int>;  // (dimension, tag) of an entity or a physical group

struct MshData {                                  // what the sections say, by Gmsh's tags
  std::string path;
  std::map<long, Vector3d> nodes;                 // node tag -> x, y, z
  std::vector<std::vector<long>> cells;           // 2D elements: node tags
  int cellType = 0;                               // 2 triangles, 3 quadrilaterals
  std::map<Key, std::vector<int>> physicalOf;     // entity -> its physical tags
  std::map<Key, std::string> names;               // physical group -> name
  std::map<Key, std::set<long>> entityNodes;      // entity -> node tags of its elements
};

[[noreturn]] void bad(const MshData& m, const std::string& what) {
  throw InputError("mesh file '" + m.path + "': " + what);
}

template <class T> T next(std::istream& in, const MshData& m, const char* section) {
  T v;
  if (!(in >> v)) bad(m, std::string("cannot read the section $") + section + " (truncated or not Gmsh 4.1 ASCII)");
  return v;
}

void readFormat(std::istream& in, MshData& m) {
  const double version = next<double>(in, m, "MeshFormat");
  const int fileType = next<int>(in, m, "MeshFormat");
  if (version < 4.1 || version >= 5.0 || fileType != 0)
    bad(m, "format version " + std::to_string(version) + (fileType ? " binary" : " ASCII") +
               ": only version 4.1 ASCII is read (save from Gmsh as 'Version 4 ASCII', or gmsh -format msh41)");
}

void readNames(std::istream& in, MshData& m) {
  const int n = next<int>(in, m, "PhysicalNames");
  for (int k = 0; k < n; ++k) {
    const int dim = next<int>(in, m, "PhysicalNames"), tag = next<int>(in, m, "PhysicalNames");
    std::string rest;
    std::getline(in, rest);
    const size_t a = rest.find('"'), b = rest.rfind('"');
    m.names[{dim, tag}] = (a != std::string::npos && b > a) ? rest.substr(a + 1, b - a - 1) : rest;
  }
}

void readEntities(std::istream& in, MshData& m) {
  int count[4];
  for (int& c : count) c = next<int>(in, m, "Entities");
  if (count[3] > 0) bad(m, "it has volumes: the background mesh must be two-dimensional");
  for (int dim = 0; dim < 3; ++dim)
    for (int k = 0; k < count[dim]; ++k) {
      const int tag = next<int>(in, m, "Entities");
      for (int i = 0; i < (dim == 0 ? 3 : 6); ++i) next<double>(in, m, "Entities");  // x or the box
      const int np = next<int>(in, m, "Entities");
      for (int i = 0; i < np; ++i) m.physicalOf[{dim, tag}].push_back(std::abs(next<int>(in, m, "Entities")));
      if (dim == 0) continue;
      const int nb = next<int>(in, m, "Entities");                               // bounding entities
      for (int i = 0; i < nb; ++i) next<int>(in, m, "Entities");
    }
}

void readNodes(std::istream& in, MshData& m) {
  const long blocks = next<long>(in, m, "Nodes");
  next<long>(in, m, "Nodes"), next<long>(in, m, "Nodes"), next<long>(in, m, "Nodes");
  for (long b = 0; b < blocks; ++b) {
    next<int>(in, m, "Nodes"), next<int>(in, m, "Nodes");
    if (next<int>(in, m, "Nodes") != 0) bad(m, "parametric nodes are not read (save without 'parametric coordinates')");
    std::vector<long> tags(next<long>(in, m, "Nodes"));
    for (long& t : tags) t = next<long>(in, m, "Nodes");
    for (long t : tags)
      for (int i = 0; i < 3; ++i) m.nodes[t](i) = next<double>(in, m, "Nodes");
  }
}

void readElements(std::istream& in, MshData& m) {
  const long blocks = next<long>(in, m, "Elements");
  next<long>(in, m, "Elements"), next<long>(in, m, "Elements"), next<long>(in, m, "Elements");
  for (long b = 0; b < blocks; ++b) {
    const int dim = next<int>(in, m, "Elements"), tag = next<int>(in, m, "Elements");
    const int type = next<int>(in, m, "Elements");
    const long n = next<long>(in, m, "Elements");
    const int nodesOf = type == 15 ? 1 : type == 1 ? 2 : type == 2 ? 3 : type == 3 ? 4 : 0;
    if (nodesOf == 0)
      bad(m, "element type " + std::to_string(type) + ": only points (15), lines (1), linear triangles (2) and "
             "bilinear quadrilaterals (3) are read (mesh with 'Element order 1')");
    if (dim == 2 && m.cellType != 0 && m.cellType != type)
      bad(m, "it has both triangles and quadrilaterals: a background mesh has one cell shape");
    if (dim == 2) m.cellType = type;
    for (long e = 0; e < n; ++e) {
      next<long>(in, m, "Elements");
      std::vector<long> v(nodesOf);
      for (long& t : v) m.entityNodes[{dim, tag}].insert(t = next<long>(in, m, "Elements"));
      if (dim == 2) m.cells.push_back(v);
    }
  }
}

MshData readSections(const std::string& path) {
  MshData m;
  m.path = path;
  std::ifstream in(path);
  if (!in) bad(m, "cannot be opened");
  std::string line;
  bool format = false;
  while (in >> line) {
    if (line.empty() || line[0] != '$' || line.rfind("$End", 0) == 0) continue;
    const std::string s = line.substr(1);
    if (s == "MeshFormat") readFormat(in, m), format = true;
    else if (s == "PhysicalNames") readNames(in, m);
    else if (s == "Entities") readEntities(in, m);
    else if (s == "Nodes") readNodes(in, m);
    else if (s == "Elements") readElements(in, m);
    else while (in >> line && line != "$End" + s) {}                         // a section we skip
  }
  if (!format) bad(m, "no $MeshFormat section: not a Gmsh .msh file");
  if (m.cells.empty()) bad(m, "no triangles or quadrilaterals (mesh the surfaces: gmsh -2)");
  return m;
}
}  // namespace

GmshMesh readGmsh(const std::string& path) {
  const MshData m = readSections(path);
  std::map<long, int> index;                                                 // node tag -> 0, 1, ...
  for (const auto& c : m.cells)
    for (long t : c) index[t] = 0;
  Eigen::MatrixX2d coord(index.size(), 2);
  int k = 0;
  for (auto& [tag, i] : index) {
    const auto x = m.nodes.find(tag);
    if (x == m.nodes.end()) bad(m, "a cell uses node " + std::to_string(tag) + ", which $Nodes does not list");
    if (x->second(2) != 0.0) bad(m, "node " + std::to_string(tag) + " has z != 0: draw the mesh in the x-y plane");
    coord.row(i = k++) << x->second(0), x->second(1);
  }
  Eigen::MatrixXi etpl(m.cells.size(), m.cells[0].size());
  for (size_t e = 0; e < m.cells.size(); ++e) {
    const int n = int(m.cells[e].size());
    double A2 = 0;                                                           // twice the signed area
    for (int a = 0; a < n; ++a) {
      const int i = index[m.cells[e][a]], j = index[m.cells[e][(a + 1) % n]];
      A2 += coord(i, 0) * coord(j, 1) - coord(j, 0) * coord(i, 1);
    }
    for (int a = 0; a < n; ++a) etpl(e, a) = index[m.cells[e][A2 < 0 ? n - 1 - a : a]];  // anticlockwise
  }
  GmshMesh g{generalMesh(coord, etpl), {}};
  for (const auto& [entity, tags] : m.physicalOf) {
    const auto nodes = m.entityNodes.find(entity);
    for (int p : tags) {
      const Key group{entity.first, p};
      const auto name = m.names.find(group);
      auto& set = g.groups[name != m.names.end() ? name->second : std::to_string(entity.first) + ":" + std::to_string(p)];
      if (nodes != m.entityNodes.end())
        for (long t : nodes->second)
          if (index.count(t)) set.push_back(index.at(t));
    }
  }
  for (auto& [name, set] : g.groups) {
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  return g;
}

}  // namespace ample
