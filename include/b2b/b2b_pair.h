/*
 * b2b contact element: the point-wise beam-to-beam contact of Wriggers and
 * Zavarise on the smoothed centreline, with its residual and exact tangent.
 * Included by <b2b/b2b.h>; do not include it on its own.
 *
 * Parameters (b2b_params)
 * -----------------------
 * An opaque handle: create, set options by key, finalize, then use it from
 * any number of threads (b2b_pair_eval only reads it). Setting an option
 * after finalize is B2B_ERR_STATE; so is evaluating with an unfinalized one.
 * Finalizing twice is harmless. An unknown key is B2B_ERR_UNKNOWN_KEY (checked
 * before the value); a value out of its range B2B_ERR_RANGE (B2B_ERR_NONFINITE
 * if not finite; an unknown "law" B2B_ERR_UNKNOWN_KIND). Getters return the
 * current value (a required option reads 0 until set).
 *
 *   key                  type  default      meaning
 *   "penalty"            real  (required)   normal penalty eps_N >= 0
 *   "law"                int   B2B_LAW_LINEAR  normal law, B2B_LAW_*
 *   "regularization_gap" real  (required for B2B_LAW_QUADRATIC) g0 > 0: the
 *                                           gap at which the force starts
 *   "parallel_angle"     real  0.5          crossing angle in degrees, in
 *                                           [0, 90), below which a pair is
 *                                           B2B_CONTACT_PARALLEL (not evaluated)
 *   "warm_start"         int   0            1: start the closest-point search
 *                                           from the history's xi, eta
 *   "max_iterations"     int   50           closest-point iterations, 1 .. 100000
 *   "friction"           real  0            Coulomb coefficient mu >= 0; 0 is
 *                                           frictionless (and costs nothing)
 *   "tangential_penalty" real  (required if friction > 0) eps_T > 0, the
 *                                           stick stiffness (force per length)
 *   "tangent"            int   B2B_TANGENT_EXACT  which tangent b2b_pair_eval
 *                                           (and the contact model) returns,
 *                                           B2B_TANGENT_* (the residual is
 *                                           the same for all):
 *     EXACT      the exact derivative of the residual (below)
 *     SYMMETRIC  its symmetric part (K + K^T)/2, for hosts with symmetric
 *                solvers (the same as EXACT without friction)
 *     MAIN       the main term only, -f_N' G G^T with G = dg/dX (what 4C calls
 *                the basic stiffness): no geometric terms, no friction part;
 *                cheapest, convergence no longer quadratic
 *     FD         central finite differences of the residual, computed inside
 *                the library (48 residual evaluations, step 1e-6 of the
 *                segments' length, the old history held fixed): a reference
 *                and a fallback, about 20x the cost of EXACT
 *   "contact_type"       int   B2B_CONTACT_TYPE_POINT  which element a contact
 *                                           model uses for a pair of segments
 *                                           (and b2b_pair_eval_line's blend):
 *     POINT      the point-wise element (b2b_pair_eval)
 *     LINE       the line-contact element (b2b_pair_eval_line), at any angle
 *     ALL_ANGLE  both, blended by the crossing angle (Line contact, below)
 *   "line_penalty"       real  (required for LINE and ALL_ANGLE, and by
 *                                           b2b_pair_eval_line) eps_L >= 0,
 *                                           the normal penalty per unit length
 *                                           of A (force per length^2)
 *   "line_tangential_penalty" real (required with friction where
 *                                           line_penalty is) eps_LT > 0, the
 *                                           stick stiffness per unit length
 *   "line_points"        int   0            integration points per segment of
 *                                           A in a contact model, 0 .. 32; 0:
 *                                           the default rule
 *                                           (b2b_pair_line_points)
 *   "line_angle"         real  5            ALL_ANGLE: below this crossing
 *                                           angle (degrees) only line contact
 *   "point_angle"        real  15           ALL_ANGLE: above it only point
 *                                           contact; between, both blended
 *                                           (parallel_angle < line_angle <
 *                                           point_angle, else finalize is
 *                                           B2B_ERR_RANGE)
 *
 * Finalize fails with B2B_ERR_STATE if a required option is missing.
 * Line-contact options set with "contact_type" POINT are kept but not
 * required (b2b_pair_eval_line then checks them).
 *
 * Normal laws (B2B_LAW_*), f_N >= 0 the compressive normal force, g the gap:
 *   LINEAR     f_N = eps_N max(0, -g)
 *   QUADRATIC  C1 regularised: f_N = eps_N (g0/2 - g) for g <= 0,
 *              eps_N (g0 - g)^2 / (2 g0) for 0 < g < g0, 0 for g >= g0
 *              (force and its slope continuous; contact starts at g = g0 > 0).
 *
 * The pair (b2b_pair_eval)
 * ------------------------
 * Two segments, A and B, each as in b2b_segment_eval: segments[0..2] = kind,
 * start_rule, end_rule of A, segments[3..5] those of B; X[24] the 24 contact
 * coordinates, A's four patch nodes then B's (x y z each); end_tangents[12]
 * A's two then B's two (may be NULL unless a rule in force is TANGENT);
 * radii[2] the cross-section radii of A and B (>= 0).
 *
 * Closest points xi, eta minimise |x_A(xi) - x_B(eta)| (safeguarded Newton
 * from the straight-chord solution, or from the history with "warm_start").
 * n = (x_A - x_B)/|x_A - x_B| points from B to A, the gap is
 * g = s |x_A - x_B| - r_A - r_B, where the sign s = -1 if n has flipped
 * against the history's previous normal (the axes passed through each other
 * within the step: they are pushed back, not pulled through), else +1, and n
 * is flipped with it.
 *
 * residual[24] is the contact contribution to the host's internal force
 * vector, the gradient of the contact potential Pi(g) with respect to X:
 * residual = -f_N dg/dX. tangent (24 x 24, column-major, leading dimension
 * ldk >= 24; NULL: not computed, which is cheaper) is its exact derivative
 * d(residual)/dX, including the change of the closest points and the second
 * derivatives of the smoothed curves; it is symmetric without friction.
 * Where the pair carries no force both are zero.
 *
 * Ownership. A contact point belongs to exactly one pair: a pair owns the
 * points with -1 <= xi < 1 (and -1 <= eta < 1); a point on the joint
 * xi = 1 belongs to the next segment (where it is xi = -1), except at the end
 * of a beam (end_rule not B2B_END_NEIGHBOUR), where the segment keeps it.
 * "On the joint" means within 1e-13 segment lengths of it, so two pairs that
 * compute the same joint point with different rounding still agree.
 *
 * History. hist_old and hist_new are host-owned arrays of
 * b2b_params_history_size() doubles: hist_old is read (a zero-filled array is
 * a valid fresh history), hist_new written (it may be the same array). To
 * commit a converged step copy hist_new into hist_old; to cut back a failed
 * step do not. The layout is private and may grow in later versions; only its
 * length is part of the ABI, and a history of the wrong length is rejected.
 *
 * Contact status (B2B_CONTACT_*), a physical outcome, not an error (the call
 * returns B2B_OK):
 *   OPEN           closest points owned by this pair, no force (gap open)
 *   ACTIVE         owned, force > 0
 *   OUTSIDE        the closest point is not this pair's: it lies on a
 *                  neighbouring segment (xi or eta outside [-1, 1), see
 *                  ownership) or beyond a beam end; no force
 *   PARALLEL       crossing angle below "parallel_angle", a singular
 *                  closest-point problem, or a cusp (a centreline whose
 *                  tangent vanishes at or next to the closest point, speed
 *                  below 1% of its chord's, e.g. a host end tangent
 *                  opposite to the chord): point-wise contact is not
 *                  defined; no force
 *   NOT_CONVERGED  the closest-point search did not converge; no force
 *   NO_NORMAL      the axes intersect exactly and there is no previous
 *                  normal in the history; no force
 * With exactly intersecting axes and a previous normal, that normal is used
 * (the tangent then omits the normal's rotation, which is unbounded there).
 *
 * info[B2B_PAIR_INFO_LEN]: see B2B_INFO_*; unused entries are zero.
 *
 * End contact (b2b_pair_eval_ends): node-to-segment and node-to-node
 * -------------------------------------------------------------------
 * Where the closest point of two centrelines is a node of one beam that the
 * segments on both sides of it point away from (a convex joint of straight
 * segments, where the beam bends towards the other one, or a beam's end),
 * every pair of the free element reports OUTSIDE, yet the beams touch there.
 * b2b_pair_eval_ends is the same element with the parameter of A (ends[0])
 * or of B (ends[1]) held at an end of its segment, -1 (its start node) or +1
 * (its end node); 0 leaves it free. With one parameter held the other
 * minimises the distance alone (node-to-segment; defined at any crossing
 * angle, so "parallel_angle" does not apply; PARALLEL only where that
 * one-dimensional problem is singular); with both held the two nodes are
 * the contact points (node-to-node). Gap, normal, normal law, friction (the
 * held parameter is the anchor, history as above), residual and exact
 * tangent are those of the free element with the held parameters constant:
 * their derivatives drop out of the linearization. A held parameter needs
 * no ownership test: which pair owns a node, and whether the node really is
 * the closest point of its beam, is the caller's decision (the contact
 * model's rule: doc/contact-element.md section 14); a free one is owned as
 * above. info[B2B_INFO_END_A], info[B2B_INFO_END_B] echo ends. ends[] other
 * than -1, 0, +1 is B2B_ERR_RANGE; ends = {0, 0} is b2b_pair_eval.
 *
 * Friction (Coulomb; Zavarise and Wriggers 2000, Litewka and Wriggers 2002)
 * -------------------------------------------------------------------------
 * With "friction" mu > 0 an active pair also carries a tangential force T,
 * the friction force that beam A exerts on beam B (B feels +T, A feels -T),
 * applied at the closest points like the normal force:
 * residual += [P_A^T T; -P_B^T T] with P = dx/dX at xi, eta.
 *   Slip measure: the anchor points are the closest points xi_n, eta_n of the
 *     last committed step (history). The tangential relative displacement of
 *     A with respect to B since then is, on the current configuration,
 *         g_T = (I - n n^T) (x_A(xi_n) - x_B(eta_n)),
 *     the tangential part of the vector between the two material points that
 *     were in contact ("finite form", doc/friction.md section 2). It is zero
 *     for any rigid motion of both beams, exact for straight beams and finite
 *     steps, and needs no derivative of the closest points beyond the first.
 *   Transport: the committed force is stored by its components in the
 *     orthonormal frame e1 = x_A,xi / |x_A,xi|, e2 = n x e1 at the contact
 *     and rebuilt in the current frame, so it stays in the tangent plane,
 *     keeps its magnitude and turns with the beams (objective). In an end
 *     contact (b2b_pair_eval_ends) a held parameter's tangent is not normal
 *     to n: e1 is then A's tangent projected onto the tangent plane,
 *     (I - n n^T) t / |(I - n n^T) t| (so a force handed over from a free
 *     pair keeps its direction), or B's where A's lies within about 6
 *     degrees of n (sin^2 below 1e-2: a tip pushed on end-on) and B's is
 *     farther from it, or the coordinate axis least aligned with n where
 *     both lie within 1e-3 rad of it (tip to tip). A node-to-node
 *     contact has no slip (both anchors are the nodes): its frame only
 *     carries a committed force over.
 *   Return mapping: T_trial = T_n + eps_T g_T; stick if |T_trial| <= mu f_N
 *     (T = T_trial), else slip: T = mu f_N T_trial / |T_trial|, with slip
 *     increment (|T_trial| - mu f_N) / eps_T along T and dissipated energy
 *     mu f_N (|T_trial| - mu f_N) / eps_T >= 0.
 *   A pair that was not active in the committed step starts in stick with
 *     T = 0 at the current closest points. A pair that is not active has no
 *     tangential force and its new history forgets the old one.
 *   The tangent is the exact derivative of this residual with the old history
 *     held fixed, and it is NOT symmetric (the slip direction couples to the
 *     normal force, and the force is transported with the frame): an active
 *     pair with mu > 0 reports info[B2B_INFO_SYMMETRIC] = 0, and the host
 *     needs a solver for non-symmetric matrices.
 *   Not modelled: rotations of the cross-sections (the axis-based contact has
 *     no rotational unknowns, so friction exerts no torque) and rolling.
 * The history of a friction parameter set is longer (query its size). Commit
 * and cut-back work as for any history: hist_old is the committed state, read
 * only; hist_new the state of this iterate, to be copied on convergence.
 *
 * Handover (b2b_pair_history_handover)
 * ------------------------------------
 * When the contact point moves across a joint of beam A (or B), the pair of
 * the neighbouring segment becomes its owner, and its old history must be the
 * committed history of the previous owner re-expressed in the new segment's
 * parameter: without it the friction force would restart from zero. The
 * function maps the anchor parameter t across the joint with the parametric
 * speeds s at the joint, t' = -1 + (t - 1) s_from / s_to (direction +1, the
 * next segment) or t' = 1 + (t + 1) s_from / s_to (direction -1), i.e. the
 * same arc length from the joint to first order, and copies the rest (the
 * normal, the force components, stick or slip). The two segments must share
 * the joint (x_from(+-1) = x_to(-+1) to 1e-10 of the sum of their chord
 * lengths, else
 * B2B_ERR_RANGE; so is a mapped parameter beyond 1e3, and nothing is
 * written). The parameter is mapped whether or not the history holds a
 * contact (without one it is the warm start's point); a fresh (all-zero)
 * history is copied unchanged. Evaluate both segments on the configuration of
 * the committed step, where the anchors were taken (doc/handover.md); a point
 * that crossed several joints is handed over once per joint.
 *
 * Line contact (b2b_pair_eval_line; doc/line-contact.md)
 * -----------------------------------------------------
 * Beams that lie (nearly) parallel touch along a line, where the point
 * element has no unique closest point (PARALLEL). The line element
 * integrates along segment A: at n_points Gauss-Legendre points xi_i
 * (weights w_i) the point x_A(xi_i) is projected orthogonally onto B's
 * smoothed curve, eta_i minimising |x_A(xi_i) - x_B(eta)| (the end
 * contact's one-sided problem with xi held at xi_i), with its own
 * sign-tracked normal n_i and gap g_i = |x_A - x_B| - r_A - r_B, and the
 * normal law per unit length of A ("line_penalty" in place of "penalty";
 * the same "law" and "regularization_gap"). The potential is
 *     Pi = sum_i w_i J_i pi(g_i),   J_i = |x_A,xi(xi_i)| (current length),
 * and the residual its gradient,
 *     residual = sum_i w_i (J_i r_i + pi(g_i) dJ_i/dX),
 * r_i = -f_i dg_i/dX the point residual of integration point i; the
 * tangent its exact derivative (the projections' motion and the curves'
 * second derivatives included), symmetric without friction. A point whose
 * eta_i lies outside [-1, 1) (ownership as for the point element) belongs
 * to the pair of B's neighbouring segment: summed over the segments of B,
 * every point of A is counted once, and on a C1 kind its projection moves
 * continuously from one segment to the next (no gap at joints; at joints
 * of the linear kind a point may have no projection or two, see
 * doc/line-contact.md). The points are interior, so joints of A need no
 * rule.
 * Friction: each integration point has its own history and the point
 * element's return mapping, with "line_tangential_penalty"; its anchor on
 * A is xi_i itself (a material point of A), on B its committed eta, read
 * at B's surface: g_T = (I - n n^T)(x_A(xi_i) - x_B(eta_n) - r_B m), m the
 * committed normal made normal to B's current tangent at eta_n (unit), so
 * that a point sliding round B's axis (a rope round a beam) slips by the
 * surface's arc; a rigid rotation of both beams by phi within a step reads
 * as a slip below r_B phi^2, and a rotation of B about its own axis as a
 * slip of r_B times its angle (an axis-based beam has no such rotation). A force per unit length,
 * integrated like the normal one; the dissipation likewise. Handover of a point's history to B's next segment is
 * b2b_pair_history_handover on its slot (beam 1).
 * Every angle ("contact_type" ALL_ANGLE): with s = sin^2 of the crossing
 * angle and s1, s2 those of "line_angle" and "point_angle", the point
 * weight is lambda(s) = u^2 (3 - 2u), u = (s - s1)/(s2 - s1) clipped to
 * [0, 1] (C1 in the angle); the point element (on the free closest
 * points) is weighted by lambda of its own angle and each integration
 * point by 1 - lambda of its local angle (t_A(xi_i), t_B(eta_i)):
 *     residual = lambda_P r_P + sum_i (1 - lambda_i) R_i.
 * The force is continuous in the angle; in the blending range the
 * residual is no potential's gradient, and the exact tangent includes
 * r_P dlambda_P/dX - R_i dlambda_i/dX (not symmetric there). Outside it,
 * it is the pure point or the pure line element. With another
 * contact_type b2b_pair_eval_line evaluates the line element alone.
 * The "tangent" option applies: SYMMETRIC symmetrizes the sum; MAIN sums
 * the points' main terms w_i J_i (1 - lambda_i) (-f_i' G_i G_i^T) (and the
 * point element's); FD differences the whole residual.
 * History: (n_points + 1) consecutive histories of
 * b2b_params_history_size doubles: the point element's first (written by
 * ALL_ANGLE, else kept fresh), then integration point i's. hist_new may
 * not be hist_old here (nothing is written on failure, as always).
 * line_info[B2B_LINE_INFO_LEN]: see B2B_LINE_INFO_*; point_info (NULL, or
 * 32 x n_points): each integration point's info as b2b_pair_eval's, with
 * force, energy, tangential force and dissipation per unit length, unweighted.
 * n_points: 1 .. B2B_LINE_POINTS_MAX (b2b_pair_line_points gives the
 * default); a hist_len other than (n_points + 1) times the history size is
 * B2B_ERR_SIZE; params without "line_penalty" (or, with friction,
 * "line_tangential_penalty") B2B_ERR_STATE.
 *
 * Bad input: B2B_ERR_NULL, B2B_ERR_STATE (params not finalized),
 * B2B_ERR_UNKNOWN_KIND, B2B_ERR_NONFINITE (coordinates, tangents, radii,
 * history), B2B_ERR_RANGE (a radius outside [0, B2B_COORD_MAX], a coordinate
 * beyond B2B_COORD_MAX, a history not written by b2b: a foreign format tag, a
 * "fresh" history that is not all zeros, a flag, normal or friction state out
 * of range, a closest-point parameter |xi| or |eta| beyond 1e3, a tangential
 * force in a history that is not in contact; and a force, energy or tangent
 * that would overflow, from a huge penalty times a deep penetration or a huge
 * regularization gap, whatever the contact status), B2B_ERR_SIZE (history length, ldk < 24), and each
 * segment's own bad input exactly as for b2b_segment_eval (unknown kind or
 * rule, zero or non-finite end tangent, a midpoint segment at both beam ends,
 * B2B_ERR_COINCIDENT, B2B_ERR_FOLDED). The message names the beam (A or B).
 */
