#include "engine/contact/wire_shell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "engine/contact/segment_distance.hpp"
#include "engine/contact/triangle_distance.hpp"
#include "engine/contact/verlet.hpp"

namespace wirepack {

namespace {
// The barrier of the contact law starts at half the overlap at which the wire's axis would
// reach the shell's mid-surface (hertz.hpp).
constexpr double kBarrierOnset = 0.5;
}  // namespace

WireShellTerm::WireShellTerm(const ShellMesh& mesh, const WireShellParams& p)
    : FrictionalTerm(p.friction),
      mesh_(mesh),
      p_(p),
      hertz_(Hertz::from(p.E_star, p.r).with_barrier(p.r + p.half_thickness, kBarrierOnset)) {
  vertex_faces_.resize(mesh.num_vertices());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int v : mesh.faces[f]) vertex_faces_[v].push_back(f);
  }
  // Boundary pieces (the rim of the hole): an edge of one face only, and its vertices.
  boundary_vertex_.assign(mesh.num_vertices(), 0);
  for (size_t k = 0; k < mesh.edges.size(); ++k) {
    if (mesh.edge_faces[k][1] < 0)
      boundary_vertex_[mesh.edges[k][0]] = boundary_vertex_[mesh.edges[k][1]] = 1;
  }
  if (p.guide) {
    // The guide's pieces: faces with an unclamped vertex, edges between two such faces and
    // interior vertices whose whole fan is such (inclusion-exclusion over their union).
    const auto unclamped = [&](int v) { return mesh.clamped.empty() || !mesh.clamped[v]; };
    guide_face_ok_.assign(mesh.num_faces(), 0);
    for (int f = 0; f < mesh.num_faces(); ++f) {
      for (int v : mesh.faces[f]) guide_face_ok_[f] |= unclamped(v) ? 1 : 0;
    }
    guide_edge_ok_.assign(mesh.edges.size(), 0);
    for (size_t k = 0; k < mesh.edges.size(); ++k) {
      const auto& ef = mesh.edge_faces[k];
      guide_edge_ok_[k] = ef[1] >= 0 && guide_face_ok_[ef[0]] && guide_face_ok_[ef[1]];
    }
    guide_vertex_ok_.assign(mesh.num_vertices(), 0);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      bool ok = !boundary_vertex_[v] && !vertex_faces_[v].empty();
      for (int f : vertex_faces_[v]) ok = ok && guide_face_ok_[f];
      guide_vertex_ok_[v] = ok;
    }
  }
}

