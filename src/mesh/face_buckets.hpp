#pragma once
// Every face of every tet, grouped by vertex triple: what boundary faces (a triple met once) and
// face neighbours (met twice) are found from. Linear time: the faces are bucketed by their
// smallest vertex (a counting sort, a few dozen faces per bucket) and each bucket is sorted by
// the other two, so the triples come in lexicographic order.
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// The face opposite local vertex k of a positive tet, ordered so that its normal points away
/// from that vertex (outwards).
std::array<int, 3> outward_face(const Tet& t, int k);

struct FaceBuckets {
  struct Entry {
    std::uint64_t rest;  // the two larger vertex ids, the larger in the low bits
    std::uint32_t slot;  // 4 × tet + the local vertex the face is opposite to
  };
  std::vector<std::uint32_t> start;  // [point]: its bucket in `entries` (CSR, np + 1)
  std::vector<Entry> entries;        // each bucket sorted by `rest`, equal ones in any order

  explicit FaceBuckets(const TetMesh& mesh);

  /// fn(first, last) for each run of entries with one vertex triple, in lexicographic order.
  template <class Fn>
  void for_each_face(Fn&& fn) const {
    for (std::size_t p = 0; p + 1 < start.size(); ++p)
      for (std::uint32_t i = start[p]; i < start[p + 1];) {
        std::uint32_t j = i + 1;
        while (j < start[p + 1] && entries[j].rest == entries[i].rest) ++j;
        fn(&entries[i], &entries[j]);
        i = j;
      }
  }
};

}  // namespace mrsim
