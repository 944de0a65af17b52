/* The forward-mode AD reference of the contact element, for C tests and the
 * cost study (test-support library b2b_ad; test-only code, not part of
 * libb2b). tests/ad/ad_pair.hpp says what it computes and how.
 *
 * b2b_ad_pair_eval has b2b_pair_eval's arguments and outputs (b2b_pair.h):
 * the same contact status, info (except info[B2B_INFO_ITERATIONS], its own
 * count), new history, residual and, if tangent is not NULL, the tangent of
 * the parameter set's "tangent" option:
 *   EXACT      the derivative of the residual by forward-mode AD (dual
 *              numbers seeded on the 24 coordinates), the committed history
 *              held fixed;
 *   SYMMETRIC  (K + K^T)/2 of that where it is not symmetric (friction,
 *              intersecting axes), else K;
 *   MAIN       -f_N' G G^T with G = dg/dX;
 *   FD         the AD tangent (info[B2B_INFO_SYMMETRIC] = 0, as the library's).
 * The residual is computed with the double instantiation of the same code.
 * Where the axes intersect within the tolerance band and the history's
 * normal is used (doc/contact-element.md 12) the AD tangent is the exact
 * derivative of the computed residual, which has no -f_N' G G^T term: the
 * library keeps that term on purpose, so the two differ by exactly it there.
 *
 * Bad input: B2B_ERR_NULL, B2B_ERR_SIZE (history length, ldk < 24),
 * B2B_ERR_UNKNOWN_KIND (kind or rule; a kind this reference does not know),
 * B2B_ERR_NONFINITE (a used coordinate, end tangent, radius, history),
 * B2B_ERR_RANGE (a midpoint segment at both beam ends, a zero end tangent),
 * B2B_ERR_COINCIDENT / B2B_ERR_FOLDED (a zero element length or direction),
 * B2B_ERR_INTERNAL (an exception). The message names the problem. It checks
 * less than the library: it is a reference for valid input. */
#ifndef B2B_AD_H
#define B2B_AD_H

#include <b2b/b2b.h>

