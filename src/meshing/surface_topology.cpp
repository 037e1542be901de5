#include "meshing/surface_topology.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

#include "core/error.hpp"

namespace mrsim {
namespace {

using Edge = std::pair<int, int>;  // (smaller, larger) vertex index

Edge edge_key(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

/// Triangles using each undirected edge, in triangle order (deterministic).
std::map<Edge, std::vector<int>> edge_triangles(const SurfaceMesh& surface) {
  std::map<Edge, std::vector<int>> edges;
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
    const Triangle& tri = surface.triangles[t];
    for (int e = 0; e < 3; ++e) edges[edge_key(tri[e], tri[(e + 1) % 3])].push_back(t);
  }
  return edges;
}

/// True when triangle `t` runs along the edge from a to b (not b to a).
bool runs_forward(const Triangle& t, int a, int b) {
  for (int e = 0; e < 3; ++e) {
    if (t[e] == a && t[(e + 1) % 3] == b) return true;
  }
  return false;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::string describe_point(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return text;
}

void check_edges_closed(const SurfaceMesh& surface, const std::string& name) {
  int boundary = 0, non_manifold = 0;
  Edge first_boundary{-1, -1}, first_non_manifold{-1, -1};
  for (const auto& [edge, tris] : edge_triangles(surface)) {
    if (tris.size() == 1 && boundary++ == 0) first_boundary = edge;
    if (tris.size() > 2 && non_manifold++ == 0) first_non_manifold = edge;
  }
  const auto& p = surface.points;
  if (boundary > 0) {
    throw InputError(name + ": open surface: " + std::to_string(boundary) +
                     " boundary edges (edges of a single triangle), e.g. from " +
                     describe_point(p[first_boundary.first]) + " to " +
                     describe_point(p[first_boundary.second]) + "; a solid needs a closed surface");
  }
  if (non_manifold > 0) {
    throw InputError(name + ": non-manifold surface: " + std::to_string(non_manifold) +
                     " edges shared by more than two triangles, e.g. from " +
                     describe_point(p[first_non_manifold.first]) + " to " +
                     describe_point(p[first_non_manifold.second]));
  }
}

void check_vertex_fans(const SurfaceMesh& surface, const std::string& name) {
  // Around each vertex, join the triangles that share an edge through it; a manifold vertex
  // ends with one group. Union-find over (vertex, triangle) incidences keyed by edge.
  const int n = static_cast<int>(surface.triangles.size());
  std::vector<std::vector<int>> around(surface.points.size());
  for (int t = 0; t < n; ++t) {
    for (int v : surface.triangles[t]) around[v].push_back(t);
  }
  int pinched = 0;
  int first = -1;
  std::vector<int> parent;
  for (int v = 0; v < static_cast<int>(around.size()); ++v) {
    const auto& tris = around[v];
    if (tris.empty()) continue;
    parent.resize(tris.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<int, int> other_end;  // neighbour vertex -> first local triangle through it
    for (int k = 0; k < static_cast<int>(tris.size()); ++k) {
      for (int w : surface.triangles[tris[k]]) {
        if (w == v) continue;
        const auto [it, inserted] = other_end.try_emplace(w, k);
        if (!inserted) parent[find_root(parent, k)] = find_root(parent, it->second);
      }
    }
    int fans = 0;
    for (int k = 0; k < static_cast<int>(tris.size()); ++k) fans += find_root(parent, k) == k;
    if (fans > 1 && pinched++ == 0) first = v;
  }
  if (pinched > 0) {
    throw InputError(name + ": " + std::to_string(pinched) + " pinched vertex" +
                     (pinched > 1 ? "es" : "") + " (two sheets of the surface touch at one point), e.g. at " +
                     describe_point(surface.points[first]) +
                     "; duplicate or separate the vertex so each sheet has its own");
  }
}

int orient_consistently(SurfaceMesh& surface, const std::string& name) {
  // Breadth-first over edge neighbours: a neighbour must run along the shared edge in the
  // opposite direction; otherwise it is flipped, once. A conflict with an already visited
  // triangle means the surface is not orientable (a Möbius-like sheet).
  const auto edges = edge_triangles(surface);
  const int n = static_cast<int>(surface.triangles.size());
  std::vector<char> visited(n, 0);
  int flipped = 0;
  std::vector<int> queue;
  for (int seed = 0; seed < n; ++seed) {
    if (visited[seed]) continue;
    visited[seed] = 1;
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const Triangle t = surface.triangles[queue[head]];
      for (int e = 0; e < 3; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        for (int other : edges.at(edge_key(a, b))) {
          if (other == queue[head]) continue;
          Triangle& o = surface.triangles[other];
          const bool agrees = !runs_forward(o, a, b);
          if (visited[other]) {
            if (!agrees) {
              throw InputError(name + ": the surface is not orientable (inconsistent sides near " +
                               describe_point(surface.points[a]) + ")");
            }
            continue;
          }
          if (!agrees) {
            std::swap(o[1], o[2]);
            ++flipped;
          }
          visited[other] = 1;
          queue.push_back(other);
        }
      }
    }
  }
  return flipped;
}

int connected_components(const SurfaceMesh& surface, std::vector<int>* component_of) {
  const int n = static_cast<int>(surface.triangles.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [edge, tris] : edge_triangles(surface)) {
    for (std::size_t k = 1; k < tris.size(); ++k) {
      parent[find_root(parent, tris[k])] = find_root(parent, tris[0]);
    }
  }
  std::map<int, int> label;
  std::vector<int> of(n);
  for (int t = 0; t < n; ++t) {
    of[t] = label.try_emplace(find_root(parent, t), static_cast<int>(label.size())).first->second;
  }
  if (component_of) *component_of = std::move(of);
  return static_cast<int>(label.size());
}

int surface_genus(const SurfaceMesh& surface) {
  const auto v = static_cast<long>(surface.points.size());
  const auto f = static_cast<long>(surface.triangles.size());
  const long e = 3 * f / 2;  // closed surface: every edge has two triangles
  return static_cast<int>((2 - (v - e + f)) / 2);
}

}  // namespace mrsim
