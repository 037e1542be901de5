#pragma once
// gmsh names nodes by tags that need not be contiguous (4.1 files from multi-entity models,
// or after deleting entities). This maps each tag to the node's 0-based position in the file.
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mrsim {

class NodeTagMap {
 public:
  /// `tags[i]` is the tag of node i; tags must be >= 0.
  explicit NodeTagMap(const std::vector<std::int64_t>& tags);
  /// Position of the node with `tag`, or -1 if no node has it.
  int find(std::int64_t tag) const;
  /// A tag given to two nodes, or -1 if every tag is unique.
  std::int64_t duplicate() const { return duplicate_; }

 private:
  // Dense table when tags are reasonably compact (the usual case, fast), hash map otherwise
  // so that a few huge tags cannot cost a huge table.
  std::vector<int> dense_;
  std::unordered_map<std::int64_t, int> sparse_;
  bool use_dense_ = true;
  std::int64_t duplicate_ = -1;
};

}  // namespace mrsim
