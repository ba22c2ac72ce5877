#include "stickslip/chart/chart_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include "chart/chart_segments.hpp"
#include "numerics/tolerances.hpp"

namespace stickslip {

namespace {
// Coordinates are scaled to the unit square; kTol is a vertex's snap radius.
constexpr double kTol = Tolerances::kFaceSnap;
using P = Point2;
using Ring = std::vector<int>;

P Sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1]}; }
double Cross(const P& a, const P& b) { return a[0] * b[1] - a[1] * b[0]; }
double Dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1]; }

// Points within kTol of each other are one vertex.
class Vertices {
 public:
  int Id(const P& p) {
    const long long i = std::llround(p[0] / (4 * kTol)), j = std::llround(p[1] / (4 * kTol));
    for (long long di = -1; di <= 1; ++di)
      for (long long dj = -1; dj <= 1; ++dj) {
        auto it = cells_.find({i + di, j + dj});
        if (it == cells_.end()) continue;
        for (int id : it->second)
          if (std::hypot(pts_[id][0] - p[0], pts_[id][1] - p[1]) <= kTol) return id;
      }
    cells_[{i, j}].push_back(static_cast<int>(pts_.size()));
    pts_.push_back(p);
    return static_cast<int>(pts_.size()) - 1;
  }
  const std::vector<P>& points() const { return pts_; }

 private:
  std::map<std::pair<long long, long long>, std::vector<int>> cells_;
  std::vector<P> pts_;
};

// The segments' graph: split at every crossing (and touching end), in the
// unit square.
std::vector<std::array<int, 2>> SplitSegments(const std::vector<Segment>& segs, Vertices& v) {
  std::vector<std::vector<double>> ts(segs.size(), std::vector<double>{0.0, 1.0});
  for (size_t i = 0; i < segs.size(); ++i) {
    const P r = Sub(segs[i][1], segs[i][0]);
    const double lr = std::hypot(r[0], r[1]);
    for (size_t j = i + 1; j < segs.size(); ++j) {
      const auto& a = segs[i];
      const auto& b = segs[j];
      if (std::min(a[0][0], a[1][0]) > std::max(b[0][0], b[1][0]) + kTol ||
          std::min(b[0][0], b[1][0]) > std::max(a[0][0], a[1][0]) + kTol ||
          std::min(a[0][1], a[1][1]) > std::max(b[0][1], b[1][1]) + kTol ||
          std::min(b[0][1], b[1][1]) > std::max(a[0][1], a[1][1]) + kTol)
        continue;
      const P s = Sub(b[1], b[0]);
      const double ls = std::hypot(s[0], s[1]);
      const double d = Cross(r, s);
      if (std::abs(d) <= Tolerances::kFaceParallel * lr * ls)
        continue;  // parallel: ends snap as vertices
      const P qp = Sub(b[0], a[0]);
      const double t = Cross(qp, s) / d, u = Cross(qp, r) / d;
      if (t < -kTol / lr || t > 1 + kTol / lr || u < -kTol / ls || u > 1 + kTol / ls) continue;
      ts[i].push_back(std::clamp(t, 0.0, 1.0));
      ts[j].push_back(std::clamp(u, 0.0, 1.0));
    }
  }
  std::set<std::pair<int, int>> edges;
  for (size_t i = 0; i < segs.size(); ++i) {
    std::sort(ts[i].begin(), ts[i].end());
    const P r = Sub(segs[i][1], segs[i][0]);
    int prev = -1;
    for (double t : ts[i]) {
      const int id = v.Id({segs[i][0][0] + t * r[0], segs[i][0][1] + t * r[1]});
      if (prev >= 0 && id != prev) edges.insert({std::min(prev, id), std::max(prev, id)});
      prev = id;
    }
  }
  std::vector<std::array<int, 2>> out;
  for (const auto& e : edges) out.push_back({e.first, e.second});
  return out;
}

// Removes dangling chains: edges ending at a vertex of degree one.
std::vector<std::array<int, 2>> Prune(const std::vector<std::array<int, 2>>& edges, size_t nv) {
  std::vector<std::vector<int>> at(nv);
  for (size_t e = 0; e < edges.size(); ++e)
    for (int k : {0, 1}) at[edges[e][k]].push_back(static_cast<int>(e));
  std::vector<int> deg(nv);
  for (size_t i = 0; i < nv; ++i) deg[i] = static_cast<int>(at[i].size());
  std::vector<bool> alive(edges.size(), true);
  std::vector<int> queue;
  for (size_t i = 0; i < nv; ++i)
    if (deg[i] == 1) queue.push_back(static_cast<int>(i));
  while (!queue.empty()) {
    const int x = queue.back();
    queue.pop_back();
    if (deg[x] != 1) continue;
    for (int e : at[x]) {
      if (!alive[e]) continue;
      alive[e] = false;
      const int y = edges[e][0] == x ? edges[e][1] : edges[e][0];
      --deg[x];
      if (--deg[y] == 1) queue.push_back(y);
    }
  }
  std::vector<std::array<int, 2>> out;
  for (size_t e = 0; e < edges.size(); ++e)
    if (alive[e]) out.push_back(edges[e]);
  return out;
}

