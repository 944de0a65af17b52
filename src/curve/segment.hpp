// One segment of a smoothed beam centreline, for every curve kind:
//
//     x(xi) = H1 P0 + H2 T0 + H3 P1 + H4 T1        (cubic Hermite, xi in [-1, 1])
//
// P0, P1 (end points) are always linear in the 12 patch coordinates X; the end
// tangents T0, T1 are either linear or a TangentTerm. build() does the
// xi-independent work once (what a closest-point iteration reuses); the
// evaluators then cost a few dozen flops per xi.
#pragma once

#include "tangent_term.hpp"

namespace b2b {
namespace curve {

// Why build() refused a patch: a b2b status code and the patch slots
// (0-based, -1 if none) of the offending element or fold.
// Two nodes coincide when their distance is below B2B_LENGTH_MIN or lost in
// the rounding of their coordinates (a few ulps of the larger one): what
// Segment::build reports as B2B_ERR_COINCIDENT.
bool points_coincide(const double* xa, const double* xb);

struct Failure {
  int status = 0;
  int slot_a = -1, slot_b = -1;
};

// Bit k set: patch slot k is read by a segment of this kind with these rules.
// Kind and rules must be valid (checked by the caller).
unsigned used_slots(int kind, int start_rule, int end_rule);

// True if the segment's end tangent at the start/end comes from the host.
bool uses_start_tangent(int kind, int start_rule);
bool uses_end_tangent(int kind, int end_rule);

class Segment {
 public:
  // X: 12 patch coordinates; unit_tangents: 6 doubles (unit host directions
  // at the first and last node), read only where a rule is B2B_END_TANGENT.
  // Inputs must already be valid (known kind/rules, finite, in range).
  // With derivatives = false only point() may be used afterwards.
  Failure build(int kind, int start_rule, int end_rule, const double* X,
                const double* unit_tangents, bool derivatives);

  // x(xi), dx/dxi, d2x/dxi2 (any pointer may be null).
  void point(double xi, double* x, double* xd, double* xdd) const;
  // x(xi) - origin, formed from the positions' offsets to base() and
  // base() - origin: when the segments lie far from the coordinates' origin
  // and origin is a node of the pair, differences of two such points keep
  // the accuracy of the inputs (about eps times the patch size, not eps
  // times the coordinates). dx/dxi, d2x/dxi2 as point().
  void point_from(const double* origin, double xi, double* x, double* xd, double* xdd) const;
  // P = dx/dX and Pd = d(dx/dxi)/dX, 3x12 column-major each.
  void jacobians(double xi, double* P, double* Pd) const;
  // P = dx/dX alone.
  void jacobian(double xi, double* P) const;
  // One term of combine_jacobians: M (3x3, column-major) times dx/dX at xi,
  // or times d(dx/dxi)/dX at xi (derivative).
  struct JacobianTerm {
    double xi;
    bool derivative;
    const double* M;
  };
  // Y = the sum over the n terms of M dx/dX (or M d(dx/dxi)/dX) on the
  // slots in `used` (used_slots() of this segment: every slot it reads
  // must be there), their 3x3 blocks one
  // after the other in slot order (3 x 3k column-major for k slots; all
  // four: the 3x12 jacobian's layout): what forming each jacobian and
  // multiplying it would give, up to rounding, at a fraction of the cost.
  // Every jacobian is a multiple of the identity per slot plus multiples of
  // the nonlinear end tangents' jacobians, so the terms' M are summed first,
  // into one 3x3 block per slot and one 3x3 factor per end tangent, and each
  // end tangent's jacobian is multiplied once (TangentTerm::add_product).
  // At most kMaxJacobianTerms terms (n >= 1).
  static constexpr int kMaxJacobianTerms = 3;
  void combine_jacobians(int n, const JacobianTerm* terms, unsigned used, double* Y) const;
  // Hx = w . d2x/dX2 and Hxd = w . d2(dx/dxi)/dX2, 12x12 column-major each,
  // exactly symmetric; Hxd may be null (not computed).
  void contracted_hessians(double xi, const double* w, double* Hx, double* Hxd) const;
  // H += s * (w . d2x/dX2): a 12x12 block with leading dimension ld,
  // symmetric up to rounding (the contact element mirrors its tangent).
  void add_contracted_hessian(double xi, const double* w, double s, double* H, int ld) const;
  // The same on the upper triangle of H only (row <= column); the entries
  // below the diagonal are not touched. For a caller that mirrors H.
  void add_contracted_hessian_upper(double xi, const double* w, double s, double* H,
                                    int ld) const;
  // Node x2, the origin of the offsets point_from works with: the best
  // origin for a pair's differences (an input, not a rounded midpoint).
  const double* base() const { return base_; }
  // The end points x(-1) and x(1) (available after build, at no cost).
  const double* start_point() const { return term_[0].value; }
  const double* end_point() const { return term_[2].value; }
  // True when the segment is linear in X (all second derivatives vanish).
  bool linear_in_X() const { return !term_[1].nonlinear && !term_[3].nonlinear; }

 private:
  struct Term {
    bool nonlinear = false;         // a tangent term, then tangent_of(k)
    double coef[4] = {0, 0, 0, 0};  // linear: value = sum_s coef[s] x_s
    double value[3] = {0, 0, 0};
    double offset[3] = {0, 0, 0};  // a position term's value minus base_
  };
  // Order of the Hermite weights: start point, start tangent, end point, end tangent.
  Term term_[4];
  // The nonlinear end tangents of terms 1 and 3 (the positions, terms 0 and
  // 2, are always linear): kept apart so that a segment carries two of
  // these large blocks, not four (a contact model builds one per segment
  // near contact: memory goes with them).
  TangentTerm tangent_[2];
  TangentTerm& tangent_of(int k) { return tangent_[k / 2]; }
  const TangentTerm& tangent_of(int k) const { return tangent_[k / 2]; }
  bool linear_kind_ = false;
  // An interior nodal segment (neighbours at both ends): both end tangents
  // are nonlinear, of the same direction rule, on the slots (0, 1, 2) and
  // (1, 2, 3), with the same length |x3 - x2| (add_interior_hessians).
  bool interior_nodal_ = false;
  // Node x2 (slot 1, read by every kind): the positions are kept as offsets
  // to it, formed at the size of the patch (see point_from).
  double base_[3] = {0, 0, 0};

  void set_linear(int k, double c0, double c1, double c2, double c3, const double* X);
  // Term k as a nonlinear end tangent sigma * |x_q - x_p| * (its direction).
  TangentTerm& set_tangent(int k, double sigma, int p, int q);
  // The terms of each kind's segment (build); the kind's end tangents at
  // interior nodes follow `dir` (nodal kinds).
  Failure build_chord(const double* X);
  Failure build_nodal(TangentTerm::Dir dir, int start_rule, int end_rule, const double* X,
                      const double* unit_tangents);
  Failure build_midpoint(int start_rule, int end_rule, const double* X,
                         const double* unit_tangents);
  // H += w . (c1 d2T0/dX2 + c3 d2T1/dX2) (the nonlinear end tangents), on
  // the whole 12x12 block or (upper) its upper triangle.
  void add_tangent_hessians(double c1, double c3, const double* w, double* H, int ld,
                            bool upper) const;
  // The same for an interior nodal segment (kLd the leading dimension of H),
  // assembled in X block by block from the tangents' parts, with no 9x9 Z
  // in between.
  template <bool kChord, bool kUpper, int kLd>
  void add_interior_hessians(double c1, double c3, const double* w, double* H) const;
};

}  // namespace curve
}  // namespace b2b
