#include "contours.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

namespace dxf::contours {

namespace {

using Vec3 = std::array<double, 3>;

constexpr double kMaxStepDeg = 5.0;  // arcs are sampled at least every 5 degrees: a chord sags 0.1 % of r

void push(Piece& p, const Vec3& v) {
  if (!p.points.empty()) {
    const Vec3& b = p.points.back();
    if (std::fabs(b[0] - v[0]) < 1e-12 && std::fabs(b[1] - v[1]) < 1e-12 && std::fabs(b[2] - v[2]) < 1e-12) return;
  }
  p.points.push_back(v);
}

// Algebraic (Kasa) least-squares circle through the points, in coordinates
// about their mean for conditioning; false when they are collinear.
bool fit_circle(const std::vector<aco::Point2>& pts, aco::Point2& center) {
  double mx = 0, my = 0;
  for (const aco::Point2& p : pts) mx += p.x, my += p.y;
  mx /= static_cast<double>(pts.size());
  my /= static_cast<double>(pts.size());
  // Minimise sum (u^2 + v^2 + D u + E v + F)^2: the normal equations.
  double suu = 0, svv = 0, suv = 0, su = 0, sv = 0, n = 0, suz = 0, svz = 0, sz = 0;
  for (const aco::Point2& p : pts) {
    const double u = p.x - mx, v = p.y - my, z = u * u + v * v;
    suu += u * u, svv += v * v, suv += u * v, su += u, sv += v, n += 1, suz += u * z, svz += v * z, sz += z;
  }
  // [suu suv su; suv svv sv; su sv n] [D E F]^T = -[suz svz sz]^T
  double a[3][4] = {{suu, suv, su, -suz}, {suv, svv, sv, -svz}, {su, sv, n, -sz}};
  for (int c = 0; c < 3; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 3; ++r) {
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    }
    if (std::fabs(a[pivot][c]) < 1e-300) return false;
    for (int k = 0; k < 4; ++k) std::swap(a[c][k], a[pivot][k]);
    for (int r = 0; r < 3; ++r) {
      if (r == c) continue;
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 4; ++k) a[r][k] -= f * a[c][k];
    }
  }
  const double d = a[0][3] / a[0][0], e = a[1][3] / a[1][1];
  if (!std::isfinite(d) || !std::isfinite(e)) return false;
  center = {mx - d / 2, my - e / 2};
  return true;
}

struct End {
  std::size_t piece;
  bool at_start;
};

}  // namespace

void add_arc(Piece& p, Vec3 center, double radius, double start_deg, double end_deg) {
  if (!std::isfinite(end_deg - start_deg) || std::fabs(start_deg) > 1e9 || std::fabs(end_deg) > 1e9) return;
  double span = std::fmod(end_deg - start_deg, 360.0);
  if (span <= 1e-12) span += 360.0;
  const int steps = std::max(1, static_cast<int>(std::ceil(span / kMaxStepDeg)));
  for (int i = 0; i <= steps; ++i) {
    const double a = (start_deg + span * i / steps) * M_PI / 180.0;
    push(p, {center[0] + radius * std::cos(a), center[1] + radius * std::sin(a), center[2]});
  }
}

void add_bulge(Piece& p, Vec3 from, Vec3 to, double bulge) {
  push(p, from);
  if (std::fabs(bulge) < 1e-12) {
    push(p, to);
    return;
  }
  // bulge = tan(theta / 4), theta the included angle, positive counter-clockwise;
  // the centre lies off the chord's middle by (1 - b^2) / (4 b) of its length, to the left.
  const double dx = to[0] - from[0], dy = to[1] - from[1];
  const double len = std::hypot(dx, dy);
  if (len < 1e-12) return;
  const double off = (1 - bulge * bulge) / (4 * bulge);
  const double cx = (from[0] + to[0]) / 2 - dy * off, cy = (from[1] + to[1]) / 2 + dx * off;
  const double theta = 4 * std::atan(bulge);
  const double r = std::hypot(from[0] - cx, from[1] - cy);
  const double a0 = std::atan2(from[1] - cy, from[0] - cx);
  const int steps = std::max(1, static_cast<int>(std::ceil(std::fabs(theta) * 180.0 / M_PI / kMaxStepDeg)));
  for (int i = 1; i < steps; ++i) {
    const double a = a0 + theta * i / steps;
    push(p, {cx + r * std::cos(a), cy + r * std::sin(a), from[2]});
  }
  push(p, to);
}

