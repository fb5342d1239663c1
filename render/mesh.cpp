#include "mesh.h"

#include <cmath>
#include <fcl/geometry/shape/convex.h>
#include <numbers>

namespace afford::render {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

void push(std::vector<float>& v, const Vector3d& p) {
  v.push_back(static_cast<float>(p.x()));
  v.push_back(static_cast<float>(p.y()));
  v.push_back(static_cast<float>(p.z()));
}

// Two unit vectors across d (unit), right-handed with it.
void basis(const Vector3d& d, Vector3d* u, Vector3d* v) {
  const Vector3d a = std::abs(d.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  *u = d.cross(a).normalized();
  *v = d.cross(*u);
}

// A round solid along x: radius r, from x0 to x1, with hemispherical ends
// (capsule) or flat ones (cylinder); rings at x = 0 so octants split clean.
void add_round(Mesh& m, double r, double half, bool capsule) {
  const int slices = 32, stacks = 8;
  auto ring = [r](double x, double phi) { return Vector3d(x, r * std::cos(phi), r * std::sin(phi)); };
  for (int k = 0; k < slices; ++k) {
    const double p0 = 2 * kPi * k / slices, p1 = 2 * kPi * (k + 1) / slices;
    const Vector3d n0(0, std::cos(p0), std::sin(p0)), n1(0, std::cos(p1), std::sin(p1));
    for (double x0 : {-half, 0.0}) {
      const double x1 = x0 + half;
      m.tri(ring(x0, p0), ring(x0, p1), ring(x1, p1), n0, n1, n1);
      m.tri(ring(x0, p0), ring(x1, p1), ring(x1, p0), n0, n1, n0);
    }
    for (double s : {-1.0, 1.0}) {
      if (!capsule) {
        const Vector3d c(s * half, 0, 0), n(s, 0, 0);
        m.tri(c, ring(s * half, p0), ring(s * half, p1), n, n, n);
        continue;
      }
      for (int i = 0; i < stacks; ++i) {
        const double t0 = kPi / 2 * i / stacks, t1 = kPi / 2 * (i + 1) / stacks;
        auto cap = [&](double t, double phi) {
          return Vector3d(s * std::sin(t), std::cos(t) * std::cos(phi), std::cos(t) * std::sin(phi));
        };
        const Vector3d a = cap(t0, p0), b = cap(t0, p1), c = cap(t1, p1), d = cap(t1, p0);
        const Vector3d off(s * half, 0, 0);
        m.tri(off + r * a, off + r * b, off + r * c, a, b, c);
        m.tri(off + r * a, off + r * c, off + r * d, a, c, d);
      }
    }
  }
}

}  // namespace

void Mesh::tri(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& na, const Vector3d& nb,
               const Vector3d& nc) {
  const Vector3d face = (b - a).cross(c - a);
  if (face.squaredNorm() < 1e-24) return;
  const bool flip = face.dot(na + nb + nc) < 0;
  push(pos, a);
  push(pos, flip ? c : b);
  push(pos, flip ? b : c);
  push(nrm, na.normalized());
  push(nrm, (flip ? nc : nb).normalized());
  push(nrm, (flip ? nb : nc).normalized());
}

void add_box(Mesh& m, const Vector3d& size, const Vector3d& centre) {
  const Vector3d h = size / 2;
  for (int a = 0; a < 3; ++a) {
    const Vector3d e = Vector3d::Unit(a), u = Vector3d::Unit((a + 1) % 3), v = Vector3d::Unit((a + 2) % 3);
    for (double s : {-1.0, 1.0}) {
      const Vector3d n = s * e;
      const Vector3d c = centre + n * h[a];
      const double hu = h.dot(u.cwiseAbs()), hv = h.dot(v.cwiseAbs());
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
          const double u0 = -hu + i * hu, v0 = -hv + j * hv;
          auto q = [&](double du, double dv) { return c + u * (u0 + du) + v * (v0 + dv); };
          m.tri(q(0, 0), q(hu, 0), q(hu, hv), n, n, n);
          m.tri(q(0, 0), q(hu, hv), q(0, hv), n, n, n);
        }
      }
    }
  }
}

