/*
 * b2b smoothed beam centreline: one segment of a beam's axis and its
 * derivatives. Included by <b2b/b2b.h>; do not include it on its own.
 *
 * Segments and patches
 * --------------------
 * A beam is a chain of n nodes, open or closed (a ring). Its smoothed axis is
 * cut into segments, each parametrised by xi in [-1, 1] in the direction of
 * increasing node numbers. A segment depends on a patch of up to four nodes,
 * x1, x2, x3, x4, passed as 12 doubles (node after node, x y z each: a 3x4
 * column-major matrix). b2b_beam_segment_count() and b2b_beam_segment_patch()
 * tell which beam nodes go into which patch slot; slots a kind does not read
 * may hold anything (they are never read, not even for the NaN check).
 *
 * Curve kinds (B2B_CURVE_*)
 * -------------------------
 *  LINEAR                 the straight chord from x2 to x3 (Wriggers and
 *                         Zavarise 1997). Slots x1, x4 unused. Not smooth at
 *                         nodes; second derivatives are zero.
 *  HERMITE_MIDPOINT       Litewka 2007: the cubic Hermite from the midpoint of
 *                         element x1-x2 to the midpoint of element x2-x3, end
 *                         tangents along the element chords, dx/dxi(-1) =
 *                         (x2 - x1)/2 and dx/dxi(1) = (x3 - x2)/2 (so the
 *                         cubic is the parabola with control points
 *                         m12, x2, m23, linear in the nodes). One segment per
 *                         node, centred on x2; slot x4 unused. It cuts the
 *                         corner at x2: it does not pass through the nodes.
 *  HERMITE_NODAL          Litewka's node-preserving curve (doc/curves.md
 *                         section 3.3; doc/bibliography.md entry 5): the
 *                         cubic Hermite from x2 to x3 with
 *                         dx/dxi(-1) = l23 (x3 - x1)/(2 l13) and
 *                         dx/dxi(1) = l23 (x4 - x2)/(2 l24).
 *  HERMITE_NODAL_WEIGHTED as HERMITE_NODAL, but the unit tangent at a node is
 *                         that of the parabola through the node and its two
 *                         neighbours with chord-length parameter:
 *                         t2 ~ l23^2 (x2 - x1) + l12^2 (x3 - x2). Same patch,
 *                         still node-preserving, and as accurate on
 *                         non-uniform meshes as on uniform ones (fourth order
 *                         on a circle, third on a general space curve;
 *                         doc/curves.md section 6), where HERMITE_NODAL drops
 *                         to second order. Not Litewka's published method.
 *
 * All kinds are C1 in position and unit tangent across segment joints
 * (except LINEAR, which is only C0); the nodal kinds are C1 in the chord-length
 * parameter and G1 in xi. xi outside [-1, 1] is valid: the cubic extends.
 *
 * Beam ends (B2B_END_*)
 * ---------------------
 * start_rule applies where the beam starts at the segment's first node, so
 * the slot before it is missing; end_rule where the beam ends at its last
 * node, so the slot after it is missing:
 *                         first node  missing slot   last node  missing slot
 *   LINEAR                (rules do not change the chord, which needs no
 *                         neighbours; they still say where the beam ends,
 *                         which decides who owns a contact on the end joint,
 *                         see b2b_pair.h)
 *   HERMITE_NODAL[_W.]    x2          x1             x3         x4
 *   HERMITE_MIDPOINT      x2          x1             x2         x3
 * (a midpoint segment at a beam end is a half element: from x2 to the
 * midpoint of x2-x3, or from the midpoint of x1-x2 to x2.)
 *
 *  NEIGHBOUR  the slot holds the real neighbour node (interior, closed beams).
 *  REFLECT    the default at a beam end: a ghost node reflected through the
 *             end node, so the end tangent lies along the end element's chord
 *             (nodal kinds: dx/dxi = (x3 - x2)/2; midpoint kind: a straight
 *             half element).
 *  TANGENT    the host gives the end tangent's direction (e.g. from its beam
 *             element's nodal rotation) in end_tangents: 3 doubles for the
 *             first node, then 3 for the last node, each pointing towards
 *             increasing node numbers; only its direction is used, its length
 *             must be non-zero. The magnitude follows the kind's rule (l23/2
 *             for the nodal kinds, half the half element's chord for the
 *             midpoint kind). The given direction is a constant for the
 *             derivatives: it does not depend on the patch coordinates.
 *
 * Outputs of b2b_segment_eval (any output pointer may be NULL: not computed)
 * -----------------------------------------------------------------------
 *  x    [9]    x(xi), dx/dxi, d2x/dxi2: a 3x3 column-major matrix.
 *  dx   [72]   first derivatives with respect to the 12 patch coordinates X:
 *              dx[i + 3*a]      = d x_i / d X_a,
 *              dx[36 + i + 3*a] = d (dx_i/dxi) / d X_a      (i < 3, a < 12),
 *              i.e. two 3x12 column-major matrices, P = dx/dX then dP/dxi.
 *  d2x  [864]  second derivatives with respect to X:
 *              d2x[i + 3*(a + 12*b)]       = d2 x_i / dX_a dX_b,
 *              d2x[432 + i + 3*(a + 12*b)] = d2 (dx_i/dxi) / dX_a dX_b.
 *              Symmetric in a, b. Zero for LINEAR and HERMITE_MIDPOINT
 *              (except at an end with a host TANGENT), which are linear in X.
 * Derivatives with respect to unused slots are zero; at a REFLECT end the
 * ghost node's dependence is already folded into the real nodes.
 *
 * Bad input: B2B_ERR_NULL (patch, or end_tangents when a rule in force is
 * TANGENT), B2B_ERR_UNKNOWN_KIND (kind or rule), B2B_ERR_NONFINITE (a used
 * coordinate, a used end tangent, or xi), B2B_ERR_RANGE (a coordinate beyond
 * B2B_COORD_MAX, a zero end tangent, or a finite xi so far outside [-1, 1]
 * that a requested output would overflow), B2B_ERR_COINCIDENT (an element of the
 * patch has zero length), B2B_ERR_FOLDED (l13 = 0 or l24 = 0: the nodes on
 * both sides of x2 or x3 coincide, so the tangent has no direction).
 */