#ifndef B2B_PAIR_H
#define B2B_PAIR_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct b2b_params b2b_params;

/* Normal laws. Values are fixed; new laws are appended. */
enum { B2B_LAW_LINEAR = 0, B2B_LAW_QUADRATIC = 1 };
#define B2B_LAW_COUNT 2 /* number of laws, 0 .. B2B_LAW_COUNT - 1; grows with them */

/* Contact status of a pair. Values are fixed. */
enum {
  B2B_CONTACT_OPEN = 0,
  B2B_CONTACT_ACTIVE = 1,
  B2B_CONTACT_OUTSIDE = 2,
  B2B_CONTACT_PARALLEL = 3,
  B2B_CONTACT_NOT_CONVERGED = 4,
  B2B_CONTACT_NO_NORMAL = 5
};

/* Entries of the info array of b2b_pair_eval. Values are fixed. */
enum {
  B2B_INFO_XI = 0,              /* closest-point parameter on A */
  B2B_INFO_ETA = 1,             /* closest-point parameter on B */
  B2B_INFO_POINT_A = 2,         /* x_A(xi), 3 entries */
  B2B_INFO_POINT_B = 5,         /* x_B(eta), 3 entries */
  B2B_INFO_NORMAL = 8,          /* unit normal from B to A (sign-tracked), 3 entries */
  B2B_INFO_GAP = 11,            /* gap g */
  B2B_INFO_NORMAL_FORCE = 12,   /* f_N >= 0 */
  B2B_INFO_ENERGY = 13,         /* contact potential Pi(g) */
  B2B_INFO_ANGLE = 14,          /* crossing angle of the tangents, degrees in [0, 90] */
  B2B_INFO_ITERATIONS = 15,     /* closest-point iterations used */
  B2B_INFO_SYMMETRIC = 16,      /* 1 if the tangent is symmetric, 0 if not */
  B2B_INFO_TANGENTIAL_FORCE = 17, /* friction force T on B by A (A feels -T), 3 entries */
  B2B_INFO_SLIP = 20,           /* slip increment of A relative to B in this step, 3 entries
                                   (zero in stick) */
  B2B_INFO_FRICTION_STATE = 23, /* B2B_FRICTION_* */
  B2B_INFO_DISSIPATION = 24,    /* energy dissipated by slip in this step, >= 0 */
  B2B_INFO_END_A = 25,          /* end contact: A's parameter held at this end of its
                                   segment, -1 or +1 (a node of A); 0: free */
  B2B_INFO_END_B = 26,          /* the same for B's parameter */
  B2B_INFO_LINE_POINTS = 27     /* a contact model's line contact (b2b_model.h): its
                                   integration points carrying force; 0 for a point
                                   contact and in b2b_pair_eval */
};
#define B2B_PAIR_INFO_LEN 32 /* entries 28..31 are reserved (written as 0) */