void WireShellTerm::rebuild_guide(const Vec3List& xs, const Vec3& top) {
  guide_faces_.clear();
  guide_edges_.clear();
  guide_verts_.clear();
  if (!p_.guide) return;
  // Faces within r + t/2 + skin of the capsule [top, bottom]: while no vertex and not the top
  // moved more than half the skin (the wire's rebuild rule; the top is a wire node), the others
  // stay apart.
  const Vec3 bottom(0.0, 0.0, p_.guide_bottom_z);
  const double reach = p_.r + p_.half_thickness + p_.skin;
  const Vec3 lo = top.cwiseMin(bottom) - Vec3::Constant(reach);
  const Vec3 hi = top.cwiseMax(bottom) + Vec3::Constant(reach);
  for (int f = 0; f < mesh_.num_faces(); ++f) {
    if (!guide_face_ok_[f]) continue;
    const auto& v = mesh_.faces[f];
    const Vec3 fmin = xs[v[0]].cwiseMin(xs[v[1]]).cwiseMin(xs[v[2]]);
    const Vec3 fmax = xs[v[0]].cwiseMax(xs[v[1]]).cwiseMax(xs[v[2]]);
    if ((fmin.array() > hi.array()).any() || (fmax.array() < lo.array()).any()) continue;
    if (segment_triangle_closest(top, bottom, xs[v[0]], xs[v[1]], xs[v[2]]).dist2 < reach * reach)
      guide_faces_.push_back(f);
  }
  // The corrections of those faces (a piece within reach lies on faces within reach).
  for (int f : guide_faces_) {
    for (int k = 0; k < 3; ++k) {
      if (guide_edge_ok_[mesh_.face_edges[f][k]]) guide_edges_.push_back(mesh_.face_edges[f][k]);
      if (guide_vertex_ok_[mesh_.faces[f][k]]) guide_verts_.push_back(mesh_.faces[f][k]);
    }
  }
  for (auto* list : {&guide_edges_, &guide_verts_}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
}

double WireShellTerm::guide_evaluate(const State& s, Forces* out) {
  guide_contacts_ = 0;
  guide_max_overlap_ = 0.0;
  guide_max_stiffness_ = 0.0;
  if (guide_faces_.empty() || s.n_free >= s.num_nodes()) return 0.0;
  const int g = s.n_free;  // the first guide node: the capsule's top
  const Vec3& top = s.x[g];
  const Vec3 bottom(0.0, 0.0, p_.guide_bottom_z);
  const Vec3 axis = bottom - top;
  const double Dc = p_.r + p_.half_thickness;
  double U = 0.0;
  // One signed contact between the guide's point top + sg (bottom - top) and shell point Q
  // (weights ws on vertices si); returns whether they touch.
  auto contact = [&](double sg, const Vec3& Q, const Vec3& fallback_n, const int* si,
                     const double* ws, int ns, double sign) {
    const Vec3 d = top + sg * axis - Q;
    const double dist2 = d.squaredNorm();
    if (!(dist2 < Dc * Dc)) return false;
    const double dist = std::sqrt(dist2);
    const Vec3 n = dist > 1e-12 * p_.r ? Vec3(d / dist) : fallback_n;  // shell to guide
    const double delta = Dc - dist;
    U += sign * hertz_.energy(delta);
    guide_max_overlap_ = std::max(guide_max_overlap_, delta);
    if (out) {
      Vec3 vs = Vec3::Zero();
      for (int k = 0; k < ns; ++k) vs += ws[k] * s.shell_v[si[k]];
      // The guide is kinematic (infinite mass): the dashpot's mass is the vertex's.
      const double f = damped_normal_force(hertz_, delta, -(s.v[g] - vs).dot(n), p_.damping_ratio,
                                           p_.vertex_mass);
      const Vec3 F = sign * f * n;  // on the guide; -F on the shell
      for (int k = 0; k < ns; ++k) out->shell_f[si[k]] -= ws[k] * F;
      out->f[g] += (1.0 - sg) * F;
    }
    return true;
  };
  for (int f : guide_faces_) {  // + (guide, face)
    const auto& v = mesh_.faces[f];
    const Vec3 &a = s.shell_x[v[0]], &b = s.shell_x[v[1]], &c = s.shell_x[v[2]];
    const TriangleClosest tc = segment_triangle_closest(top, bottom, a, b, c);
    if (!(tc.dist2 < Dc * Dc)) continue;
    const Vec3 Q = tc.w[0] * a + tc.w[1] * b + tc.w[2] * c;
    Vec3 fn = (b - a).cross(c - a).normalized();
    if (fn.dot(top + tc.s * axis - (a + b + c) / 3.0) < 0) fn = -fn;
    if (contact(tc.s, Q, fn, v.data(), tc.w.data(), 3, +1.0)) {
      ++guide_contacts_;
      guide_max_stiffness_ =
          std::max(guide_max_stiffness_, hertz_.stiffness(Dc - std::sqrt(tc.dist2)));
    }
  }
  if (guide_contacts_ == 0) return U;
  const Vec3 no_n = Vec3::UnitX();  // only for a piece exactly on the axis (measure zero)
  for (int k : guide_edges_) {      // - (guide, shell edge)
    const int si[2] = {mesh_.edges[k][0], mesh_.edges[k][1]};
    const SegmentClosest c =
        segment_segment_closest(top, bottom, s.shell_x[si[0]], s.shell_x[si[1]]);
    const double ws[2] = {1.0 - c.t, c.t};
    contact(c.s, s.shell_x[si[0]] + c.t * (s.shell_x[si[1]] - s.shell_x[si[0]]), no_n, si, ws, 2,
            -1.0);
  }
  for (int vtx : guide_verts_) {  // + (guide, shell vertex)
    const Vec3& Q = s.shell_x[vtx];
    const double aa = axis.squaredNorm();
    const double t = aa > 0 ? std::clamp((Q - top).dot(axis) / aa, 0.0, 1.0) : 0.0;
    const double one = 1.0;
    contact(t, Q, no_n, &vtx, &one, 1, +1.0);
  }
  return U;
}

void WireShellTerm::maybe_rebuild(const State& s) {
  const int ne = active_edges(s);
  if (ne != edges_at_build_ ||
      wire_ref_.moved_beyond(s.x, std::min(ne + 1, s.num_nodes()), p_.skin) ||
      shell_ref_.moved_beyond(s.shell_x, s.shell_x.size(), p_.skin))
    rebuild(s);
}

void WireShellTerm::rebuild(const State& s) {
  const int ne = active_edges(s);
  const int nf = mesh_.num_faces();
  ++rebuilds_;
  edges_at_build_ = ne;
  wire_ref_.build(s.x, std::min(ne + 1, s.num_nodes()));
  shell_ref_.build(s.shell_x, s.shell_x.size());
  if (!wire_ref_.at_build.empty()) rebuild_guide(shell_ref_.at_build, wire_ref_.at_build.back());
  candidates_.clear();
  seg_edge_.clear();
  seg_vert_.clear();
  cand_slack2_4_.clear();
  edge_slack2_4_.clear();
  vert_slack2_4_.clear();
  if (ne < 1 || nf == 0) return;
  points_.resize(ne + nf);
  double lmax = 0.0;
  for (int e = 0; e < ne; ++e) {
    points_[e] = 0.5 * (s.x[e] + s.x[e + 1]);
    lmax = std::max(lmax, (s.x[e + 1] - s.x[e]).norm());
  }
  double face_reach = 0.0;
#pragma omp parallel for schedule(static) reduction(max : face_reach)
  for (int f = 0; f < nf; ++f) {
    const auto& v = mesh_.faces[f];
    const Vec3 c = (s.shell_x[v[0]] + s.shell_x[v[1]] + s.shell_x[v[2]]) / 3.0;
    points_[ne + f] = c;
    for (int k = 0; k < 3; ++k) face_reach = std::max(face_reach, (s.shell_x[v[k]] - c).norm());
  }
  face_reach_ = face_reach;
  const double Dc = p_.r + p_.half_thickness;
  const double reach = Dc + p_.skin;
  grid_.find_pairs_between(points_, ne, 0.5 * lmax + face_reach_ + reach, broad_);
  // (wire edge, face) pairs within reach with their slack (verlet.hpp), sorted by pair
  // (the broad phase lists its pairs in (i, j) order).
  // Distances in parallel (one entry per broad pair), the list in the broad phase's order.
  const int nb = static_cast<int>(broad_.size());
  broad_dist2_.resize(nb);
#pragma omp parallel for schedule(dynamic, 64)
  for (int k = 0; k < nb; ++k) {
    const auto [e, j] = broad_[k];  // (wire edge, ne + face): find_pairs_between
    const auto& v = mesh_.faces[j - ne];
    broad_dist2_[k] = segment_triangle_closest(s.x[e], s.x[e + 1], s.shell_x[v[0]], s.shell_x[v[1]],
                                               s.shell_x[v[2]])
                          .dist2;
  }
  found_.clear();
  for (int k = 0; k < nb; ++k) {
    const double dist2 = broad_dist2_[k];
    if (dist2 < reach * reach) {
      found_.push_back({broad_[k].first, broad_[k].second - ne, quarter_slack2(dist2, Dc, p_.r)});
    }
  }
  for (const auto& c : found_) {
    candidates_.emplace_back(c.e, c.f);
    cand_slack2_4_.push_back(c.slack2_4);
  }
  // Unique (wire edge, shell edge) and (wire edge, shell vertex) pairs of the candidates, for
  // the inclusion-exclusion corrections: an edge is the overlap of its two faces, an interior
  // vertex the overlap of its closed fan; the rim's pieces overlap nothing. Built here, not per
  // evaluation: they change only with the candidates.
  // The candidates come sorted by wire edge: sorting each edge's few pieces gives the sorted
  // unique lists at a fraction of one global sort.
  const auto sort_unique_from = [](std::vector<std::pair<int, int>>& list, size_t from) {
    std::sort(list.begin() + from, list.end());
    list.erase(std::unique(list.begin() + from, list.end()), list.end());
  };
  for (size_t i = 0; i < candidates_.size();) {
    const int e = candidates_[i].first;
    const size_t edges_from = seg_edge_.size(), verts_from = seg_vert_.size();
    for (; i < candidates_.size() && candidates_[i].first == e; ++i) {
      const int f = candidates_[i].second;
      for (int k = 0; k < 3; ++k) {
        const int ek = mesh_.face_edges[f][k], vk = mesh_.faces[f][k];
        if (mesh_.edge_faces[ek][1] >= 0) seg_edge_.emplace_back(e, ek);
        if (!boundary_vertex_[vk]) seg_vert_.emplace_back(e, vk);
      }
    }
    sort_unique_from(seg_edge_, edges_from);
    sort_unique_from(seg_vert_, verts_from);
  }
  // Slack of the correction pairs, from their distances at the build (in parallel, one entry
  // per pair).
  const int n_edge = static_cast<int>(seg_edge_.size());
  const int n_vert = static_cast<int>(seg_vert_.size());
  edge_slack2_4_.resize(n_edge);
  vert_slack2_4_.resize(n_vert);
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_edge; ++q) {
      const auto [e, k] = seg_edge_[q];
      const SegmentClosest c = segment_segment_closest(
          s.x[e], s.x[e + 1], s.shell_x[mesh_.edges[k][0]], s.shell_x[mesh_.edges[k][1]]);
      edge_slack2_4_[q] = quarter_slack2(c.dist2, Dc, p_.r);
    }
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_vert; ++q) {
      const auto [e, vtx] = seg_vert_[q];
      const SegmentClosest c =
          segment_segment_closest(s.x[e], s.x[e + 1], s.shell_x[vtx], s.shell_x[vtx]);
      vert_slack2_4_[q] = quarter_slack2(c.dist2, Dc, p_.r);
    }
  }
  // Owners of each correction: the candidates (wire edge, face) of the faces around the shell
  // edge (its two faces in order) or vertex (its fan in order); -1 where a face is not a
  // candidate. A correction's pieces lie on its owners' faces, so it touches only while one of
  // its owners does.
  const auto candidate_of = [&](int e, int f) {
    const auto it = std::lower_bound(candidates_.begin(), candidates_.end(), std::make_pair(e, f));
    return it != candidates_.end() && *it == std::make_pair(e, f)
               ? static_cast<int>(it - candidates_.begin())
               : -1;
  };
  // Offsets first (serial prefix sum), then the owners in parallel, each pair its own slots.
  vert_owner_start_.assign(n_vert + 1, 0);
  for (int q = 0; q < n_vert; ++q) {
    vert_owner_start_[q + 1] =
        vert_owner_start_[q] + static_cast<int>(vertex_faces_[seg_vert_[q].second].size());
  }
  edge_owner_.resize(n_edge);
  vert_owner_.resize(vert_owner_start_[n_vert]);
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_edge; ++q) {
      const auto [e, k] = seg_edge_[q];
      const auto& ef = mesh_.edge_faces[k];
      edge_owner_[q] = {candidate_of(e, ef[0]), ef[1] >= 0 ? candidate_of(e, ef[1]) : -1};
    }
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_vert; ++q) {
      const auto [e, vtx] = seg_vert_[q];
      int* slot = vert_owner_.data() + vert_owner_start_[q];
      for (int f : vertex_faces_[vtx]) *slot++ = candidate_of(e, f);
    }
  }
}