std::vector<Vec3> sample_spline(int degree, const std::vector<double>& knots, const std::vector<Vec3>& control,
                                const std::vector<double>& weights) {
  const int n = static_cast<int>(control.size()) - 1;
  const int p = degree;
  // DXF splines are of degree 1 to 11 in practice; a higher one is no drawing.
  if (p < 1 || p > 25 || n < p || static_cast<int>(knots.size()) != n + p + 2) return {};
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (knots[i] < knots[i - 1]) return {};
  }
  auto weight = [&](int i) { return weights.size() == control.size() ? weights[static_cast<std::size_t>(i)] : 1.0; };
  const double u0 = knots[static_cast<std::size_t>(p)], u1 = knots[static_cast<std::size_t>(n + 1)];
  if (!(u1 > u0)) return {};
  const int samples = std::min(16 * (n + 1), 20000);
  std::vector<Vec3> out;
  for (int s = 0; s <= samples; ++s) {
    const double u = u0 + (u1 - u0) * s / samples;
    int k = p;
    while (k < n && knots[static_cast<std::size_t>(k + 1)] <= u) ++k;
    // de Boor on homogeneous points (x w, y w, z w, w).
    std::vector<std::array<double, 4>> d(static_cast<std::size_t>(p + 1));
    for (int j = 0; j <= p; ++j) {
      const int i = j + k - p;
      const double w = weight(i);
      const Vec3& c = control[static_cast<std::size_t>(i)];
      d[static_cast<std::size_t>(j)] = {c[0] * w, c[1] * w, c[2] * w, w};
    }
    for (int r = 1; r <= p; ++r) {
      for (int j = p; j >= r; --j) {
        const double lo = knots[static_cast<std::size_t>(j + k - p)], hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
        const double alpha = hi > lo ? (u - lo) / (hi - lo) : 0.0;
        for (int q = 0; q < 4; ++q) {
          d[static_cast<std::size_t>(j)][q] = (1 - alpha) * d[static_cast<std::size_t>(j - 1)][q] + alpha * d[static_cast<std::size_t>(j)][q];
        }
      }
    }
    const auto& h = d[static_cast<std::size_t>(p)];
    if (!(std::fabs(h[3]) > 0)) return {};
    out.push_back({h[0] / h[3], h[1] / h[3], h[2] / h[3]});
  }
  return out;
}