/* Tangent options ("tangent"). Values are fixed. */
enum {
  B2B_TANGENT_EXACT = 0,
  B2B_TANGENT_SYMMETRIC = 1,
  B2B_TANGENT_MAIN = 2,
  B2B_TANGENT_FD = 3
};

/* Contact types ("contact_type"). Values are fixed. */
enum {
  B2B_CONTACT_TYPE_POINT = 0,
  B2B_CONTACT_TYPE_LINE = 1,
  B2B_CONTACT_TYPE_ALL_ANGLE = 2
};

/* Integration points of the line element: at most this many per segment. */
#define B2B_LINE_POINTS_MAX 32

/* Entries of line_info of b2b_pair_eval_line. Values are fixed. */
enum {
  B2B_LINE_INFO_POINTS = 0,        /* integration points n_points */
  B2B_LINE_INFO_ACTIVE_POINTS = 1, /* integration points carrying force (weight > 0) */
  B2B_LINE_INFO_OWNED_POINTS = 2,  /* points whose projection this pair owns (open or active) */
  B2B_LINE_INFO_NORMAL_FORCE = 3,  /* integrated normal force (line part weighted, plus
                                      the point part's weighted f_N) */
  B2B_LINE_INFO_ENERGY = 4,        /* contact potential (weighted parts) */
  B2B_LINE_INFO_DISSIPATION = 5,   /* dissipation of the step (weighted parts) */
  B2B_LINE_INFO_MIN_GAP = 6,       /* smallest gap of the owned points (and of the point
                                      part where it is owned); DBL_MAX if none */
  B2B_LINE_INFO_SYMMETRIC = 7,     /* 1 if the tangent is symmetric */
  B2B_LINE_INFO_STICK_POINTS = 8,  /* active points sticking */
  B2B_LINE_INFO_SLIP_POINTS = 9,   /* active points slipping */
  B2B_LINE_INFO_LENGTH = 10,       /* sum w_i J_i: the current length of segment A */
  B2B_LINE_INFO_POINT_WEIGHT = 11, /* ALL_ANGLE: lambda_P of the point element, else 0 */
  B2B_LINE_INFO_POINT_STATUS = 12, /* ALL_ANGLE: the point element's B2B_CONTACT_*, else -1 */
  B2B_LINE_INFO_POINT_FORCE = 13,  /* ALL_ANGLE: lambda_P f_N of the point element */
  B2B_LINE_INFO_POINT_FRICTION_STATE = 14 /* ALL_ANGLE: the point element's B2B_FRICTION_*
                                             where it carries force, else 0 */
};
#define B2B_LINE_INFO_LEN 16 /* entry 15 is reserved (written as 0) */