double RingArea(const std::vector<P>& v, const Ring& r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i) a += Cross(v[r[i]], v[r[(i + 1) % r.size()]]);
  return 0.5 * a;
}

bool InRing(const std::vector<P>& v, const Ring& r, const P& p) {
  bool in = false;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const P& a = v[r[i]];
    const P& b = v[r[j]];
    if ((a[1] > p[1]) != (b[1] > p[1]) &&
        p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      in = !in;
  }
  return in;
}

// The arrangement of a pruned edge set: faces (outer ring, holes) and, per
// half-edge (2e: edges[e][0] -> [1], 2e + 1 back), the face on its left
// (-1: outside the rectangle).
struct Arrangement {
  std::vector<std::array<int, 2>> edges;
  std::vector<int> owner;
  std::vector<Ring> outer;
  std::vector<std::vector<Ring>> holes;
  std::vector<double> outer_area;
};

Arrangement Build(const std::vector<P>& v, const std::vector<std::array<int, 2>>& raw) {
  Arrangement a;
  a.edges = Prune(raw, v.size());
  const int nh = 2 * static_cast<int>(a.edges.size());
  auto from = [&](int h) { return a.edges[h / 2][h % 2]; };
  auto to = [&](int h) { return a.edges[h / 2][1 - h % 2]; };
  std::vector<std::vector<int>> out(v.size());
  for (int h = 0; h < nh; ++h) out[from(h)].push_back(h);
  std::vector<int> pos(nh);
  for (auto& list : out) {
    auto angle = [&](int h) {
      const P d = Sub(v[to(h)], v[from(h)]);
      return std::atan2(d[1], d[0]);
    };
    std::sort(list.begin(), list.end(), [&](int x, int y) { return angle(x) < angle(y); });
    for (size_t k = 0; k < list.size(); ++k) pos[list[k]] = static_cast<int>(k);
  }
  // next(h): at h's end, the outgoing edge just clockwise of h's twin: the
  // face on the left is traced counter-clockwise.
  std::vector<int> cycle_of(nh, -1);
  std::vector<Ring> cycles;
  std::vector<std::vector<int>> cycle_halves;
  for (int h0 = 0; h0 < nh; ++h0) {
    if (cycle_of[h0] >= 0) continue;
    Ring ring;
    std::vector<int> halves;
    for (int h = h0; cycle_of[h] < 0;) {
      cycle_of[h] = static_cast<int>(cycles.size());
      ring.push_back(from(h));
      halves.push_back(h);
      const auto& list = out[to(h)];
      const int n = static_cast<int>(list.size());
      h = list[(pos[h ^ 1] + n - 1) % n];
    }
    cycles.push_back(ring);
    cycle_halves.push_back(halves);
  }
  // Components, for holes: a hole is a component's outer cycle.
  std::vector<int> comp(v.size());
  std::iota(comp.begin(), comp.end(), 0);
  auto find = [&](int x) {
    while (comp[x] != x) x = comp[x] = comp[comp[x]];
    return x;
  };
  for (const auto& e : a.edges) comp[find(e[0])] = find(e[1]);
  std::vector<double> area(cycles.size());
  std::vector<int> face_of(cycles.size(), -1);
  int exterior = -1;
  for (size_t c = 0; c < cycles.size(); ++c) {
    area[c] = RingArea(v, cycles[c]);
    if (area[c] > 0) {
      face_of[c] = static_cast<int>(a.outer.size());
      a.outer.push_back(cycles[c]);
      a.outer_area.push_back(area[c]);
    } else if (exterior < 0 || area[c] < area[exterior]) {
      exterior = static_cast<int>(c);
    }
  }
  a.holes.resize(a.outer.size());
  for (size_t c = 0; c < cycles.size(); ++c) {
    if (area[c] > 0 || static_cast<int>(c) == exterior) continue;
    int best = -1;
    const P& p = v[cycles[c][0]];
    for (size_t f = 0; f < a.outer.size(); ++f)
      if (find(a.outer[f][0]) != find(cycles[c][0]) && InRing(v, a.outer[f], p) &&
          (best < 0 || a.outer_area[f] < a.outer_area[best]))
        best = static_cast<int>(f);
    face_of[c] = best;
    if (best >= 0) a.holes[best].push_back(cycles[c]);
  }
  a.owner.assign(nh, -1);
  for (int h = 0; h < nh; ++h) a.owner[h] = face_of[cycle_of[h]];
  return a;
}

