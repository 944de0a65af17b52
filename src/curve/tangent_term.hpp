// The one nonlinear ingredient of every smoothed segment: an end tangent
//
//     T(X) = sigma * L(X) * unit(u(X)),   L = |x_q - x_p|,
//
// where X are the 12 patch coordinates, L is the length of one patch element
// and u a direction made of patch nodes:
//   Chord     u = x_c - x_a                           (Litewka's nodal tangent)
//   Weighted  u = l_bc^2 (x_b - x_a) + l_ab^2 (x_c - x_b)
//             (derivative of the chord-length parabola through a, b, c)
//   Constant  u = a host-given direction (only L varies with X).
// Value, 3x12 Jacobian and, for any vector w, the 12x12 contraction
// w . d2T/dX2 are computed in closed form (doc/curves.md sections 7-8); the
// latter in the node differences z (section 9), where it is a 6x6 matrix
// (see below).
#pragma once

namespace b2b {
namespace curve {

struct TangentTerm {
  enum class Dir { Constant, Chord, Weighted };

  // --- set-up (filled by the segment) ---
  double sigma = 0.5;
  int p = 1, q = 2;          // L = |x_q - x_p|
  Dir dir = Dir::Chord;
  int a = 0, b = 1, c = 2;   // slots of u (Chord uses a and c)
  double given[3] = {0, 0, 0};  // unit direction for Dir::Constant

  // --- results ---
  double value[3] = {0, 0, 0};
  double jac[36];            // dT/dX, 3x12 column-major (after jacobian())

  // Computes value. Returns false when u has no direction (a folded patch).
  bool evaluate(const double* X);
  // Fills jac. Call after evaluate().
  void jacobian();
  // Y += N dT/dX (N 3x3, column-major), Y the 3x12 result by slot: Y[s]
  // its 3x3 block of slot s (column-major; null for a slot T does not
  // read). N jac up to rounding, from the jacobian's parts where they are
  // cheaper (the chord's blocks are multiples of S = sigma L (I - uhat
  // uhat^T) / r and of the rank-one E = sigma uhat eL^T, so N S and N E are
  // all the products; a constant direction has E alone), else on the slots
  // jac lives on. Call after jacobian().
  void add_product(const double* N, double* const Y[4]) const;
  // The contraction w . d2T in the node differences z_j = x_j - x_{j-1}
  // (j = 1..3; T depends on X only through them):
  //   Z += s * (w . d2T/dz2) on the upper triangle (row <= column),
  // Z column-major with leading dimension ldz, the block of z_j at rows and
  // columns 3(j-1). Requires consecutive slots, as Segment sets them:
  // q = p + 1, and for Chord and Weighted b = a + 1, c = b + 1, q in {b, c}.
  // In X it is D^T Z D, D = dz/dX (Segment does that). Call after jacobian().
  void add_contracted_hessian_z(const double* w, double s, double* Z, int ldz) const;

  // The same contraction s * (w . d2T/dz2) in its parts, for a caller that
  // assembles them in X itself (Segment, on an interior nodal segment):
  //   the direction's part on the blocks (b, b), (b, c), (c, c) of z,
  //     N = Fb^T M Fb, Fb^T M Fc, Fc^T M Fc (+ the weighted cw . d2u~),
  //     for the chord (Fb = Fc = I) the one matrix M = Nbb = Nbc = Ncc;
  //   the length's part: e G_x^T on (q, x) and G_x e^T on (x, q) for x = b, c,
  //     and cL (I - e e^T) on (q, q).
  // Not for Dir::Constant (its contraction is the length's (q, q) term alone).
  struct Contraction {
    double Nbb[9], Nbc[9], Ncc[9];  // 3x3 column-major; chord: Nbb only (= M)
    double Gb[3], Gc[3];            // sigma Fb^T cw, sigma Fc^T cw (chord: Gb = Gc, Gb only)
    double cL;                      // s sigma (w . uhat) / L
    double e[3];                    // the unit chord x_q - x_p
  };
  void contraction(const double* w, double s, Contraction& c) const;

 private:
  double L_ = 0, eL_[3] = {0, 0, 0};   // element length and unit chord
  double r_ = 0, uhat_[3] = {0, 0, 0}; // |u~| and unit(u)
  // u~ = k0 * u with k0 a positive constant frozen at evaluation: unit(u~) =
  // unit(u) for all X, so derivatives of unit(u) follow from those of u~
  // while u~ stays O(1) for any mesh size (no overflow at 1e100).
  double k0_ = 1, s1_ = 0, s2_ = 0, w1_[3] = {0, 0, 0}, w2_[3] = {0, 0, 0};
  // d(u~)/dx_s as 3x3 blocks (column-major) for the slots slot_[0..n_slots_)
  // (Constant and Weighted; jacobian() writes the chord's blocks directly)
  int n_slots_ = 0, slot_[3] = {0, 0, 0};
  double du_[3][9];
};

}  // namespace curve
}  // namespace b2b