#ifndef B2B_CURVE_H
#define B2B_CURVE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Curve kinds. Values are fixed; new kinds are appended. */
enum {
  B2B_CURVE_LINEAR = 0,
  B2B_CURVE_HERMITE_MIDPOINT = 1,
  B2B_CURVE_HERMITE_NODAL = 2,
  B2B_CURVE_HERMITE_NODAL_WEIGHTED = 3
};
#define B2B_CURVE_KIND_COUNT 4 /* number of kinds, 0 .. B2B_CURVE_KIND_COUNT - 1; grows with them */

/* Rules at beam ends. Values are fixed. */
enum {
  B2B_END_NEIGHBOUR = 0,
  B2B_END_REFLECT = 1,
  B2B_END_TANGENT = 2
};

/* Fixed array lengths of the curve functions. */
#define B2B_PATCH_NODES 4
#define B2B_PATCH_LEN 12   /* patch coordinates: 3 x 4 */
#define B2B_POINT_LEN 9    /* x, dx/dxi, d2x/dxi2: 3 x 3 */
#define B2B_DPOINT_LEN 72  /* dx/dX, d(dx/dxi)/dX: 2 x (3 x 12) */
#define B2B_D2POINT_LEN 864 /* d2x/dX2, d2(dx/dxi)/dX2: 2 x (3 x 12 x 12) */

/* Evaluate one segment of a smoothed centreline at xi (see above). */
B2B_EXPORT int b2b_segment_eval(int kind, int start_rule, int end_rule,
                                const double patch[12],
                                const double end_tangents[6], double xi,
                                double x[9], double dx[72], double d2x[864],
                                char *errmsg, int errmsg_len);

/* Number of segments of a beam of n_nodes nodes (closed: 0 open, 1 ring):
 * LINEAR and the nodal kinds have n_nodes - 1 segments on an open beam
 * (segment s from node s to node s + 1) and n_nodes on a ring; the midpoint
 * kind has n_nodes segments on both (segment s centred on node s).
 * An open beam needs n_nodes >= 2, a ring n_nodes >= 3 (B2B_ERR_RANGE). */
B2B_EXPORT int b2b_beam_segment_count(int kind, int n_nodes, int closed,
                                      int *n_segments, char *errmsg,
                                      int errmsg_len);

/* The patch of segment `segment` (0-based) of such a beam: nodes[k] is the
 * beam node (0-based) that goes into patch slot k, or -1 where the slot is
 * missing or not read by the kind; *start_rule and *end_rule are
 * B2B_END_REFLECT where the beam starts or ends at that segment and
 * B2B_END_NEIGHBOUR elsewhere (a host may replace REFLECT by TANGENT). */
B2B_EXPORT int b2b_beam_segment_patch(int kind, int n_nodes, int closed,
                                      int segment, int nodes[4],
                                      int *start_rule, int *end_rule,
                                      char *errmsg, int errmsg_len);

#ifdef __cplusplus
}
#endif

#endif /* B2B_CURVE_H */
