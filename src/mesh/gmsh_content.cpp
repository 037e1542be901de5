#include "mesh/gmsh_sections.hpp"

#include "mesh/mesh_input.hpp"

namespace mrsim {

void add_gmsh_node(InputCursor& in, GmshContent& content, std::int64_t tag, const Vec3& p) {
  if (tag < 0) in.fail(cat("node tag ", tag, " is negative"));
  if (content.points.size() >= static_cast<std::size_t>(kMaxGmshCount)) in.fail("too many nodes");
  content.node_tags.push_back(tag);
  content.points.push_back(p);
}

const GmshElementType& accepted_gmsh_type(InputCursor& in, int type, const std::string& which) {
  const std::string reason = gmsh_rejection_reason(type);
  if (!reason.empty()) in.fail(cat(which, ": ", reason));
  return *find_gmsh_element_type(type);
}

void add_gmsh_element(GmshContent& content, const GmshElementType& type, std::int64_t tag,
                      const std::int64_t* node_tags) {
  if (type.type != kGmshLinearTet) {
    ++content.ignored[type.plural];
    return;
  }
  content.tet_tags.push_back(tag);
  content.tet_nodes.push_back({node_tags[0], node_tags[1], node_tags[2], node_tags[3]});
}

}  // namespace mrsim
