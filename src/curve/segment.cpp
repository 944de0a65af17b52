#include "segment.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "hermite_basis.hpp"
#include "kinds.hpp"
#include "vec3.hpp"

namespace b2b {
namespace curve {
bool points_coincide(const double* xa, const double* xb) {
  double d[3];
  sub3(xb, xa, d);
  const double tol =
      std::max(B2B_LENGTH_MIN, 4.0 * DBL_EPSILON * std::max(max_abs3(xa), max_abs3(xb)));
  return !(dot3(d, d) > tol * tol);
}

namespace {

bool coincident(const double* X, int sa, int sb) {
  const double* xa = X + 3 * sa;
  const double* xb = X + 3 * sb;
  double d[3];
  sub3(xb, xa, d);
  const double tol =
      std::max(B2B_LENGTH_MIN, 4.0 * DBL_EPSILON * std::max(max_abs3(xa), max_abs3(xb)));
  return !(dot3(d, d) > tol * tol);
}

}  // namespace

unsigned used_slots(int kind, int start_rule, int end_rule) {
  const KindInfo& k = kind_info(kind);
  return k.slots | (start_rule == B2B_END_NEIGHBOUR ? k.start_neighbour_slots : 0u) |
         (end_rule == B2B_END_NEIGHBOUR ? k.end_neighbour_slots : 0u);
}

bool uses_start_tangent(int kind, int start_rule) {
  return kind_info(kind).host_tangents && start_rule == B2B_END_TANGENT;
}

bool uses_end_tangent(int kind, int end_rule) {
  return kind_info(kind).host_tangents && end_rule == B2B_END_TANGENT;
}

void Segment::set_linear(int k, double c0, double c1, double c2, double c3, const double* X) {
  Term& t = term_[k];
  t.nonlinear = false;
  t.coef[0] = c0;
  t.coef[1] = c1;
  t.coef[2] = c2;
  t.coef[3] = c3;
  // From the nodes' offsets to the base node: a position term (coefficients
  // summing to 1) is then the base plus an offset formed at the size of the
  // patch, so a midpoint far from the coordinates' origin loses nothing in
  // point_from; a tangent term (coefficients summing to 0) is the same
  // difference either way.
  const bool position = (k % 2 == 0);
  for (int i = 0; i < 3; ++i) {
    double v = 0.0;
    for (int s = 0; s < 4; ++s)
      if (t.coef[s] != 0.0) v += t.coef[s] * (X[3 * s + i] - base_[i]);  // unused slots are never read
    t.offset[i] = position ? v : 0.0;
    t.value[i] = position ? base_[i] + v : v;
  }
}

namespace {

Failure rejected(int status, int slot_a, int slot_b) {
  Failure f;
  f.status = status;
  f.slot_a = slot_a;
  f.slot_b = slot_b;
  return f;
}

// An end tangent whose direction follows the nodes a, b, c (the end node b
// and its neighbours), by the kind's rule.
void set_direction(TangentTerm& tt, TangentTerm::Dir dir, int a, int b, int c) {
  tt.dir = dir;
  tt.a = a;
  tt.b = b;
  tt.c = c;
}

// An end tangent along the host's unit direction u (a constant).
void set_given(TangentTerm& tt, const double* u) {
  tt.dir = TangentTerm::Dir::Constant;
  for (int i = 0; i < 3; ++i) tt.given[i] = u[i];
}

}  // namespace

TangentTerm& Segment::set_tangent(int k, double sigma, int p, int q) {
  Term& t = term_[k];
  t.nonlinear = true;
  TangentTerm& tt = tangent_of(k);
  tt.sigma = sigma;
  tt.p = p;
  tt.q = q;
  return tt;
}

Failure Segment::build(int kind, int start_rule, int end_rule, const double* X,
                       const double* unit_tangents, bool derivatives) {
  linear_kind_ = false;
  interior_nodal_ = false;
  for (Term& t : term_) t.nonlinear = false;
  for (int i = 0; i < 3; ++i) base_[i] = X[3 + i];  // x2, read by every kind
  Failure f;
  switch (kind_of(kind)) {
    case Kind::Linear:
      linear_kind_ = true;
      f = build_chord(X);
      break;
    case Kind::HermiteMidpoint:
      f = build_midpoint(start_rule, end_rule, X, unit_tangents);
      break;
    case Kind::HermiteNodal:
      f = build_nodal(TangentTerm::Dir::Chord, start_rule, end_rule, X, unit_tangents);
      break;
    case Kind::HermiteNodalWeighted:
      f = build_nodal(TangentTerm::Dir::Weighted, start_rule, end_rule, X, unit_tangents);
      break;
  }
  if (f.status) return f;

  for (int k = 1; k < 4; k += 2) {
    Term& t = term_[k];
    if (!t.nonlinear) continue;
    TangentTerm& tt = tangent_of(k);
    if (!tt.evaluate(X)) return rejected(B2B_ERR_FOLDED, tt.a, tt.c);
    for (int i = 0; i < 3; ++i) t.value[i] = tt.value[i];
    if (derivatives) tt.jacobian();
  }
  return f;
}

Failure Segment::build_chord(const double* X) {
  if (coincident(X, 1, 2)) return rejected(B2B_ERR_COINCIDENT, 1, 2);
  set_linear(0, 0, 1, 0, 0, X);  // x2
  set_linear(2, 0, 0, 1, 0, X);  // x3
  // The chord tangent (x3 - x2)/2 at both ends, whatever the rules.
  set_linear(1, 0, -0.5, 0.5, 0, X);
  set_linear(3, 0, -0.5, 0.5, 0, X);
  return Failure();
}

Failure Segment::build_nodal(TangentTerm::Dir dir, int start_rule, int end_rule, const double* X,
                             const double* unit_tangents) {
  if (coincident(X, 1, 2)) return rejected(B2B_ERR_COINCIDENT, 1, 2);
  if (start_rule == B2B_END_NEIGHBOUR) {
    if (coincident(X, 0, 1)) return rejected(B2B_ERR_COINCIDENT, 0, 1);
    if (coincident(X, 0, 2)) return rejected(B2B_ERR_FOLDED, 0, 2);
  }
  if (end_rule == B2B_END_NEIGHBOUR) {
    if (coincident(X, 2, 3)) return rejected(B2B_ERR_COINCIDENT, 2, 3);
    if (coincident(X, 1, 3)) return rejected(B2B_ERR_FOLDED, 1, 3);
  }
  set_linear(0, 0, 1, 0, 0, X);  // x2
  set_linear(2, 0, 0, 1, 0, X);  // x3
  // A reflected ghost gives the chord tangent (x3 - x2)/2.
  if (start_rule == B2B_END_REFLECT)
    set_linear(1, 0, -0.5, 0.5, 0, X);
  else if (start_rule == B2B_END_TANGENT)
    set_given(set_tangent(1, 0.5, 1, 2), unit_tangents);
  else
    set_direction(set_tangent(1, 0.5, 1, 2), dir, 0, 1, 2);
  if (end_rule == B2B_END_REFLECT)
    set_linear(3, 0, -0.5, 0.5, 0, X);
  else if (end_rule == B2B_END_TANGENT)
    set_given(set_tangent(3, 0.5, 1, 2), unit_tangents + 3);
  else
    set_direction(set_tangent(3, 0.5, 1, 2), dir, 1, 2, 3);
  interior_nodal_ = start_rule == B2B_END_NEIGHBOUR && end_rule == B2B_END_NEIGHBOUR;
  return Failure();
}

Failure Segment::build_midpoint(int start_rule, int end_rule, const double* X,
                                const double* unit_tangents) {
  // Centred on x2.
  const bool first = start_rule != B2B_END_NEIGHBOUR;
  const bool last = end_rule != B2B_END_NEIGHBOUR;
  if (first && last) return rejected(B2B_ERR_RANGE, -1, -1);
  if (!first && coincident(X, 0, 1)) return rejected(B2B_ERR_COINCIDENT, 0, 1);
  if (!last && coincident(X, 1, 2)) return rejected(B2B_ERR_COINCIDENT, 1, 2);
  // x1 = x3: the parabola from m12 to m23 = m12 turns back at x2 (a hairpin
  // whose tangent vanishes at its apex); l13 = 0 is FOLDED (b2b_curve.h).
  if (!first && !last && coincident(X, 0, 2)) return rejected(B2B_ERR_FOLDED, 0, 2);
  if (first) {  // half element from x2 to the midpoint of x2-x3
    set_linear(0, 0, 1, 0, 0, X);
    if (start_rule == B2B_END_TANGENT)
      set_given(set_tangent(1, 0.25, 1, 2), unit_tangents);
    else
      set_linear(1, 0, -0.25, 0.25, 0, X);
    set_linear(2, 0, 0.5, 0.5, 0, X);
    set_linear(3, 0, -0.25, 0.25, 0, X);
  } else if (last) {  // half element from the midpoint of x1-x2 to x2
    set_linear(0, 0.5, 0.5, 0, 0, X);
    set_linear(1, -0.25, 0.25, 0, 0, X);
    set_linear(2, 0, 1, 0, 0, X);
    if (end_rule == B2B_END_TANGENT)
      set_given(set_tangent(3, 0.25, 0, 1), unit_tangents + 3);
    else
      set_linear(3, -0.25, 0.25, 0, 0, X);
  } else {  // parabola m12 -> m23 with control point x2
    set_linear(0, 0.5, 0.5, 0, 0, X);
    set_linear(1, -0.5, 0.5, 0, 0, X);
    set_linear(2, 0, 0.5, 0.5, 0, X);
    set_linear(3, 0, -0.5, 0.5, 0, X);
  }
  return Failure();
}

void Segment::point(double xi, double* x, double* xd, double* xdd) const {
  static const double zero[3] = {0.0, 0.0, 0.0};
  point_from(zero, xi, x, xd, xdd);
}

void Segment::point_from(const double* origin, double xi, double* x, double* xd,
                         double* xdd) const {
  // x(xi) - origin = (base - origin) + the Hermite sum over the position
  // terms' offsets and the tangents (the position weights sum to 1 and their
  // derivatives to 0, so the base comes off whole).
  const double* p0 = term_[0].offset;
  const double* p1 = term_[2].offset;
  if (linear_kind_) {  // the chord: no Hermite weights to pay for
    for (int i = 0; i < 3; ++i) {
      if (x) x[i] = (base_[i] - origin[i]) + (0.5 * (1.0 - xi) * p0[i] + 0.5 * (1.0 + xi) * p1[i]);
      if (xd) xd[i] = 0.5 * (p1[i] - p0[i]);
      if (xdd) xdd[i] = 0.0;
    }
    return;
  }
  const HermiteBasis hb(xi);
  for (int i = 0; i < 3; ++i) {
    const double tv[4] = {p0[i], term_[1].value[i], p1[i], term_[3].value[i]};
    double v = 0, vd = 0, vdd = 0;
    for (int k = 0; k < 4; ++k) {
      v += hb.h[k] * tv[k];
      vd += hb.dh[k] * tv[k];
      vdd += hb.ddh[k] * tv[k];
    }
    if (x) x[i] = (base_[i] - origin[i]) + v;
    if (xd) xd[i] = vd;
    if (xdd) xdd[i] = vdd;
  }
}

void Segment::jacobians(double xi, double* P, double* Pd) const {
  // Linear terms contribute a multiple of the identity per slot.
  double wgt[4] = {0, 0, 0, 0}, dwgt[4] = {0, 0, 0, 0};
  if (linear_kind_) {  // the chord's weights, without the Hermite detour
    wgt[1] = 0.5 * (1.0 - xi);
    wgt[2] = 0.5 * (1.0 + xi);
    dwgt[1] = -0.5;
    dwgt[2] = 0.5;
  }
  const HermiteBasis hb(xi);
  for (int k = 0; k < 4 && !linear_kind_; ++k) {
    if (term_[k].nonlinear) continue;
    for (int s = 0; s < 4; ++s) {
      wgt[s] += hb.h[k] * term_[k].coef[s];
      dwgt[s] += hb.dh[k] * term_[k].coef[s];
    }
  }
  std::memset(P, 0, 36 * sizeof(double));
  std::memset(Pd, 0, 36 * sizeof(double));
  for (int s = 0; s < 4; ++s)
    for (int i = 0; i < 3; ++i) {
      P[i + 3 * (3 * s + i)] = wgt[s];
      Pd[i + 3 * (3 * s + i)] = dwgt[s];
    }
  for (int k = 1; k < 4; k += 2) {
    if (!term_[k].nonlinear) continue;
    const double* J = tangent_of(k).jac;
    for (int m = 0; m < 36; ++m) {
      P[m] += hb.h[k] * J[m];
      Pd[m] += hb.dh[k] * J[m];
    }
  }
}

void Segment::jacobian(double xi, double* P) const {
  double wgt[4] = {0, 0, 0, 0};
  if (linear_kind_) {
    wgt[1] = 0.5 * (1.0 - xi);
    wgt[2] = 0.5 * (1.0 + xi);
  }
  const HermiteBasis hb(xi);
  for (int k = 0; k < 4 && !linear_kind_; ++k) {
    if (term_[k].nonlinear) continue;
    for (int s = 0; s < 4; ++s) wgt[s] += hb.h[k] * term_[k].coef[s];
  }
  std::memset(P, 0, 36 * sizeof(double));
  for (int s = 0; s < 4; ++s)
    for (int i = 0; i < 3; ++i) P[i + 3 * (3 * s + i)] = wgt[s];
  for (int k = 1; k < 4; k += 2) {
    if (!term_[k].nonlinear) continue;
    const double* J = tangent_of(k).jac;
    for (int m = 0; m < 36; ++m) P[m] += hb.h[k] * J[m];
  }
}

namespace {

// out = the sum over t < n of c[stride t] terms[t].M (3x3), a pass per term
// over the 9 entries (restrict: out is none of the M, the passes vectorise).
void combine_terms(int n, const Segment::JacobianTerm* terms, const double* c, int stride,
                   double* __restrict out) {
  const double* __restrict M = terms[0].M;
  for (int e = 0; e < 9; ++e) out[e] = c[0] * M[e];
  for (int t = 1; t < n; ++t) {
    const double ct = c[stride * t];
    const double* __restrict Mt = terms[t].M;
    for (int e = 0; e < 9; ++e) out[e] += ct * Mt[e];
  }
}

}  // namespace

void Segment::combine_jacobians(int n, const JacobianTerm* terms, unsigned used,
                                double* Y) const {
  // The weights of jacobians() at each term's xi: slot s's identity block
  // wgt[s] (dwgt[s]) and end tangent k's h[k] (dh[k]).
  double ws[kMaxJacobianTerms][4], wk[kMaxJacobianTerms][2];
  for (int t = 0; t < n; ++t) {
    const JacobianTerm& term = terms[t];
    double* wgt = ws[t];
    for (int s = 0; s < 4; ++s) wgt[s] = 0.0;
    wk[t][0] = wk[t][1] = 0.0;
    if (linear_kind_) {
      wgt[1] = term.derivative ? -0.5 : 0.5 * (1.0 - term.xi);
      wgt[2] = term.derivative ? 0.5 : 0.5 * (1.0 + term.xi);
      continue;
    }
    const HermiteBasis hb(term.xi);
    const double* h = term.derivative ? hb.dh : hb.h;
    for (int k = 0; k < 4; ++k) {
      if (term_[k].nonlinear)
        wk[t][k / 2] = h[k];
      else
        for (int s = 0; s < 4; ++s) wgt[s] += h[k] * term_[k].coef[s];
    }
  }
  double* block[4] = {nullptr, nullptr, nullptr, nullptr};  // the used slots' blocks in Y
  double* y = Y;
  for (int s = 0; s < 4; ++s) {
    if (!(used & (1u << s))) continue;
    block[s] = y;
    y += 9;
    bool read = false;  // a slot no term's linear part reads: a zero block
    for (int t = 0; t < n; ++t) read = read || ws[t][s] != 0.0;
    if (read)
      combine_terms(n, terms, &ws[0][s], 4, block[s]);
    else
      for (int e = 0; e < 9; ++e) block[s][e] = 0.0;
  }
  for (int k = 1; k < 4; k += 2) {
    if (!term_[k].nonlinear) continue;
    double N[9];
    combine_terms(n, terms, &wk[0][k / 2], 2, N);
    tangent_of(k).add_product(N, block);
  }
}

namespace {

// Block (A, B) of the symmetric 9x9 Z of the node differences z_1..z_3, of
// which only the upper triangle is stored (leading dimension 9), entry
// (alpha, beta); zero outside z_1..z_3 and for (1, 3): no term couples z_1
// and z_3.
template <int A, int B>
inline double zs(const double* Z, int alpha, int beta) {
  if constexpr (A < 1 || B < 1 || A > 3 || B > 3 || A - B > 1 || B - A > 1) {
    (void)Z;
    (void)alpha;
    (void)beta;
    return 0.0;
  } else if constexpr (A < B) {
    return Z[3 * (A - 1) + alpha + 9 * (3 * (B - 1) + beta)];
  } else if constexpr (A > B) {
    return Z[3 * (B - 1) + beta + 9 * (3 * (A - 1) + alpha)];
  } else {
    return alpha <= beta ? Z[3 * (A - 1) + alpha + 9 * (3 * (A - 1) + beta)]
                         : Z[3 * (A - 1) + beta + 9 * (3 * (A - 1) + alpha)];
  }
}

// H at block (I, J) += the 3x3 block v(a, b): the whole block, and unless
// kUpper its transpose at (J, I); a diagonal block (I = J) on its upper
// triangle, mirrored unless kUpper (so that it is exactly symmetric).
template <int I, int J, bool kUpper, typename V>
inline void add_block(double* H, int ld, V v) {
  double* hij = H + 3 * I + ld * 3 * J;
  double* hji = H + 3 * J + ld * 3 * I;
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < (I == J ? b + 1 : 3); ++a) {
      const double x = v(a, b);
      hij[a + ld * b] += x;
      if (!kUpper && (I != J || a != b)) hji[b + ld * a] += x;
    }
}

// Block (I, J), I <= J, of D^T Z D (slot k moves z_k by +1 and z_k+1 by -1):
//   Z_IJ - Z_I+1,J - Z_I,J+1 + Z_I+1,J+1, added to H (add_block).
template <int I, int J, bool kUpper>
inline void add_dzd_block(const double* Z, double* H, int ld) {
  add_block<I, J, kUpper>(H, ld, [Z](int a, int b) {
    return (zs<I, J>(Z, a, b) - zs<I + 1, J>(Z, a, b)) -
           (zs<I, J + 1>(Z, a, b) - zs<I + 1, J + 1>(Z, a, b));
  });
}

template <bool kUpper>
void add_dzd(const double* Z, double* H, int ld) {
  // H_03 = Z_13 = 0
  add_dzd_block<0, 0, kUpper>(Z, H, ld);
  add_dzd_block<0, 1, kUpper>(Z, H, ld);
  add_dzd_block<0, 2, kUpper>(Z, H, ld);
  add_dzd_block<1, 1, kUpper>(Z, H, ld);
  add_dzd_block<1, 2, kUpper>(Z, H, ld);
  add_dzd_block<1, 3, kUpper>(Z, H, ld);
  add_dzd_block<2, 2, kUpper>(Z, H, ld);
  add_dzd_block<2, 3, kUpper>(Z, H, ld);
  add_dzd_block<3, 3, kUpper>(Z, H, ld);
}

}  // namespace

template <bool kChord, bool kUpper, int kLd>
void Segment::add_interior_hessians(double c1, double c3, const double* w, double* H) const {
  // Both tangents have the length L = |x3 - x2| (slots p = 1, q = 2, unit
  // chord e) and their directions on the slots (a, b, c) = (0, 1, 2) and
  // (1, 2, 3) (doc/curves.md section 9). With the parts of each tangent's
  // contraction (TangentTerm::contraction), in X:
  //   the length's parts, summed: cL (I - e e^T) on the blocks of x2 and x3
  //   (+ on (1,1), (2,2), - on (1,2)), and dL g^T + g dL^T with dL = -e on
  //   slot 1, +e on slot 2, and g = sum of both tangents' duhat^T w in X:
  //   -Gb at a, Gb - Gc at b, Gc at c (g0..g3 below);
  //   each direction's part N in X: (a,a) Nbb, (a,b) Nbc - Nbb, (a,c) -Nbc,
  //   (b,b) Nbb - Nbc - Nbc^T + Ncc, (b,c) Nbc - Ncc, (c,c) Ncc; for the
  //   chord (all three M) only M on (a,a), (c,c) and -M on (a,c) remain.
  // This is D^T Z D of add_tangent_hessians with its cancellations done.
  TangentTerm::Contraction s, t;  // start and end tangent
  tangent_[0].contraction(w, c1, s);
  tangent_[1].contraction(w, c3, t);
  const double* e = s.e;  // = t.e: the same chord of the same nodes
  const double cL = s.cL + t.cL;
  const double* sGc = kChord ? s.Gb : s.Gc;
  const double* tGc = kChord ? t.Gb : t.Gc;
  double g0[3], g1[3], g2[3], g3[3];
  for (int i = 0; i < 3; ++i) {
    g0[i] = -s.Gb[i];
    g1[i] = kChord ? -t.Gb[i] : (s.Gb[i] - sGc[i]) - t.Gb[i];
    g2[i] = kChord ? s.Gb[i] : sGc[i] + (t.Gb[i] - tGc[i]);
    g3[i] = tGc[i];
  }
  auto Q = [&](int a, int b) { return cL * ((a == b ? 1.0 : 0.0) - e[a] * e[b]); };
  if constexpr (kChord) {
    const double* M0 = s.Nbb;
    const double* M1 = t.Nbb;
    add_block<0, 0, kUpper>(H, kLd, [&](int a, int b) { return M0[a + 3 * b]; });
    add_block<0, 1, kUpper>(H, kLd, [&](int a, int b) { return -g0[a] * e[b]; });
    add_block<0, 2, kUpper>(H, kLd, [&](int a, int b) { return g0[a] * e[b] - M0[a + 3 * b]; });
    add_block<1, 1, kUpper>(H, kLd, [&](int a, int b) {
      return (M1[a + 3 * b] + Q(a, b)) - (e[a] * g1[b] + g1[a] * e[b]);
    });
    add_block<1, 2, kUpper>(
        H, kLd, [&](int a, int b) { return (g1[a] * e[b] - e[a] * g2[b]) - Q(a, b); });
    add_block<1, 3, kUpper>(H, kLd, [&](int a, int b) { return -e[a] * g3[b] - M1[a + 3 * b]; });
    add_block<2, 2, kUpper>(H, kLd, [&](int a, int b) {
      return (M0[a + 3 * b] + Q(a, b)) + (e[a] * g2[b] + g2[a] * e[b]);
    });
    add_block<2, 3, kUpper>(H, kLd, [&](int a, int b) { return e[a] * g3[b]; });
    add_block<3, 3, kUpper>(H, kLd, [&](int a, int b) { return M1[a + 3 * b]; });
  } else {
    // The directions' parts in X: the start tangent's (b, b), (b, c), (c, c)
    // on slots (1, 1), (1, 2), (2, 2) meet the end tangent's (a, a), (a, b),
    // (b, b) there.
    auto Nab = [](const TangentTerm::Contraction& c, int a, int b) {
      return c.Nbc[a + 3 * b] - c.Nbb[a + 3 * b];
    };
    auto Nbb = [](const TangentTerm::Contraction& c, int a, int b) {
      return (c.Nbb[a + 3 * b] + c.Ncc[a + 3 * b]) - (c.Nbc[a + 3 * b] + c.Nbc[b + 3 * a]);
    };
    auto Nbc = [](const TangentTerm::Contraction& c, int a, int b) {
      return c.Nbc[a + 3 * b] - c.Ncc[a + 3 * b];
    };
    add_block<0, 0, kUpper>(H, kLd, [&](int a, int b) { return s.Nbb[a + 3 * b]; });
    add_block<0, 1, kUpper>(H, kLd, [&](int a, int b) { return Nab(s, a, b) - g0[a] * e[b]; });
    add_block<0, 2, kUpper>(H, kLd, [&](int a, int b) { return g0[a] * e[b] - s.Nbc[a + 3 * b]; });
    add_block<1, 1, kUpper>(H, kLd, [&](int a, int b) {
      return (Nbb(s, a, b) + t.Nbb[a + 3 * b]) + (Q(a, b) - (e[a] * g1[b] + g1[a] * e[b]));
    });
    add_block<1, 2, kUpper>(H, kLd, [&](int a, int b) {
      return (Nbc(s, a, b) + Nab(t, a, b)) + ((g1[a] * e[b] - e[a] * g2[b]) - Q(a, b));
    });
    add_block<1, 3, kUpper>(H, kLd, [&](int a, int b) { return -e[a] * g3[b] - t.Nbc[a + 3 * b]; });
    add_block<2, 2, kUpper>(H, kLd, [&](int a, int b) {
      return (s.Ncc[a + 3 * b] + Nbb(t, a, b)) + (Q(a, b) + (e[a] * g2[b] + g2[a] * e[b]));
    });
    add_block<2, 3, kUpper>(H, kLd, [&](int a, int b) { return Nbc(t, a, b) + e[a] * g3[b]; });
    add_block<3, 3, kUpper>(H, kLd, [&](int a, int b) { return t.Ncc[a + 3 * b]; });
  }
}

void Segment::add_tangent_hessians(double c1, double c3, const double* w, double* H, int ld,
                                   bool upper) const {
  if (interior_nodal_ && (ld == 24 || ld == 12)) {
    const bool chord = tangent_[0].dir == TangentTerm::Dir::Chord;
    if (ld == 24) {  // the pair's tangent
      if (chord && upper)
        add_interior_hessians<true, true, 24>(c1, c3, w, H);
      else if (chord)
        add_interior_hessians<true, false, 24>(c1, c3, w, H);
      else if (upper)
        add_interior_hessians<false, true, 24>(c1, c3, w, H);
      else
        add_interior_hessians<false, false, 24>(c1, c3, w, H);
    } else if (chord) {  // a segment's own 12 x 12 (contracted_hessians)
      add_interior_hessians<true, false, 12>(c1, c3, w, H);
    } else {
      add_interior_hessians<false, false, 12>(c1, c3, w, H);
    }
    return;
  }
  // Both end tangents are functions of the node differences z_j = x_j -
  // x_{j-1} (j = 1..3). Their contractions are summed in z, the upper
  // triangle of a 9x9 matrix Z, and taken to X once (D^T Z D, add_dzd).
  double Z[81];
  std::memset(Z, 0, sizeof Z);
  const double coef[2] = {c1, c3};
  for (int t = 0; t < 2; ++t) {
    if (term_[1 + 2 * t].nonlinear) tangent_[t].add_contracted_hessian_z(w, coef[t], Z, 9);
  }
  if (upper)
    add_dzd<true>(Z, H, ld);
  else
    add_dzd<false>(Z, H, ld);
}

void Segment::add_contracted_hessian(double xi, const double* w, double s, double* H,
                                     int ld) const {
  if (linear_in_X()) return;
  const HermiteBasis hb(xi);
  add_tangent_hessians(s * hb.h[1], s * hb.h[3], w, H, ld, false);
}

void Segment::add_contracted_hessian_upper(double xi, const double* w, double s, double* H,
                                           int ld) const {
  if (linear_in_X()) return;
  const HermiteBasis hb(xi);
  add_tangent_hessians(s * hb.h[1], s * hb.h[3], w, H, ld, true);
}

void Segment::contracted_hessians(double xi, const double* w, double* Hx, double* Hxd) const {
  std::memset(Hx, 0, 144 * sizeof(double));
  if (Hxd) std::memset(Hxd, 0, 144 * sizeof(double));
  if (linear_in_X()) return;
  const HermiteBasis hb(xi);
  add_tangent_hessians(hb.h[1], hb.h[3], w, Hx, 12, false);
  if (Hxd) add_tangent_hessians(hb.dh[1], hb.dh[3], w, Hxd, 12, false);
  // Every term is symmetric, but D^T Z D sums (i,j) and (j,i) in different
  // orders: average the triangles so that hosts (and the documentation) can
  // rely on exact symmetry.
  for (double* H : {Hx, Hxd}) {
    if (!H) continue;
    for (int j = 0; j < 12; ++j)
      for (int i = j + 1; i < 12; ++i) {
        const double m = 0.5 * (H[i + 12 * j] + H[j + 12 * i]);
        H[i + 12 * j] = m;
        H[j + 12 * i] = m;
      }
  }
}

}  // namespace curve
}  // namespace b2b