namespace {

// A piece of the wire (an edge, or an interior node) or of the shell (a face, an edge, a
// vertex): up to three points with weights.
struct Piece {
  int idx[3] = {-1, -1, -1};
  int count = 0;
};

}  // namespace

double WireShellTerm::evaluate(const State& s, Forces* out) {
  maybe_rebuild(s);
  const double Dc = p_.r + p_.half_thickness;
  const double m_eff = 1.0 / (1.0 / p_.node_mass + 1.0 / p_.vertex_mass);
  face_pairs_.clear();
  max_overlap_ = 0.0;

  // One signed contact between wire point P (weights ww on wire nodes wi) and shell point Q
  // (weights ws on shell vertices si): normal, overlap, energy and force, without side effects
  // (so that threads can compute them); hit.touching is false when apart.
  auto contact = [&](const Vec3& P, const Vec3& Q, const Vec3& fallback_n, const int* wi,
                     const double* ww, int nw, const int* si, const double* ws, int ns, double sign,
                     Hit& hit) {
    const Vec3 d = P - Q;
    const double dist2 = d.squaredNorm();
    hit.touching = dist2 < Dc * Dc;
    if (!hit.touching) return;
    const double dist = std::sqrt(dist2);
    hit.n = dist > 1e-12 * p_.r ? Vec3(d / dist) : fallback_n;
    hit.delta = Dc - dist;
    hit.energy = sign * hertz_.energy(hit.delta);
    if (!out) {
      hit.force = sign * hertz_.force(hit.delta);
      return;
    }
    Vec3 vw = Vec3::Zero(), vs = Vec3::Zero();
    for (int k = 0; k < nw; ++k) vw += ww[k] * s.v[wi[k]];
    for (int k = 0; k < ns; ++k) vs += ws[k] * s.shell_v[si[k]];
    const double f =
        damped_normal_force(hertz_, hit.delta, -(vw - vs).dot(hit.n), p_.damping_ratio, m_eff);
    hit.F = sign * f * hit.n;  // on the wire; -F on the shell
    hit.force = sign * f;
  };
  // Adds a contact computed above (in pair order, so the sums do not depend on the threads);
  // returns its signed normal force [N] (0 when apart).
  double U = 0.0;
  auto apply = [&](const Hit& hit, const int* wi, const double* ww, int nw, const int* si,
                   const double* ws, int ns) -> double {
    if (!hit.touching) return 0.0;
    max_overlap_ = std::max(max_overlap_, hit.delta);
    U += hit.energy;
    if (out) {
      for (int k = 0; k < nw; ++k) out->f[wi[k]] += ww[k] * hit.F;
      for (int k = 0; k < ns; ++k) out->shell_f[si[k]] -= ws[k] * hit.F;
    }
    return hit.force;
  };

  // Geometry and contact forces first, in parallel (threads over pairs; each writes its own
  // entry): the closest points of the (wire edge, face), (wire edge, shell edge) and (wire
  // edge, shell vertex) pairs that can touch, and the contacts of those that do. The forces are
  // then added serially in pair order, so the sums do not depend on the threads.
  const auto wire_moved2 = [&](int e) {
    return std::max(wire_ref_.moved2[e], wire_ref_.moved2[e + 1]);
  };
  const int n_cand = static_cast<int>(candidates_.size());
  const int n_edge = static_cast<int>(seg_edge_.size());
  const int n_vert = static_cast<int>(seg_vert_.size());
  cand_geo_.resize(n_cand);
  cand_hit_.resize(n_cand);
  edge_geo_.resize(n_edge);
  edge_hit_.resize(n_edge);
  vert_t_.resize(n_vert);
  vert_hit_.resize(n_vert);
  const double far2 = Dc * Dc;  // dist2 at or above this: no contact
  const double skipped = std::numeric_limits<double>::infinity();  // dist2 of a skipped pair
  // A candidate touches when its distance is below r + t/2 (then it is a face pair below).
  const auto touching = [&](int q) { return q >= 0 && cand_geo_[q].dist2 < far2; };
  const Vec3 no_n = Vec3::UnitZ();  // only for exactly coincident points (measure zero)
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_cand; ++q) {
      const auto [e, f] = candidates_[q];
      const auto& v = mesh_.faces[f];
      const double moved2 = std::max(
          wire_moved2(e), std::max(shell_ref_.moved2[v[0]],
                                   std::max(shell_ref_.moved2[v[1]], shell_ref_.moved2[v[2]])));
      if (moved2 < cand_slack2_4_[q]) {  // cannot touch yet
        cand_geo_[q].dist2 = far2;
        continue;
      }
      const TriangleClosest& tc = cand_geo_[q] = segment_triangle_closest(
          s.x[e], s.x[e + 1], s.shell_x[v[0]], s.shell_x[v[1]], s.shell_x[v[2]]);
      if (tc.dist2 >= far2) continue;
      // The primary contact: closest points, the face's normal towards the wire as fallback.
      const Vec3 &a = s.shell_x[v[0]], &b = s.shell_x[v[1]], &c = s.shell_x[v[2]];
      const Vec3 P = s.x[e] + tc.s * (s.x[e + 1] - s.x[e]);
      const Vec3 Q = tc.w[0] * a + tc.w[1] * b + tc.w[2] * c;
      Vec3 fn = (b - a).cross(c - a).normalized();
      if (fn.dot(P - (a + b + c) / 3.0) < 0) fn = -fn;
      const int wi[2] = {e, e + 1};
      const double ww[2] = {1.0 - tc.s, tc.s};
      contact(P, Q, fn, wi, ww, 2, v.data(), tc.w.data(), 3, +1.0, cand_hit_[q]);
    }
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_edge; ++q) {  // - (wire edge, shell edge)
      const auto [e, k] = seg_edge_[q];
      const int v0 = mesh_.edges[k][0], v1 = mesh_.edges[k][1];
      edge_hit_[q].touching = false;
      if (std::max(wire_moved2(e), std::max(shell_ref_.moved2[v0], shell_ref_.moved2[v1])) <
              edge_slack2_4_[q] ||
          (!touching(edge_owner_[q][0]) && !touching(edge_owner_[q][1]))) {
        edge_geo_[q].dist2 = skipped;
        continue;
      }
      const SegmentClosest& c = edge_geo_[q] =
          segment_segment_closest(s.x[e], s.x[e + 1], s.shell_x[v0], s.shell_x[v1]);
      const int wi[2] = {e, e + 1}, si[2] = {v0, v1};
      const double ww[2] = {1 - c.s, c.s}, ws[2] = {1 - c.t, c.t};
      contact(s.x[e] + c.s * (s.x[e + 1] - s.x[e]),
              s.shell_x[v0] + c.t * (s.shell_x[v1] - s.shell_x[v0]), no_n, wi, ww, 2, si, ws, 2,
              -1.0, edge_hit_[q]);
    }