void add_ellipsoid(Mesh& m, const Vector3d& r, int slices, int stacks) {
  auto p = [&r](double t, double phi) {
    return Vector3d(r.x() * std::sin(t) * std::cos(phi), r.y() * std::sin(t) * std::sin(phi), r.z() * std::cos(t));
  };
  const Vector3d inv2 = r.cwiseProduct(r).cwiseInverse();
  auto n = [&](const Vector3d& q) { return Vector3d(q.cwiseProduct(inv2)); };
  for (int i = 0; i < stacks; ++i) {
    const double t0 = kPi * i / stacks, t1 = kPi * (i + 1) / stacks;
    for (int j = 0; j < slices; ++j) {
      const double p0 = 2 * kPi * j / slices, p1 = 2 * kPi * (j + 1) / slices;
      const Vector3d a = p(t0, p0), b = p(t1, p0), c = p(t1, p1), d = p(t0, p1);
      m.tri(a, b, c, n(a), n(b), n(c));
      m.tri(a, c, d, n(a), n(c), n(d));
    }
  }
}

void add_shape(Mesh& m, const afford::Geometry& g) {
  const ShapeSpec& s = g.spec();
  switch (s.kind) {
    case ShapeKind::sphere:
      add_ellipsoid(m, Vector3d::Constant(s.radius));
      break;
    case ShapeKind::ellipsoid:
      add_ellipsoid(m, s.radii);
      break;
    case ShapeKind::box:
      add_box(m, s.size);
      break;
    case ShapeKind::capsule:
      add_round(m, s.radius, s.length / 2, true);
      break;
    case ShapeKind::cylinder:
      add_round(m, s.radius, s.length / 2, false);
      break;
    case ShapeKind::convex: {
      const auto* convex = dynamic_cast<const fcl::Convexd*>(&g.fcl());
      if (convex == nullptr) break;
      const std::vector<Vector3d>& v = convex->getVertices();
      const std::vector<int>& f = convex->getFaces();
      Vector3d centre = Vector3d::Zero();
      for (const Vector3d& p : v) centre += p;
      centre /= static_cast<double>(std::max<size_t>(v.size(), 1));
      size_t at = 0;
      for (int face = 0; face < convex->getFaceCount() && at < f.size(); ++face) {
        const size_t k = static_cast<size_t>(f[at]);
        const auto idx = [&](size_t i) { return v[static_cast<size_t>(f[at + 1 + i])]; };
        Vector3d mid = Vector3d::Zero();
        for (size_t i = 0; i < k; ++i) mid += idx(i);
        mid /= static_cast<double>(k);
        Vector3d n = (idx(1) - idx(0)).cross(idx(2) - idx(0)).normalized();
        if (n.dot(mid - centre) < 0) n = -n;
        for (size_t i = 1; i + 1 < k; ++i) m.tri(idx(0), idx(i), idx(i + 1), n, n, n);
        at += k + 1;
      }
      break;
    }
  }
}

void add_tube(Mesh& m, const Vector3d& from, const Vector3d& to, double radius, int slices) {
  const Vector3d axis = to - from;
  if (axis.norm() < 1e-9) return;
  const Vector3d d = axis.normalized();
  Vector3d u, v;
  basis(d, &u, &v);
  for (int k = 0; k < slices; ++k) {
    const double p0 = 2 * kPi * k / slices, p1 = 2 * kPi * (k + 1) / slices;
    const Vector3d n0 = u * std::cos(p0) + v * std::sin(p0), n1 = u * std::cos(p1) + v * std::sin(p1);
    m.tri(from + radius * n0, from + radius * n1, to + radius * n1, n0, n1, n1);
    m.tri(from + radius * n0, to + radius * n1, to + radius * n0, n0, n1, n0);
    m.tri(to, to + radius * n0, to + radius * n1, d, d, d);
    m.tri(from, from + radius * n0, from + radius * n1, -d, -d, -d);
  }
}