std::vector<Found> round_loops(const std::vector<Placed>& pieces, double tolerance) {
  // Loops: closed pieces as they are, open ones joined where exactly two ends meet.
  struct Loop {
    std::vector<aco::Point2> points;
    std::set<std::string_view> kinds;
    std::string_view layer;
    std::uint32_t line = 0;
  };
  std::vector<Loop> loops;
  double scale = 1.0;
  for (const Placed& p : pieces) {
    for (const aco::Point2& q : p.points) scale = std::max({scale, std::fabs(q.x), std::fabs(q.y)});
  }
  const double eps = 1e-7 * scale;  // ends that meet are written with the same digits
  auto key = [&](aco::Point2 q) { return std::make_pair(std::llround(q.x / eps / 4), std::llround(q.y / eps / 4)); };
  struct PairHash {
    std::size_t operator()(const std::pair<long long, long long>& k) const {
      return std::hash<long long>()(k.first) * 1000003u ^ std::hash<long long>()(k.second);
    }
  };
  std::unordered_map<std::pair<long long, long long>, std::vector<End>, PairHash> ends;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Placed& p = pieces[i];
    if (p.points.size() < 2) continue;
    if (p.closed) {
      loops.push_back({p.points, {p.kind}, p.layer, p.line});
      continue;
    }
    ends[key(p.points.front())].push_back({i, true});
    ends[key(p.points.back())].push_back({i, false});
  }
  auto meeting = [&](aco::Point2 q) {
    std::vector<End> found;
    const auto [kx, ky] = key(q);
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = ends.find({kx + dx, ky + dy});
        if (it == ends.end()) continue;
        for (const End& e : it->second) {
          const Placed& p = pieces[e.piece];
          const aco::Point2 at = e.at_start ? p.points.front() : p.points.back();
          if (aco::euclidean(at, q) <= eps) found.push_back(e);
          if (found.size() > 2) return found;  // a junction of three or more: no contour through it
        }
      }
    }
    return found;
  };
  std::vector<char> used(pieces.size(), 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Placed& first = pieces[i];
    if (used[i] || first.closed || first.points.size() < 2) continue;
    used[i] = 1;
    Loop loop{first.points, {first.kind}, first.layer, first.line};
    const aco::Point2 start = first.points.front();
    bool closed = false;
    for (std::size_t guard = 0; guard < pieces.size(); ++guard) {
      const aco::Point2 at = loop.points.back();
      if (loop.points.size() > 2 && aco::euclidean(at, start) <= eps) {
        closed = true;
        break;
      }
      const std::vector<End> here = meeting(at);
      // Exactly this piece's end and one other: a junction of more is no contour.
      if (here.size() != 2) break;
      const End next = here[0].piece == i || used[here[0].piece] ? here[1] : here[0];
      if (used[next.piece]) break;
      used[next.piece] = 1;
      const Placed& p = pieces[next.piece];
      loop.kinds.insert(p.kind);
      loop.line = std::min(loop.line, p.line);
      if (next.at_start) loop.points.insert(loop.points.end(), p.points.begin() + 1, p.points.end());
      else loop.points.insert(loop.points.end(), p.points.rbegin() + 1, p.points.rend());
    }
    if (!closed) continue;
    loop.points.pop_back();  // the start again
    loops.push_back(std::move(loop));
  }
  std::vector<Found> out;
  for (Loop& loop : loops) {
    std::vector<aco::Point2>& pts = loop.points;
    if (pts.size() > 1 && aco::euclidean(pts.front(), pts.back()) <= eps) pts.pop_back();
    if (pts.size() < 3) continue;
    aco::Point2 c;
    if (!fit_circle(pts, c)) continue;
    double r = 0;
    for (const aco::Point2& q : pts) r += aco::euclidean(q, c);
    r /= static_cast<double>(pts.size());
    if (!(r > 0) || !std::isfinite(r)) continue;
    // Round: every point and every chord's middle within the tolerance of the
    // circle, and the loop goes once round its centre.
    double worst = 0, turned = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const aco::Point2 a = pts[k], b = pts[(k + 1) % pts.size()];
      const aco::Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
      worst = std::max({worst, std::fabs(aco::euclidean(a, c) - r), std::fabs(aco::euclidean(mid, c) - r)});
      double step = std::atan2(b.y - c.y, b.x - c.x) - std::atan2(a.y - c.y, a.x - c.x);
      while (step > M_PI) step -= 2 * M_PI;
      while (step < -M_PI) step += 2 * M_PI;
      turned += step;
    }
    if (worst > tolerance * r || std::fabs(std::fabs(turned) - 2 * M_PI) > 1e-6) continue;
    std::string kinds;
    for (std::string_view k : loop.kinds) kinds += (kinds.empty() ? "" : "+") + std::string(k);
    out.push_back({c, 2 * r, std::string(loop.layer), loop.line, kinds});
  }
  std::sort(out.begin(), out.end(), [](const Found& a, const Found& b) { return a.line < b.line; });
  return out;
}

}  // namespace dxf::contours