#pragma omp for schedule(dynamic, 64)
    for (int q = 0; q < n_vert; ++q) {  // + (wire edge, shell vertex)
      const auto [e, vtx] = seg_vert_[q];
      vert_hit_[q].touching = false;
      if (std::max(wire_moved2(e), shell_ref_.moved2[vtx]) < vert_slack2_4_[q]) continue;
      const int* owners = vert_owner_.data() + vert_owner_start_[q];
      const int n_owners = vert_owner_start_[q + 1] - vert_owner_start_[q];
      bool any = false;
      for (int j = 0; j < n_owners && !any; ++j) any = touching(owners[j]);
      if (!any) continue;
      // Closest point of the wire edge to the vertex: x_e + t (x_e+1 - x_e), t in [0, 1].
      const Vec3& Q = s.shell_x[vtx];
      const Vec3 d = s.x[e + 1] - s.x[e];
      const double dd = d.squaredNorm();
      const double t = vert_t_[q] = dd > 0 ? std::clamp((Q - s.x[e]).dot(d) / dd, 0.0, 1.0) : 0.0;
      const int wi[2] = {e, e + 1};
      const double ww[2] = {1 - t, t}, one = 1.0;
      contact(s.x[e] + t * d, Q, no_n, wi, ww, 2, &vtx, &one, 1, +1.0, vert_hit_[q]);
    }
  }

  // (wire edge, face): the primary contacts, one face pair per candidate within reach.
  cand_face_pair_.assign(n_cand, -1);
  for (int q = 0; q < n_cand; ++q) {
    const TriangleClosest& tc = cand_geo_[q];
    if (tc.dist2 >= far2) continue;
    cand_face_pair_[q] = static_cast<int>(face_pairs_.size());
    const auto [e, f] = candidates_[q];
    const int wi[2] = {e, e + 1};
    const double ww[2] = {1.0 - tc.s, tc.s};
    const Hit& hit = cand_hit_[q];
    FacePair fp{e, f, tc.s, tc.w, Vec3::Zero(), 0.0, 0.0};
    if (hit.touching) {
      fp.n = hit.n;
      fp.delta = hit.delta;
    }
    fp.force = apply(hit, wi, ww, 2, mesh_.faces[f].data(), tc.w.data(), 3);
    face_pairs_.push_back(fp);
  }

  // Corrections of inclusion-exclusion, each shared by the face pairs it belongs to.
  auto share = [&](double signed_force, const int* owner_candidates, int n_c) {
    if (signed_force == 0.0) return;
    int owners[16];
    int n_own = 0;
    for (int j = 0; j < n_c; ++j) {
      const int k = owner_candidates[j] >= 0 ? cand_face_pair_[owner_candidates[j]] : -1;
      if (k >= 0 && n_own < 16) owners[n_own++] = k;
    }
    for (int i = 0; i < n_own; ++i) face_pairs_[owners[i]].force += signed_force / n_own;
  };
  for (int q = 0; q < n_edge; ++q) {  // - (wire edge, shell edge)
    if (!edge_hit_[q].touching) continue;
    const SegmentClosest& c = edge_geo_[q];
    const auto [e, k] = seg_edge_[q];
    const int wi[2] = {e, e + 1}, si[2] = {mesh_.edges[k][0], mesh_.edges[k][1]};
    const double ww[2] = {1 - c.s, c.s}, ws[2] = {1 - c.t, c.t};
    share(apply(edge_hit_[q], wi, ww, 2, si, ws, 2), edge_owner_[q].data(), 2);
  }
  for (int q = 0; q < n_vert; ++q) {  // + (wire edge, shell vertex)
    if (!vert_hit_[q].touching) continue;
    const auto [e, vtx] = seg_vert_[q];
    const double t = vert_t_[q];
    const int wi[2] = {e, e + 1};
    const double ww[2] = {1 - t, t}, one = 1.0;
    share(apply(vert_hit_[q], wi, ww, 2, &vtx, &one, 1), vert_owner_.data() + vert_owner_start_[q],
          vert_owner_start_[q + 1] - vert_owner_start_[q]);
  }
  // The guide (adds exactly nothing while no face is within its reach).
  if (p_.guide) U += guide_evaluate(s, out);
  return U;
}

