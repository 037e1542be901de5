#pragma once
// The rows of the interpolation map (hierarchy/active_row.hpp), merged: each point's row as one
// term per active point (or support point, level -1), sorted by (level, point). Rows are built
// on demand and kept until clear(): a ghost's row is the weighted merge of its interpolation
// tet's rows, so chains of ghosts and neighbouring users share their sources' rows instead of
// expanding them again (the skin map asks for thousands of overlapping rows at each topology
// change). A point's terms reached through several ghosts are summed in the order of the rows
// merged, so the same state always gives the same bits.
#include <cstdint>
#include <utility>
#include <vector>

#include "hierarchy/active_row.hpp"

namespace mrsim {

class MergedRows {
 public:
  struct Span {  // [begin, end) in terms()
    int begin = 0, end = 0;
  };
  /// The merged row of point p of level l in the hierarchy's current statuses; `free_point[l][p]`
  /// is 0 for Dirichlet points.
  Span row(const Hierarchy& h, const std::vector<const std::vector<std::uint8_t>*>& free_point,
           int l, int p);
  /// Σ weights[k] × rows[k] (count ≤ 4) into `out`, merged the same way.
  void combine(const Span* rows, const double* weights, int count,
               std::vector<ActiveTerm>& out) const;
  const std::vector<ActiveTerm>& terms() const { return terms_; }
  /// Forgets every row (the statuses are about to change); keeps the memory.
  void clear();

 private:
  std::vector<std::vector<int>> at_;  // [level][point]: index into spans_, or -1
  std::vector<Span> spans_;
  std::vector<ActiveTerm> terms_;
  std::vector<std::pair<int, int>> points_;  // the points in at_, for clear()
  // A row being merged: a point's sources are complete before its own merge starts, so one
  // scratch serves every depth of the recursion.
  std::vector<ActiveTerm> scratch_;
};

}  // namespace mrsim
