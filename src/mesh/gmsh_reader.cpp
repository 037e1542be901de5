#include "mesh/gmsh_reader.hpp"

#include <cstdint>
#include <string>

#include "mesh/gmsh_sections.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/node_tag_map.hpp"

namespace mrsim {
namespace {

struct MshFormat {
  std::string version;  // as written: "2.2", "4.1"
  bool v41 = false;
  bool binary = false;
};

[[noreturn]] void reject_msh1(const std::filesystem::path& path) {
  throw mesh_error(path,
                   "legacy gmsh MSH 1 file ($NOD/$ELM sections) is not supported: open it in gmsh and save it "
                   "as MSH 4.1 or 2.2 (command line: gmsh FILE -save -format msh41 -o NEW.msh)");
}

// Binary files follow the format line with the int 1, which tells the writer's byte order.
void read_endianness_marker(InputCursor& in) {
  const auto one = in.binary<std::uint32_t>("the binary endianness marker");
  if (one == 1) return;
  if (one == 0x01000000u) {
    in.set_swap_bytes(true);
    return;
  }
  in.fail(cat("binary endianness marker is ", one, ", expected 1 (the binary file is corrupt)"));
}

MshFormat read_mesh_format(InputCursor& in, const std::filesystem::path& path) {
  const std::string_view first = in.token("$MeshFormat");
  if (first == "$NOD" || first == "$NOE") reject_msh1(path);
  if (first != "$MeshFormat") throw mesh_error(path, "not a gmsh mesh file: it does not start with $MeshFormat");
  MshFormat f;
  f.version = std::string(in.token("the MSH version"));
  f.binary = in.integer_in("the MSH file type (0 ASCII, 1 binary)", 0, 1) == 1;
  const std::int64_t data_size = in.integer("the MSH data size");
  in.end_line("the MSH format line");
  if (f.version == "2" || f.version.starts_with("2.")) {
    f.v41 = false;
  } else if (f.version == "4.1") {
    f.v41 = true;
  } else {
    in.fail(cat("gmsh MSH version ", f.version, " is not supported: save the mesh as MSH 4.1 or 2.2 "
                "(gmsh option Mesh.MshFileVersion)"));
  }
  if (data_size != 8) in.fail(cat("MSH data size ", data_size, " is not supported (gmsh writes 8)"));
  if (f.binary) read_endianness_marker(in);
  in.expect("$EndMeshFormat");
  return f;
}

// Sections mrsim does not need ($PhysicalNames, $Entities, $NodeData, ...) are skipped whole;
// searching for their end marker works in binary files too.
void skip_section(InputCursor& in, std::string_view name) {
  if (!in.skip_past(cat("$End", name.substr(1))))
    in.fail(cat("section ", name, " has no $End", name.substr(1), " (the file is truncated)"));
}

GmshContent read_sections(InputCursor& in, const MshFormat& f) {
  GmshContent content;
  bool seen_nodes = false, seen_elements = false;
  while (!in.at_end()) {
    const std::string name(in.token("a section name"));
    if (name.empty() || name[0] != '$') in.fail(cat("expected a section such as $Nodes, found ", quoted_token(name)));
    if (name == "$NOD" || name == "$ELM") reject_msh1(in.path());
    const bool nodes = name == "$Nodes", elements = name == "$Elements";
    if (!nodes && !elements) {
      skip_section(in, name);
      continue;
    }
    if ((nodes && seen_nodes) || (elements && seen_elements)) in.fail(cat("a second ", name, " section"));
    in.end_line(name);  // binary data starts right after the newline
    if (nodes && f.v41) read_gmsh41_nodes(in, f.binary, content);
    if (nodes && !f.v41) read_gmsh2_nodes(in, f.binary, content);
    if (elements && f.v41) read_gmsh41_elements(in, f.binary, content);
    if (elements && !f.v41) read_gmsh2_elements(in, f.binary, content);
    seen_nodes |= nodes;
    seen_elements |= elements;
  }
  if (!seen_nodes) throw mesh_error(in.path(), "has no $Nodes section");
  if (!seen_elements) throw mesh_error(in.path(), "has no $Elements section");
  return content;
}

// Replaces node tags by positions; every tag must name a node of $Nodes.
std::vector<Tet> resolve_tets(const GmshContent& c, const std::filesystem::path& path) {
  const NodeTagMap map(c.node_tags);
  if (map.duplicate() >= 0) throw mesh_error(path, cat("node tag ", map.duplicate(), " is defined twice in $Nodes"));
  std::vector<Tet> tets(c.tet_nodes.size());
  for (std::size_t k = 0; k < tets.size(); ++k)
    for (int v = 0; v < 4; ++v) {
      const int index = map.find(c.tet_nodes[k][v]);
      if (index < 0)
        throw mesh_error(path, cat("element ", c.tet_tags[k], " refers to node ", c.tet_nodes[k][v],
                                   ", which is not defined in $Nodes"));
      tets[k][v] = index;
    }
  return tets;
}

}  // namespace

RawMesh read_gmsh(const std::filesystem::path& path) {
  const std::string bytes = read_whole_file(path);
  InputCursor in(bytes, path);
  const MshFormat f = read_mesh_format(in, path);
  GmshContent c = read_sections(in, f);
  RawMesh raw;
  raw.format = cat("gmsh-", f.version, f.binary ? "-binary" : "-ascii");
  raw.tets = resolve_tets(c, path);
  raw.points = std::move(c.points);
  raw.point_ids = std::move(c.node_tags);
  raw.tet_ids = std::move(c.tet_tags);
  raw.point_noun = "node";
  raw.tet_noun = "element";
  raw.ignored = std::move(c.ignored);
  return raw;
}

}  // namespace mrsim