double WireShellTerm::accumulate(const State& s, Forces& out) {
  const double U = evaluate(s, &out);
  double kmax = 0.0;
  for (const FacePair& c : face_pairs_) kmax = std::max(kmax, hertz_.stiffness(c.delta));
  kmax = std::max(kmax, guide_max_stiffness_);
  max_stiffness_ = kmax * (friction_ ? 1.0 + p_.friction.stiffness_ratio : 1.0);
  if (!friction_) return U;
  for (const FacePair& c : face_pairs_) friction_->mark(ContactKey{c.e, c.f});
  friction_->finish_marking();
  const bool twist = s.has_twist();
  const double r = p_.r;
  const double m_eff = 1.0 / (1.0 / p_.node_mass + 1.0 / p_.vertex_mass);
  // The friction queries in parallel (each its own entry), the forces added in pair order.
  const int np = static_cast<int>(face_pairs_.size());
  queries_.resize(np);
  edge_t_.resize(np);
#pragma omp parallel for schedule(dynamic, 64)
  for (int i = 0; i < np; ++i) {
    const FacePair& c = face_pairs_[i];
    const int e = c.e;
    const auto& v = mesh_.faces[c.f];
    Vec3 v_rel = (1.0 - c.s) * s.v[e] + c.s * s.v[e + 1];
    for (int k = 0; k < 3; ++k) v_rel -= c.w[k] * s.shell_v[v[k]];
    Vec3 te = Vec3::Zero();
    if (twist) {
      te = (s.x[e + 1] - s.x[e]).normalized();
      v_rel += s.omega[e] * te.cross(-r * c.n);  // the wire's surface point at -r n
    }
    edge_t_[i] = te;
    FrictionHistory::Query& q = queries_[i];
    q.key = ContactKey{e, c.f};
    q.n = c.n;
    q.F_n = std::max(c.force, 0.0);
    q.k_n = hertz_.stiffness(c.delta);
    q.v_rel = v_rel;
    q.m_eff = m_eff;
    // Neighbours for history transfer: the next edges along the wire, the faces across.
    q.neighbours[0] = {e + 1, c.f};
    q.neighbours[1] = {e - 1, c.f};
    for (int k = 0; k < 3; ++k) {
      const auto& ef = mesh_.edge_faces[mesh_.face_edges[c.f][k]];
      q.neighbours[2 + k] = {e, ef[0] == c.f ? ef[1] : ef[0]};
    }
    q.num_neighbours = 5;
  }
  friction_->forces(queries_, friction_force_);
  for (int i = 0; i < np; ++i) {
    const FacePair& c = face_pairs_[i];
    const int e = c.e;
    const auto& v = mesh_.faces[c.f];
    const Vec3& ft = friction_force_[i];
    out.f[e] += (1.0 - c.s) * ft;
    out.f[e + 1] += c.s * ft;
    for (int k = 0; k < 3; ++k) out.shell_f[v[k]] -= c.w[k] * ft;
    if (twist) out.torque[e] += (-r * c.n).cross(ft).dot(edge_t_[i]);
  }
  return U;
}

