// Ear clipping in the polygon's best-fit plane (Newell normal), clipping the ear with the largest
// smallest angle first so that quads and n-gons do not turn into slivers. Falls back to a fan when the
// projection is not simple (a badly non-planar polygon), which still covers the polygon.
#include <algorithm>
#include <cmath>

#include "mesh_io_soup.hpp"

namespace foldkit::unfold::detail {
namespace {

double min_angle(Vec2 a, Vec2 b, Vec2 c) {
  auto angle = [](Vec2 p, Vec2 q, Vec2 r) {
    return std::atan2(std::fabs(cross(q - p, r - p)), dot(q - p, r - p));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

bool inside_or_on(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

std::vector<std::array<int, 3>> fan(int n) {
  std::vector<std::array<int, 3>> out;
  for (int i = 1; i + 1 < n; ++i)
    out.push_back({0, i, i + 1});
  return out;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec3>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 3) return {};
  if (n == 3) return {{0, 1, 2}};
  Vec3 normal{};
  Vec3 centre{};
  for (int i = 0; i < n; ++i) {
    const Vec3 a = points[i], b = points[(i + 1) % n];
    normal = normal + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    centre = centre + a;
  }
  normal = normalized(normal);
  if (norm(normal) == 0) return fan(n);
  centre = centre / n;
  const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(helper, normal));
  const Vec3 v = cross(normal, u);
  std::vector<Vec2> p(n);
  for (int i = 0; i < n; ++i)
    p[i] = {dot(points[i] - centre, u), dot(points[i] - centre, v)};

  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i)
    ring[i] = i;
  std::vector<std::array<int, 3>> out;
  while (ring.size() > 3) {
    const int m = static_cast<int>(ring.size());
    int best = -1;
    double best_quality = -1;
    for (int k = 0; k < m; ++k) {
      const int a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
      if (cross(p[b] - p[a], p[c] - p[b]) <= 0) continue;  // reflex or straight: not an ear
      bool empty = true;
      for (int o : ring)
        if (o != a && o != b && o != c && inside_or_on(p[o], p[a], p[b], p[c])) {
          empty = false;
          break;
        }
      if (!empty) continue;
      const double quality = min_angle(p[a], p[b], p[c]);
      if (quality > best_quality) {
        best_quality = quality;
        best = k;
      }
      if (best >= 0 && m > 64) break;  // large n-gons: the first ear, to stay O(n^2)
    }
    if (best < 0) return fan(n);
    out.push_back({ring[(best + m - 1) % m], ring[best], ring[(best + 1) % m]});
    ring.erase(ring.begin() + best);
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

}  // namespace foldkit::unfold::detail