void add_arrow(Mesh& m, const Vector3d& tail, const Vector3d& head, double radius) {
  const Vector3d axis = head - tail;
  const double len = axis.norm();
  if (len < 1e-9) return;
  const Vector3d d = axis / len;
  const double head_len = std::min(len * 0.45, radius * 5);
  const Vector3d neck = head - d * head_len;
  add_tube(m, tail, neck, radius);
  Vector3d u, v;
  basis(d, &u, &v);
  const int slices = 16;
  const double r = radius * 2.4;
  for (int k = 0; k < slices; ++k) {
    const double p0 = 2 * kPi * k / slices, p1 = 2 * kPi * (k + 1) / slices;
    const Vector3d e0 = u * std::cos(p0) + v * std::sin(p0), e1 = u * std::cos(p1) + v * std::sin(p1);
    const Vector3d n0 = (e0 * head_len + d * r).normalized(), n1 = (e1 * head_len + d * r).normalized();
    m.tri(neck + r * e0, neck + r * e1, head, n0, n1, (n0 + n1).normalized());
    m.tri(neck, neck + r * e0, neck + r * e1, -d, -d, -d);
  }
}

void shatter(const Mesh& in, double gap, Mesh& out) {
  out.clear();
  out.pos.reserve(in.pos.size());
  out.nrm = in.nrm;
  for (size_t t = 0; t + 9 <= in.pos.size(); t += 9) {
    float sign[3];
    for (int a = 0; a < 3; ++a) {
      const float c = in.pos[t + static_cast<size_t>(a)] + in.pos[t + 3 + static_cast<size_t>(a)] +
                      in.pos[t + 6 + static_cast<size_t>(a)];
      sign[a] = c < 0 ? -1.0f : 1.0f;
    }
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a) {
        out.pos.push_back(in.pos[t + static_cast<size_t>(3 * k + a)] + sign[a] * static_cast<float>(gap));
      }
    }
  }
}

void split_open(const Mesh& in, int axis, const Vector3d& toward, double angle, double gap, Mesh& out) {
  out.clear();
  out.pos.reserve(in.pos.size());
  out.nrm.reserve(in.nrm.size());
  const Vector3d a = Vector3d::Unit(axis);
  Eigen::Matrix3f turn[2];  // [0]: the half below the cut, [1]: above
  Eigen::Vector3f shift[2];
  for (int h = 0; h < 2; ++h) {
    const double s = h == 0 ? -1 : 1;
    // The half's cut face looks along -s*a; turn that toward `toward`.
    const Vector3d k = (-s * a).cross(toward);
    turn[h] = Eigen::Matrix3f::Identity();
    if (k.norm() > 1e-6) turn[h] = Eigen::AngleAxisd(angle, k.normalized()).toRotationMatrix().cast<float>();
    shift[h] = (s * gap * a).cast<float>();
  }
  for (size_t t = 0; t + 9 <= in.pos.size(); t += 9) {
    const float c = in.pos[t + static_cast<size_t>(axis)] + in.pos[t + 3 + static_cast<size_t>(axis)] +
                    in.pos[t + 6 + static_cast<size_t>(axis)];
    const int h = c < 0 ? 0 : 1;
    for (size_t k = 0; k < 9; k += 3) {
      const Eigen::Vector3f q(in.pos[t + k], in.pos[t + k + 1], in.pos[t + k + 2]);
      const Eigen::Vector3f p = turn[h] * q + shift[h];
      const Eigen::Vector3f n = turn[h] * Eigen::Vector3f(in.nrm[t + k], in.nrm[t + k + 1], in.nrm[t + k + 2]);
      out.pos.insert(out.pos.end(), {p.x(), p.y(), p.z()});
      out.nrm.insert(out.nrm.end(), {n.x(), n.y(), n.z()});
    }
  }
}

}  // namespace afford::render