std::string WireShellTerm::failure() const {
  if (guide_max_overlap_ >= hertz_.D)
    return "guide-shell contact: the shell reached the feed axis outside the hole (overlap " +
           std::to_string(guide_max_overlap_ / p_.r) + " r)";
  if (max_overlap_ < hertz_.D) return {};
  return "wire-shell contact: the wire's axis reached the shell's mid-surface (overlap " +
         std::to_string(max_overlap_ / p_.r) + " r)";
}

double WireShellTerm::omega_max_sq(const RodInertia&) const {
  // Gershgorin on M^-1/2 K M^-1/2 (the eigenvalues of M^-1 K) for a contact of stiffness k
  // between a wire point (weights summing to 1 over nodes of mass m_n) and a shell point
  // (weights summing to 1 over vertices of mass m_v): the row of a vertex sums to at most
  // k (1 / m_v + 1 / sqrt(m_v m_n)), a node's to k (1 / m_n + 1 / sqrt(m_v m_n)). Equal
  // masses give the former 2 k / m; a light vertex against the wire's point mass (m_v / m_n
  // ~ 0.07 at xi = 10) about 1.3 k / m_v.
  const double m_min = std::min(p_.node_mass, p_.vertex_mass);
  return max_stiffness_ * (1.0 / m_min + 1.0 / std::sqrt(p_.node_mass * p_.vertex_mass));
}

template <class Self, class Archive>
void WireShellTerm::serialize(Self& t, Archive& ar) {
  ar.tag("WSHL");
  ar(t.edges_at_build_, t.rebuilds_, t.face_reach_, t.wire_ref_.at_build, t.shell_ref_.at_build);
  ar(t.candidates_, t.seg_edge_, t.seg_vert_, t.edge_owner_, t.vert_owner_start_, t.vert_owner_);
  ar(t.cand_slack2_4_, t.edge_slack2_4_, t.vert_slack2_4_);
  if (!t.shell_ref_.at_build.empty() &&
      t.shell_ref_.at_build.size() != static_cast<std::size_t>(t.mesh_.num_vertices()))
    ar.fail("wire-shell contact of another mesh");
  serialize_friction(ar, t.friction_.get());
}

void WireShellTerm::save(StateWriter& out) const {
  serialize(*this, out);
}
void WireShellTerm::load(StateReader& in) {
  serialize(*this, in);
  // The guide's candidates are a function of the state at the build (not stored).
  if (!wire_ref_.at_build.empty()) rebuild_guide(shell_ref_.at_build, wire_ref_.at_build.back());
}

}  // namespace wirepack
