#include "engine/contact/shell_self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/contact/segment_distance.hpp"
#include "engine/contact/triangle_distance.hpp"

namespace wirepack {

namespace {
// The barrier of both laws starts at half the overlap at which the mid-surfaces (VT) or the
// edges (EE) would meet (hertz.hpp).
constexpr double kBarrierOnset = 0.5;
// Edges are capsules of this fraction of the half-thickness (see the header).
constexpr double kEdgeRadiusFraction = 0.5;

bool has_vertex(const std::array<int, 3>& f, int v) {
  return f[0] == v || f[1] == v || f[2] == v;
}
}  // namespace

ShellSelfContactTerm::ShellSelfContactTerm(const ShellMesh& mesh, const ShellSelfContactParams& p)
    : FrictionalTerm(p.friction), mesh_(mesh), p_(p), t_(2.0 * p.half_thickness) {
  if (!(p.half_thickness > 0.0) || !(p.E_star > 0.0) || !(p.skin > 0.0) || !(p.vertex_mass > 0.0)) {
    throw std::invalid_argument(
        "ShellSelfContactTerm: half_thickness, E_star, skin and vertex_mass must be > 0");
  }
  if (!(p.exclusion >= t_)) {
    throw std::invalid_argument(
        "ShellSelfContactTerm: exclusion must be at least the thickness t = 2 h, or "
        "neighbouring elements of the rest mesh touch");
  }
  if (mesh.num_faces() > 0 && static_cast<int>(mesh.face_edges.size()) != mesh.num_faces()) {
    throw std::invalid_argument("ShellSelfContactTerm: mesh topology not built");
  }
  const double h = p.half_thickness;
  hertz_vt_ = Hertz::from(p.E_star, h).with_barrier(t_, kBarrierOnset);
  const double he = kEdgeRadiusFraction * h;
  hertz_ee_ = Hertz::from(p.E_star, he).with_barrier(2.0 * he, kBarrierOnset);

  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  const int ne = static_cast<int>(mesh.edges.size());
  // w_v = A_v / A_ref: barycentric rest area over the area per vertex of an equilateral mesh
  // of edge t.
  const double A_ref = 0.5 * std::sqrt(3.0) * t_ * t_;
  weight_.assign(nv, 0.0);
  vertex_faces_.assign(nv, {});
  vertex_edges_.assign(nv, {});
  rest_centroid_.resize(nf);
  rest_face_reach_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& v = mesh.faces[f];
    const Vec3 &a = mesh.rest[v[0]], &b = mesh.rest[v[1]], &c = mesh.rest[v[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const Vec3 g = (a + b + c) / 3.0;
    rest_centroid_[f] = g;
    rest_face_reach_[f] = std::max({(a - g).norm(), (b - g).norm(), (c - g).norm()});
    for (int k = 0; k < 3; ++k) {
      weight_[v[k]] += area / (3.0 * A_ref);
      vertex_faces_[v[k]].push_back(f);
    }
  }
  rest_mid_.resize(ne);
  rest_half_.resize(ne);
  for (int e = 0; e < ne; ++e) {
    const Vec3 &a = mesh.rest[mesh.edges[e][0]], &b = mesh.rest[mesh.edges[e][1]];
    rest_mid_[e] = 0.5 * (a + b);
    rest_half_[e] = 0.5 * (b - a).norm();
    for (int k = 0; k < 2; ++k) vertex_edges_[mesh.edges[e][k]].push_back(e);
  }
  row_stiffness_.assign(nv, 0.0);
}

std::string ShellSelfContactTerm::failure() const {
  if (max_overlap_ratio_ < 1.0) return {};
  return "shell self-contact: two pieces of the shell passed through each other (overlap " +
         std::to_string(max_overlap_ratio_) +
         " of the limit; a force beyond what the contact "
         "carries)";
}

double ShellSelfContactTerm::suggested_exclusion(const ShellMesh& mesh, double half_thickness) {
  double lmax = 0.0;
  for (const auto& e : mesh.edges)
    lmax = std::max(lmax, (mesh.rest[e[1]] - mesh.rest[e[0]]).norm());
  return 4.0 * half_thickness + lmax;
}

bool ShellSelfContactTerm::kept(int v, int f) const {
  const double ex = p_.exclusion;
  const double dc = (mesh_.rest[v] - rest_centroid_[f]).norm();
  if (dc < ex) return false;                        // the centroid is on the face
  if (dc - rest_face_reach_[f] >= ex) return true;  // the face is within its reach
  const auto& t = mesh_.faces[f];
  const TriangleClosest c =
      point_triangle_closest(mesh_.rest[v], mesh_.rest[t[0]], mesh_.rest[t[1]], mesh_.rest[t[2]]);
  return c.dist2 >= ex * ex;
}

void ShellSelfContactTerm::maybe_rebuild(const State& s) {
  // The largest move without early exit: the whole list is scanned at rest anyway.
  if (ref_.at_build.size() != s.shell_x.size() ||
      ref_.max_moved2(s.shell_x) > 0.25 * p_.skin * p_.skin)
    rebuild(s);
}

void ShellSelfContactTerm::rebuild(const State& s) {
  const int nv = mesh_.num_vertices(), nf = mesh_.num_faces();
  const int ne = static_cast<int>(mesh_.edges.size());
  const Vec3List& x = s.shell_x;
  if (static_cast<int>(x.size()) != nv) {
    throw std::invalid_argument("ShellSelfContactTerm: state and mesh sizes differ");
  }
  ++rebuilds_;
  ref_.build(x, x.size());
  vt_faces_.clear();
  vt_edges_.clear();
  vt_verts_.clear();
  ee_.clear();
  if (nf == 0) return;
  const double ex = p_.exclusion;

  // VT: vertices and face centroids in one grid; a face can hold a point within reach only
  // if its centroid is within reach + its own reach.
  const double reach_vt = t_ + p_.skin;
  points_.resize(nv + nf);
  std::copy(x.begin(), x.end(), points_.begin());
  double face_reach = 0.0;
  for (int f = 0; f < nf; ++f) {
    const auto& v = mesh_.faces[f];
    const Vec3 g = (x[v[0]] + x[v[1]] + x[v[2]]) / 3.0;
    points_[nv + f] = g;
    for (int k = 0; k < 3; ++k) face_reach = std::max(face_reach, (x[v[k]] - g).norm());
  }
  grid_vt_.find_pairs_between(points_, nv, reach_vt + face_reach, broad_);
  for (const auto& [i, j] : broad_) {
    if (i >= nv || j < nv) continue;  // only (vertex, face) pairs
    const int v = i, f = j - nv;
    if (weight_[v] <= 0.0 || has_vertex(mesh_.faces[f], v)) continue;
    if ((mesh_.rest[v] - rest_centroid_[f]).squaredNorm() < ex * ex) continue;  // cheap reject
    const auto& t = mesh_.faces[f];
    const TriangleClosest c = point_triangle_closest(x[v], x[t[0]], x[t[1]], x[t[2]]);
    if (c.dist2 < reach_vt * reach_vt && kept(v, f)) vt_faces_.emplace_back(v, f);
  }
  std::sort(vt_faces_.begin(), vt_faces_.end());

  // Inclusion-exclusion pieces of each candidate face: its interior edges whose other face is
  // kept too, and its vertices with their Euler weight over the kept part of their fan.
  for (const auto& [v, f] : vt_faces_) {
    for (int k = 0; k < 3; ++k) {
      const int e = mesh_.face_edges[f][k];
      const auto& ef = mesh_.edge_faces[e];
      if (ef[1] >= 0 && kept(v, ef[0] == f ? ef[1] : ef[0])) vt_edges_.emplace_back(v, e);
      const int u = mesh_.faces[f][k];
      int kf = 0, ke = 0;
      for (int g : vertex_faces_[u]) kf += kept(v, g) ? 1 : 0;
      for (int eu : vertex_edges_[u]) {
        const auto& euf = mesh_.edge_faces[eu];
        ke += euf[1] >= 0 && kept(v, euf[0]) && kept(v, euf[1]) ? 1 : 0;
      }
      const int c = 1 - kf + ke;  // kf >= 1: f itself
      if (c != 0) vt_verts_.push_back({v, u, static_cast<double>(c)});
    }
  }
  std::sort(vt_edges_.begin(), vt_edges_.end());
  vt_edges_.erase(std::unique(vt_edges_.begin(), vt_edges_.end()), vt_edges_.end());
  auto by_vu = [](const VertexPiece& a, const VertexPiece& b) {
    return a.v != b.v ? a.v < b.v : a.u < b.u;
  };
  std::sort(vt_verts_.begin(), vt_verts_.end(), by_vu);
  vt_verts_.erase(std::unique(vt_verts_.begin(), vt_verts_.end(),
                              [](const VertexPiece& a, const VertexPiece& b) {
                                return a.v == b.v && a.u == b.u;
                              }),
                  vt_verts_.end());

  // EE: edge midpoints; two edges can come within reach only if their midpoints are within
  // reach + both half lengths.
  const double reach_ee = hertz_ee_.D + p_.skin;
  points_.resize(ne);
  double half_max = 0.0;
  for (int e = 0; e < ne; ++e) {
    const Vec3 &a = x[mesh_.edges[e][0]], &b = x[mesh_.edges[e][1]];
    points_[e] = 0.5 * (a + b);
    half_max = std::max(half_max, 0.5 * (b - a).norm());
  }
  grid_ee_.find_pairs(points_, reach_ee + 2.0 * half_max, broad_);
  for (const auto& [e1, e2] : broad_) {
    const auto &E1 = mesh_.edges[e1], &E2 = mesh_.edges[e2];
    if (E1[0] == E2[0] || E1[0] == E2[1] || E1[1] == E2[0] || E1[1] == E2[1]) continue;
    const double dm = (rest_mid_[e1] - rest_mid_[e2]).norm();
    if (dm < ex) continue;  // rest distance <= midpoint distance
    const SegmentClosest c = segment_segment_closest(x[E1[0]], x[E1[1]], x[E2[0]], x[E2[1]]);
    if (c.dist2 >= reach_ee * reach_ee) continue;
    if (dm - rest_half_[e1] - rest_half_[e2] < ex) {
      const SegmentClosest r = segment_segment_closest(mesh_.rest[E1[0]], mesh_.rest[E1[1]],
                                                       mesh_.rest[E2[0]], mesh_.rest[E2[1]]);
      if (r.dist2 < ex * ex) continue;
    }
    ee_.emplace_back(e1, e2);
  }
}

int ShellSelfContactTerm::find_face_pair(int v, int f) const {
  const auto it = std::lower_bound(
      face_pairs_.begin(), face_pairs_.end(), std::make_pair(v, f),
      [](const FacePair& c, const std::pair<int, int>& k) { return std::make_pair(c.v, c.f) < k; });
  return it != face_pairs_.end() && it->v == v && it->f == f
             ? static_cast<int>(it - face_pairs_.begin())
             : -1;
}

double ShellSelfContactTerm::evaluate(const State& s, Forces* out) {
  maybe_rebuild(s);
  const Vec3List& x = s.shell_x;
  const double m_eff = 0.5 * p_.vertex_mass;  // two vertices of equal mass
  double U = 0.0;
  face_pairs_.clear();
  edge_pairs_.clear();
  for (int v : touched_) row_stiffness_[v] = 0.0;
  touched_.clear();
  max_overlap_ratio_ = 0.0;

  // One contact of `scale` times `law` between point P = sum aw_k x[ai_k] and point
  // Q = sum bw_k x[bi_k], touching below distance D = law.D; returns the signed normal force
  // on P along the normal from Q to P [N] (0 when apart).
  auto contact = [&](const Vec3& P, const Vec3& Q, const Vec3& fallback_n, const int* ai,
                     const double* aw, int na, const int* bi, const double* bw, int nb,
                     const Hertz& law, double scale, Vec3* normal, double* overlap) -> double {
    const double D = law.D;
    const Vec3 d = P - Q;
    const double dist2 = d.squaredNorm();
    if (dist2 >= D * D) return 0.0;
    const double dist = std::sqrt(dist2);
    const Vec3 n = dist > 1e-12 * D ? Vec3(d / dist) : fallback_n;
    const double delta = D - dist;
    max_overlap_ratio_ = std::max(max_overlap_ratio_, delta / D);
    U += scale * law.energy(delta);
    if (normal) *normal = n;
    if (overlap) *overlap = delta;
    if (!out) return scale * law.force(delta);
    const double mag = std::abs(scale);
    const double sign = scale > 0.0 ? 1.0 : -1.0;
    Vec3 va = Vec3::Zero(), vb = Vec3::Zero();
    for (int k = 0; k < na; ++k) va += aw[k] * s.shell_v[ai[k]];
    for (int k = 0; k < nb; ++k) vb += bw[k] * s.shell_v[bi[k]];
    // Dashpot at the scaled stiffness: scale * f(k, m / scale) = scale f + 2 zeta sqrt(scale k m).
    const double f =
        sign * mag *
        damped_normal_force(law, delta, -(va - vb).dot(n), p_.damping_ratio, m_eff / mag);
    const Vec3 F = f * n;
    // Gershgorin row sums of this contact's stiffness k c c^T, c = (aw, -bw), sum |c| = 2.
    const double k2 = 2.0 * scale * law.stiffness(delta);
    for (int k = 0; k < na; ++k) {
      out->shell_f[ai[k]] += aw[k] * F;
      row_stiffness_[ai[k]] += aw[k] * k2;
      touched_.push_back(ai[k]);
    }
    for (int k = 0; k < nb; ++k) {
      out->shell_f[bi[k]] -= bw[k] * F;
      row_stiffness_[bi[k]] += bw[k] * k2;
      touched_.push_back(bi[k]);
    }
    return f;
  };

  // (vertex, face): the primary VT contacts.
  const double one = 1.0;
  for (const auto& [v, f] : vt_faces_) {
    const auto& t = mesh_.faces[f];
    const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    const TriangleClosest tc = point_triangle_closest(x[v], a, b, c);
    if (tc.dist2 >= t_ * t_) continue;
    const Vec3 Q = tc.w[0] * a + tc.w[1] * b + tc.w[2] * c;
    Vec3 fn = (b - a).cross(c - a).normalized();  // only for a vertex on the mid-surface
    if (fn.dot(x[v] - (a + b + c) / 3.0) < 0) fn = -fn;
    FacePair fp{v, f, tc.w, Vec3::Zero(), 0.0, 0.0};
    fp.force = contact(x[v], Q, fn, &v, &one, 1, t.data(), tc.w.data(), 3, hertz_vt_, weight_[v],
                       &fp.n, &fp.delta);
    face_pairs_.push_back(fp);
  }

  // Inclusion-exclusion corrections; with friction each is shared by the face pairs of its
  // vertex that contain the piece, so that a face pair's force is its share of the net.
  const bool share = out && friction_;
  auto share_force = [&](double f, int v, const int* faces, int n_faces) {
    if (f == 0.0) return;
    int owners[16];
    int n_own = 0;
    for (int j = 0; j < n_faces && n_own < 16; ++j) {
      const int k = find_face_pair(v, faces[j]);
      if (k >= 0) owners[n_own++] = k;
    }
    for (int i = 0; i < n_own; ++i) face_pairs_[owners[i]].force += f / n_own;
  };
  const Vec3 no_n = Vec3::UnitZ();        // only for exactly coincident points (measure zero)
  for (const auto& [v, e] : vt_edges_) {  // - (vertex, edge)
    const int q0 = mesh_.edges[e][0], q1 = mesh_.edges[e][1];
    const Vec3 d = x[q1] - x[q0];
    const double dd = d.squaredNorm();
    const double u = dd > 0 ? std::clamp((x[v] - x[q0]).dot(d) / dd, 0.0, 1.0) : 0.0;
    const int bi[2] = {q0, q1};
    const double bw[2] = {1.0 - u, u};
    const double f = contact(x[v], x[q0] + u * d, no_n, &v, &one, 1, bi, bw, 2, hertz_vt_,
                             -weight_[v], nullptr, nullptr);
    if (share) {
      const auto& ef = mesh_.edge_faces[e];
      const int faces[2] = {ef[0], ef[1]};
      share_force(f, v, faces, 2);
    }
  }
  for (const VertexPiece& p : vt_verts_) {  // + c_u (vertex, vertex)
    const double f = contact(x[p.v], x[p.u], no_n, &p.v, &one, 1, &p.u, &one, 1, hertz_vt_,
                             p.c * weight_[p.v], nullptr, nullptr);
    if (share) {
      const auto& vf = vertex_faces_[p.u];
      share_force(f, p.v, vf.data(), static_cast<int>(vf.size()));
    }
  }

  // Edge-edge.
  for (const auto& [e1, e2] : ee_) {
    const int a0 = mesh_.edges[e1][0], a1 = mesh_.edges[e1][1];
    const int b0 = mesh_.edges[e2][0], b1 = mesh_.edges[e2][1];
    const SegmentClosest c = segment_segment_closest(x[a0], x[a1], x[b0], x[b1]);
    const double D = hertz_ee_.D;
    if (c.dist2 >= D * D) continue;
    const Vec3 P = x[a0] + c.s * (x[a1] - x[a0]);
    const Vec3 Q = x[b0] + c.t * (x[b1] - x[b0]);
    Vec3 fn = (x[a1] - x[a0]).cross(x[b1] - x[b0]);
    fn = fn.squaredNorm() > 0.0 ? Vec3(fn.normalized()) : no_n;
    const int ai[2] = {a0, a1}, bi[2] = {b0, b1};
    const double aw[2] = {1.0 - c.s, c.s}, bw[2] = {1.0 - c.t, c.t};
    EdgePair ep{e1, e2, c.s, c.t, Vec3::Zero(), 0.0, 0.0};
    ep.force = contact(P, Q, fn, ai, aw, 2, bi, bw, 2, hertz_ee_, 1.0, &ep.n, &ep.delta);
    edge_pairs_.push_back(ep);
  }
  return U;
}

double ShellSelfContactTerm::accumulate(const State& s, Forces& out) {
  const double U = evaluate(s, &out);
  max_row_stiffness_ = 0.0;
  for (int v : touched_) max_row_stiffness_ = std::max(max_row_stiffness_, row_stiffness_[v]);
  if (!friction_) return U;

  const int nv = mesh_.num_vertices();
  auto ee_key = [nv](int e1, int e2) {
    return ContactKey{nv + std::min(e1, e2), std::max(e1, e2)};
  };
  for (const FacePair& c : face_pairs_) friction_->mark(ContactKey{c.v, c.f});
  for (const EdgePair& c : edge_pairs_) friction_->mark(ee_key(c.e1, c.e2));
  friction_->finish_marking();
  const double m_eff = 0.5 * p_.vertex_mass;
  const Vec3List& vel = s.shell_v;

  for (const FacePair& c : face_pairs_) {
    const auto& t = mesh_.faces[c.f];
    Vec3 v_rel = vel[c.v];
    for (int k = 0; k < 3; ++k) v_rel -= c.w[k] * vel[t[k]];
    // Neighbours for history transfer: the same vertex over the faces across f's edges.
    ContactKey nb[3];
    int n_nb = 0;
    for (int k = 0; k < 3; ++k) {
      const auto& ef = mesh_.edge_faces[mesh_.face_edges[c.f][k]];
      const int g = ef[0] == c.f ? ef[1] : ef[0];
      if (g >= 0) nb[n_nb++] = ContactKey{c.v, g};
    }
    const double w = weight_[c.v];
    const Vec3 ft = friction_->force(ContactKey{c.v, c.f}, c.n, std::max(c.force, 0.0),
                                     w * hertz_vt_.stiffness(c.delta), v_rel, m_eff / w, nb, n_nb);
    out.shell_f[c.v] += ft;
    for (int k = 0; k < 3; ++k) out.shell_f[t[k]] -= c.w[k] * ft;
  }

  for (const EdgePair& c : edge_pairs_) {
    const int a0 = mesh_.edges[c.e1][0], a1 = mesh_.edges[c.e1][1];
    const int b0 = mesh_.edges[c.e2][0], b1 = mesh_.edges[c.e2][1];
    const Vec3 v_rel =
        (1.0 - c.s) * vel[a0] + c.s * vel[a1] - (1.0 - c.t) * vel[b0] - c.t * vel[b1];
    // Neighbours: one edge fixed, the other replaced by an edge of its adjacent faces.
    ContactKey nb[8];
    int n_nb = 0;
    auto add_around = [&](int moving, int fixed) {
      for (int f : mesh_.edge_faces[moving]) {
        if (f < 0) continue;
        for (int g : mesh_.face_edges[f]) {
          if (g != moving && n_nb < 8) nb[n_nb++] = ee_key(g, fixed);
        }
      }
    };
    add_around(c.e2, c.e1);
    add_around(c.e1, c.e2);
    const Vec3 ft = friction_->force(ee_key(c.e1, c.e2), c.n, std::max(c.force, 0.0),
                                     hertz_ee_.stiffness(c.delta), v_rel, m_eff, nb, n_nb);
    out.shell_f[a0] += (1.0 - c.s) * ft;
    out.shell_f[a1] += c.s * ft;
    out.shell_f[b0] -= (1.0 - c.t) * ft;
    out.shell_f[b1] -= c.t * ft;
  }
  return U;
}

double ShellSelfContactTerm::omega_max_sq(const RodInertia&) const {
  // Gershgorin-style: the largest row sum of the net (signed, inclusion-exclusion) contact
  // stiffness over the smallest vertex mass; the tangential springs add their ratio.
  const double ratio = friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0;
  return ratio * max_row_stiffness_ / p_.vertex_mass;
}

template <class Self, class Archive>
void ShellSelfContactTerm::serialize(Self& t, Archive& ar) {
  ar.tag("SSLF");
  ar(t.rebuilds_);
  ar(t.ref_.at_build);
  ar(t.vt_faces_);
  ar(t.vt_edges_);
  ar(t.vt_verts_);
  ar(t.ee_);
  if (!t.ref_.at_build.empty() &&
      t.ref_.at_build.size() != static_cast<std::size_t>(t.mesh_.num_vertices()))
    ar.fail("shell self-contact of another mesh");
  serialize_friction(ar, t.friction_.get());
}

void ShellSelfContactTerm::save(StateWriter& out) const {
  serialize(*this, out);
}
void ShellSelfContactTerm::load(StateReader& in) {
  serialize(*this, in);
}

}  // namespace wirepack