#ifdef __cplusplus
extern "C" {
#endif

int b2b_ad_pair_eval(const b2b_params *params, const int segments[6], const double X[24],
                     const double end_tangents[12], const double radii[2],
                     const double *hist_old, double *hist_new, int hist_len,
                     int *contact_status, double info[32], double residual[24],
                     double *tangent, int ldk, char *errmsg, int errmsg_len);

/* Flags of b2b_ad_pair_eval_ex. */
enum {
  /* A deliberately wrong reference, for checking the checks: the closest
   * points are held fixed in the derivative (dxi/dX = deta/dX = 0). */
  B2B_AD_FREEZE_CLOSEST_POINTS = 1,
  /* The reference in long double (x87 extended precision on x86-64: a
   * 64-bit significand), to tell which of two double results is off by how
   * much: a diagnostic, about 10x slower. */
  B2B_AD_LONG_DOUBLE = 2
};

/* b2b_ad_pair_eval with flags, two more outputs and a diagnostic input
 * (each may be NULL): energy_gradient[24], dPi/dX of the contact potential
 * by AD (the total derivative, closest points moving: without friction it
 * must equal the residual, which is computed from the curves' first
 * derivatives instead); value_mismatch, the largest |value part of the dual
 * evaluation - the double evaluation| over the residual's entries (0: the
 * two instantiations agree bit for bit); closest_points[2], xi and eta to
 * use instead of the reference's own search (e.g. the library's, from its
 * info), with their derivatives from the implicit function as usual. */
int b2b_ad_pair_eval_ex(const b2b_params *params, const int segments[6], const double X[24],
                        const double end_tangents[12], const double radii[2],
                        const double *hist_old, double *hist_new, int hist_len, int flags,
                        int *contact_status, double info[32], double residual[24],
                        double *tangent, int ldk, double energy_gradient[24],
                        double *value_mismatch, const double closest_points[2], char *errmsg,
                        int errmsg_len);

/* The end contact of b2b_pair_eval_ends (b2b_pair.h, "End contact"):
 * b2b_ad_pair_eval_ex's outputs with the parameter of A (ends[0]) and/or B
 * (ends[1]) held at -1 or +1 (0: free). The held parameter is a constant of
 * the reference: its own 1-D search (or none, node to node), the scalar
 * Newton steps move only the free parameter, so the held one's derivative is
 * zero by construction; no crossing-angle threshold (PARALLEL only for a
 * singular 1-D problem or a cusp); no ownership test for a held parameter.
 * ends = {0, 0} is b2b_ad_pair_eval_ex. */
int b2b_ad_pair_eval_ends(const b2b_params *params, const int segments[6], const double X[24],
                          const double end_tangents[12], const double radii[2],
                          const int ends[2], const double *hist_old, double *hist_new,
                          int hist_len, int flags, int *contact_status, double info[32],
                          double residual[24], double *tangent, int ldk,
                          double energy_gradient[24], char *errmsg, int errmsg_len);

/* The line-contact element of b2b_pair_eval_line (b2b_pair.h, "Line
 * contact"; doc/line-contact.md): the same arguments and outputs (status,
 * line_info, point_info (may be NULL), new histories, residual, tangent of
 * the "tangent" option), point_info's iteration counts its own.
 * tests/ad/ad_line.hpp says what it computes: n Gauss-Legendre points of
 * its own, each the point element above with A's parameter held at xi_i
 * (the line penalties, its own history), weighted by w_i |x_A,xi(xi_i)|
 * with that length element in the scalar type; with contact_type
 * ALL_ANGLE the blend with the point element (slot 0 of the histories),
 * its weights in the scalar type. The tangent is the AD derivative of the
 * residual as written (EXACT; SYMMETRIC its symmetric part; MAIN the
 * weighted main terms; FD the AD tangent, flagged non-symmetric).
 * The pair's status, which b2b_pair.h does not spell out: ACTIVE if a part
 * carries force, else OPEN if a part is owned (open or active), else the
 * line points' common status, OUTSIDE where they differ.
 * Bad input as b2b_ad_pair_eval, and B2B_ERR_RANGE for n_points outside
 * 1 .. B2B_LINE_POINTS_MAX, B2B_ERR_SIZE for hist_len other than
 * (n_points + 1) times the history size. */
int b2b_ad_pair_eval_line(const b2b_params *params, const int segments[6], const double X[24],
                          const double end_tangents[12], const double radii[2], int n_points,
                          const double *hist_old, double *hist_new, int hist_len,
                          int *contact_status, double line_info[16], double *point_info,
                          double residual[24], double *tangent, int ldk, char *errmsg,
                          int errmsg_len);

/* b2b_ad_pair_eval_line with flags (B2B_AD_LONG_DOUBLE; FREEZE holds every
 * projection, and the point element's closest points, in the derivative)
 * and two more outputs (each may be NULL): energy_gradient[24], the AD
 * gradient of the line part's potential sum_i w_i J_i pi(g_i) (without
 * friction and the blend it must equal the residual); value_mismatch, as
 * for b2b_ad_pair_eval_ex. */
int b2b_ad_pair_eval_line_ex(const b2b_params *params, const int segments[6],
                             const double X[24], const double end_tangents[12],
                             const double radii[2], int n_points, const double *hist_old,
                             double *hist_new, int hist_len, int flags, int *contact_status,
                             double line_info[16], double *point_info, double residual[24],
                             double *tangent, int ldk, double energy_gradient[24],
                             double *value_mismatch, char *errmsg, int errmsg_len);

/* The curve kinds the reference implements: kinds 0 .. count-1. */
int b2b_ad_curve_kind_count(void);

#ifdef __cplusplus
}
#endif

#endif /* B2B_AD_H */