/* Friction state of a pair (info[B2B_INFO_FRICTION_STATE]). Values are fixed. */
enum { B2B_FRICTION_NONE = 0, B2B_FRICTION_STICK = 1, B2B_FRICTION_SLIP = 2 };
#define B2B_PAIR_NDOF 24

B2B_EXPORT int b2b_params_create(b2b_params **params, char *errmsg, int errmsg_len);
/* Frees the handle and sets *params to NULL; NULL or *params == NULL is a no-op. */
B2B_EXPORT int b2b_params_destroy(b2b_params **params);
B2B_EXPORT int b2b_params_set_real(b2b_params *params, const char *key, double value,
                                   char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_params_set_int(b2b_params *params, const char *key, int value,
                                  char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_params_get_real(const b2b_params *params, const char *key, double *value,
                                   char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_params_get_int(const b2b_params *params, const char *key, int *value,
                                  char *errmsg, int errmsg_len);
/* Checks the options together and makes the handle read-only. */
B2B_EXPORT int b2b_params_finalize(b2b_params *params, char *errmsg, int errmsg_len);
/* Number of doubles of a pair history for this (finalized) parameter set. */
B2B_EXPORT int b2b_params_history_size(const b2b_params *params, int *n, char *errmsg,
                                       int errmsg_len);

/* Evaluates one contact pair (see above). */
B2B_EXPORT int b2b_pair_eval(const b2b_params *params, const int segments[6],
                             const double X[24], const double end_tangents[12],
                             const double radii[2], const double *hist_old, double *hist_new,
                             int hist_len, int *contact_status, double info[32],
                             double residual[24], double *tangent, int ldk, char *errmsg,
                             int errmsg_len);

/* b2b_pair_eval with parameters held at segment ends (see End contact above):
 * ends[2] for A and B, each -1, 0 or +1. */
B2B_EXPORT int b2b_pair_eval_ends(const b2b_params *params, const int segments[6],
                                  const double X[24], const double end_tangents[12],
                                  const double radii[2], const int ends[2],
                                  const double *hist_old, double *hist_new, int hist_len,
                                  int *contact_status, double info[32], double residual[24],
                                  double *tangent, int ldk, char *errmsg, int errmsg_len);

/* The line-contact element (see Line contact above): n_points integration
 * points along A; hist_old, hist_new: (n_points + 1) * history size doubles
 * (hist_len); point_info: NULL or 32 * n_points doubles. */
B2B_EXPORT int b2b_pair_eval_line(const b2b_params *params, const int segments[6],
                                  const double X[24], const double end_tangents[12],
                                  const double radii[2], int n_points, const double *hist_old,
                                  double *hist_new, int hist_len, int *contact_status,
                                  double line_info[16], double *point_info,
                                  double residual[24], double *tangent, int ldk, char *errmsg,
                                  int errmsg_len);

/* The integration points of a segment of (current chord) length `length`
 * between beams of radii radius_a and radius_b: "line_points" if it is set
 * (> 0), else the default rule 3 + ceil(length / (radius_a + radius_b)),
 * within 4 .. 16 (16 for zero radii): about one point per contact width
 * and a degree-7 rule at least. length, radii >= 0 and finite. */
B2B_EXPORT int b2b_pair_line_points(const b2b_params *params, double length, double radius_a,
                                    double radius_b, int *n_points, char *errmsg,
                                    int errmsg_len);

/* Re-expresses a committed pair history for the neighbouring segment of one
 * beam (see Handover above). beam: 0 (A) or 1 (B), the beam whose segment
 * changes; direction: +1 if `to` follows `from` along the beam, -1 if it
 * precedes it. from_segment / to_segment: kind, start_rule, end_rule;
 * from_X / to_X: their 12 patch coordinates; *_end_tangents as in
 * b2b_segment_eval (may be NULL unless a rule is TANGENT). hist_to may be
 * hist_from. Bad input as for b2b_pair_eval, B2B_ERR_UNKNOWN_KIND for a beam
 * other than 0, 1 or a direction other than +1, -1. */
B2B_EXPORT int b2b_pair_history_handover(const b2b_params *params, int beam, int direction,
                                         const int from_segment[3], const double from_X[12],
                                         const double from_end_tangents[6],
                                         const int to_segment[3], const double to_X[12],
                                         const double to_end_tangents[6],
                                         const double *hist_from, double *hist_to,
                                         int hist_len, char *errmsg, int errmsg_len);

#ifdef __cplusplus
}
#endif

#endif /* B2B_PAIR_H */