// The ring without vertices on the straight line through their neighbours
// (left where merged faces met); the area is unchanged.
Ring Simplified(const std::vector<P>& v, const Ring& r) {
  Ring out;
  const size_t n = r.size();
  for (size_t i = 0; i < n; ++i) {
    const P a = Sub(v[r[i]], v[r[(i + n - 1) % n]]), b = Sub(v[r[(i + 1) % n]], v[r[i]]);
    if (std::abs(Cross(a, b)) >
            Tolerances::kFaceCollinear * std::hypot(a[0], a[1]) * std::hypot(b[0], b[1]) ||
        Dot(a, b) < 0)
      out.push_back(r[i]);
  }
  return out.size() >= 3 ? out : r;
}

double SegmentDistance(const P& p, const P& a, const P& b) {
  const P ab = Sub(b, a);
  const double l2 = Dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(Dot(Sub(p, a), ab) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p[0] - a[0] - t * ab[0], p[1] - a[1] - t * ab[1]);
}

// A point of the face far from its edges: among the midpoints of the interior
// intervals of 32 horizontal lines, the one farthest from every edge.
P InteriorPoint(const std::vector<P>& v, const Ring& outer, const std::vector<Ring>& holes) {
  std::vector<const Ring*> rings{&outer};
  for (const Ring& h : holes) rings.push_back(&h);
  double y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
  for (int i : outer) y0 = std::min(y0, v[i][1]), y1 = std::max(y1, v[i][1]);
  P best = v[outer[0]];
  double best_d = -1;
  constexpr int kLines = 32;
  for (int k = 0; k < kLines; ++k) {
    const double y = y0 + (y1 - y0) * (k + 0.5) / kLines;
    std::vector<double> xs;
    for (const Ring* r : rings)
      for (size_t i = 0, j = r->size() - 1; i < r->size(); j = i++) {
        const P& a = v[(*r)[i]];
        const P& b = v[(*r)[j]];
        if ((a[1] > y) != (b[1] > y))
          xs.push_back(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]));
      }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2) {
      const P c{0.5 * (xs[i] + xs[i + 1]), y};
      double d = std::numeric_limits<double>::infinity();
      for (const Ring* r : rings)
        for (size_t m = 0, n = r->size() - 1; m < r->size(); n = m++)
          d = std::min(d, SegmentDistance(c, v[(*r)[m]], v[(*r)[n]]));
      if (d > best_d) best_d = d, best = c;
    }
  }
  return best;
}
}  // namespace

std::vector<Face> ArrangementFaces(const Plane& plane,
                                   const std::vector<std::vector<Point2>>& polylines,
                                   const std::function<int(const Point2&)>& label) {
  auto real = [&](const P& u) -> P {
    return {plane.from1 + u[0] * plane.width1(), plane.from2 + u[1] * plane.width2()};
  };
  const std::vector<Segment> segs = UnitSegments(plane, polylines);
  Vertices vertices;
  const std::vector<std::array<int, 2>> edges = SplitSegments(segs, vertices);
  const std::vector<P>& v = vertices.points();
  // Label every face at its interior point, then drop the edges between two
  // faces of one label and trace the merged faces.
  const Arrangement fine = Build(v, edges);
  std::vector<int> labels;
  for (size_t f = 0; f < fine.outer.size(); ++f)
    labels.push_back(label(real(InteriorPoint(v, fine.outer[f], fine.holes[f]))));
  std::map<std::pair<int, int>, int> fine_half;  // (from, to) -> half-edge of `fine`
  std::vector<std::array<int, 2>> kept;
  for (size_t e = 0; e < fine.edges.size(); ++e) {
    const int l = fine.owner[2 * e], r = fine.owner[2 * e + 1];
    fine_half[{fine.edges[e][0], fine.edges[e][1]}] = static_cast<int>(2 * e);
    fine_half[{fine.edges[e][1], fine.edges[e][0]}] = static_cast<int>(2 * e + 1);
    if (l < 0 || r < 0 || labels[l] != labels[r]) kept.push_back(fine.edges[e]);
  }
  const Arrangement merged = Build(v, kept);
  std::vector<Face> faces(merged.outer.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    Face& face = faces[f];
    const Ring& ring = merged.outer[f];
    // The fine face left of the ring's first edge carries the label.
    const int h = fine_half.at({ring[0], ring[1 % ring.size()]});
    face.label = fine.owner[h] >= 0 ? labels[fine.owner[h]] : 0;
    const double scale = plane.width1() * plane.width2();
    face.outer_area = merged.outer_area[f] * scale;
    face.area = face.outer_area;
    for (int i : Simplified(v, ring)) face.outer.push_back(real(v[i]));
    for (const Ring& hole : merged.holes[f]) {
      face.area += RingArea(v, hole) * scale;  // negative: clockwise
      face.holes.emplace_back();
      for (int i : Simplified(v, hole)) face.holes.back().push_back(real(v[i]));
    }
    face.inside = real(InteriorPoint(v, ring, merged.holes[f]));
  }
  std::stable_sort(faces.begin(), faces.end(),
                   [](const Face& a, const Face& b) { return a.outer_area > b.outer_area; });
  return faces;
}

}  // namespace stickslip
