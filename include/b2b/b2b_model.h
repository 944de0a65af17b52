/*
 * b2b contact model: the bookkeeping around the contact element. A host hands
 * b2b all its beams once; every Newton iteration it passes the current nodal
 * coordinates and gets back every active contact element, with search,
 * active set, ownership at joints, handover of a contact (and its friction
 * history) from one segment to the next, commit / cut-back and restart done
 * for it. Included by <b2b/b2b.h>; do not include it on its own.
 *
 * Life cycle
 * ----------
 *   b2b_model_create
 *   b2b_model_add_beam (once per beam), b2b_model_set_group_pair (per pair of
 *   groups that may touch), b2b_model_set_self_contact, b2b_model_set_real /
 *   _set_int (options)
 *   b2b_model_finalize(n_nodes)
 *   per load step:  per Newton iteration:  b2b_model_update(x), or
 *                                          b2b_model_update_xu(x, u)
 *                                          b2b_model_contact_count / _get_contact,
 *                                          or the assembly helpers
 *                   converged: b2b_model_commit     failed: b2b_model_revert
 *   b2b_model_save / b2b_model_restore (restart), b2b_model_stats
 *   b2b_model_destroy
 * Calls in the wrong state are B2B_ERR_STATE (update before finalize, commit
 * or get_contact before an update, add_beam after finalize, ...). A failed
 * call leaves the model as it was.
 *
 * Beams
 * -----
 * A beam is a chain of the host's node numbers (0-based in C), open or closed
 * (a ring: the last node joins the first; do not repeat it), with a circular
 * cross-section radius r > 0, a curve kind (B2B_CURVE_*) and a contact group
 * (an int >= 0; a label: no array is indexed by it, so any numbering the
 * host likes, e.g. from 1 in Fortran; messages print it as given). Its
 * segments are those of b2b_beam_segment_count /
 * b2b_beam_segment_patch; open ends use B2B_END_REFLECT. A beam needs at
 * least 2 nodes (3 if closed); a node may not appear twice in one beam.
 * Beams may share host nodes (a frame): segments whose patches share a host
 * node are never paired, on one beam or across beams.
 *
 * Groups
 * ------
 * Two beams are searched for contact only if their groups form a pair given a
 * finalized b2b_params by b2b_model_set_group_pair (the model copies it; the
 * host may destroy its handle). Different beams of one group g touch if the
 * pair (g, g) is set. Between committed steps (before the first update, or
 * right after a commit or revert) a pair's parameter set may be replaced by
 * one of the same history length (penalty continuation); a different length
 * is B2B_ERR_SIZE.
 *
 * Self-contact (b2b_model_set_self_contact) is off by default. When on, two
 * segments of the same beam are paired only if they share no host node and
 * the arc length between them, measured along the beam's chords in the
 * configuration of the first update that is committed (precisely: the first
 * update after finalize measures them; a revert before any commit forgets
 * them, and the next update measures again; a restore brings the restart
 * buffer's), exceeds the exclusion length (default,
 * exclusion_length < 0: 4 r, longer than the pi r of the tightest fold a
 * solid rod of radius r can make, so neighbours on a bent beam are never
 * read as contact). It needs the group pair (g, g) of the beam's group g.
 *
 * Options (b2b_model_set_real / _set_int; at any time after create; each
 * says what a change after finalize does: nothing the model keeps goes stale)
 *   "search_margin"  real  default: the largest radius of the model's beams.
 *                          The Verlet skin s of the broad phase (> 0).
 *                          After finalize: the next update searches again
 *                          with the new margin.
 *   "threads"        int   0 (default): as many as OpenMP offers; n >= 1:
 *                          at most n threads for this model's updates.
 *                          After finalize: from the next update on (results
 *                          do not depend on it).
 *   "max_handover_hops" int  16: segments a contact may travel in one
 *                          update (along both beams together), 1 .. 1000.
 *                          After finalize: from the next update on (no
 *                          result of an update is kept that depends on it
 *                          other than through the histories it committed).
 *   "message_base"   int   0: beam, segment, node and contact numbers in
 *                          messages are 0-based (C); 1: 1-based (the Fortran
 *                          module sets it, so its callers read their own
 *                          numbers). Results are always 0-based in C.
 *                          After finalize: from the next message on.
 *   "max_candidates" int   100000000 (default), >= 1: the most pairs of
 *                          segments one broad-phase search may keep (its
 *                          memory: about 12 bytes per pair). A search that
 *                          finds more stops and the update fails with
 *                          B2B_ERR_SIZE, its message naming the option; the
 *                          model is unchanged (a dense scene, all nodes on
 *                          one point, or a search margin far too large).
 *                          After finalize: the next update searches again
 *                          under the new bound.
 *
 * Update (b2b_model_update)
 * -------------------------
 * Memory: an update that cannot allocate what it needs (on any of its
 * threads) fails with B2B_ERR_NOMEM and leaves the model unchanged.
 * x holds the current coordinates of all host nodes: node k at
 * x[ldx*k + 0..2] (a 3 x n_cols column-major array with leading dimension
 * ldx >= 3); n_cols >= n_nodes. Only nodes of beams are read (each must be
 * finite and within B2B_COORD_MAX). The current coordinates, not the
 * reference ones: FEAP's x(ndm, numnp) is the reference geometry, and a
 * host that keeps reference coordinates and displacements apart, as FEAP
 * does (x(ndm, numnp), u(ndf, numnp)), calls b2b_model_update_xu instead.
 *
 * b2b_model_update_xu(x, ldx, u, ldu, n_cols, ...): the same update with the
 * current coordinates x + u, node k's reference coordinates at
 * x[ldx*k + 0..2] and its displacements at u[ldu*k + 0..2] (ldx, ldu >= 3:
 * FEAP's x(ndm, numnp) with ndm = 3 and u(ndf, numnp) with ndf >= 3, whose
 * rotations or other dofs beyond the first 3 are not read); n_cols >=
 * n_nodes for both. Each sum is formed as the coordinate is read (one
 * rounding, x[.] + u[.]), so the result is b2b_model_update on the array
 * x + u bit for bit. Checks as b2b_model_update: a non-finite or too large
 * x is B2B_ERR_NONFINITE / B2B_ERR_RANGE ("coordinate"), a non-finite u
 * B2B_ERR_NONFINITE naming the node and axis ("displacement"), a sum beyond
 * B2B_COORD_MAX B2B_ERR_RANGE ("current coordinate x + u").
 *   Elements: before any search, every element of every beam is checked in
 *     O(n): two consecutive nodes of a beam that coincide (a zero-length
 *     element, wherever it is) are B2B_ERR_COINCIDENT, naming the beam and
 *     segment; so a scene with all nodes on one point costs O(n), not the
 *     O(n^2) search of its pairs.
 *   Broad phase: boxes around each segment (its Hermite control polygon,
 *     which contains the curve) grown by r + g0/2 + 4s/3, in Boost.Geometry's
 *     packed R-tree when b2b was built with the Boost headers, else in b2b's
 *     bounding-volume hierarchy (median splits along the longest extent;
 *     both O(n log n), no global box or cell size to set; the same
 *     candidates either way);
 *     rebuilt only when some node has moved more than s/2
 *     since the last build, so that most iterations reuse the candidates.
 *     g0: the largest regularization gap of the group pairs (0 without the
 *     quadratic law).
 *   Narrow phase: every candidate whose current boxes lie within
 *     r_A + r_B + g0 + s of each other is evaluated by the contact element
 *     (b2b_pair_eval's mathematics) on segments built once per update;
 *     the rest are open ("far").
 *   Ownership at joints is the element's rule, so a contact on a joint, or
 *     where nodes of both beams coincide, is counted once.
 *   End contacts: a pair whose closest point lies beyond its segments
 *     (OUTSIDE) holds the node it points to, if the segment starts there
 *     (at a beam start, or at a joint of two LINEAR segments, where the
 *     tangent turns) or ends an open beam there, and the node is the
 *     closest point of its beam to first order (the distance grows into the
 *     segment and into the one before the node): a convex joint of straight
 *     segments or a beam end touching another beam is then an active
 *     contact (node-to-segment, or node-to-node), evaluated as
 *     b2b_pair_eval_ends, with friction and handover like any other;
 *     info[B2B_INFO_END_A] / _END_B name the held node
 *     (doc/contact-element.md section 14).
 *   Line contact: a group pair whose parameter set has "contact_type" LINE or
 *     ALL_ANGLE evaluates each pair of its segments with b2b_pair_eval_line's
 *     element (A the pair's lower segment in model order; integration along
 *     A). A pair's count of integration points is "line_points", or (0) the
 *     default rule on A's chord when the pair is first evaluated; it keeps
 *     that count while it has a history. Each integration point is owned by
 *     the pair of the segment of B it projects onto, so summed over the
 *     pairs every point of A is counted once. A point whose projection moves
 *     to B's next segment takes its committed history with it (its friction
 *     force and normal; doc/line-contact.md section 9). A line pair is one
 *     contact: info holds its integrated normal force, energy and
 *     dissipation, its smallest gap, B2B_INFO_LINE_POINTS (points carrying
 *     force), SLIP if a point slips (else STICK if one sticks), and xi, eta,
 *     the points, normal and angle of its deepest point carrying force; its
 *     tangential force and slip entries are 0. The stats count line contacts
 *     (B2B_COUNT_LINE) and their points (B2B_TOTAL_LINE_POINTS). A pair's
 *     parameter set may be replaced only by one of the same contact kind
 *     (point, or line/all-angle; else B2B_ERR_SIZE). The crossing check
 *     (below) gives each point of a line pair new since the commit the
 *     normal of its projection on the committed geometry. ALL_ANGLE's
 *     point part follows its point across one joint of either beam per
 *     update, as a point contact's does; it has no end contact (yet).
 *   Handover: a contact that was active at the last commit and whose point
 *     now lies outside its pair (the element reports xi or eta outside
 *     [-1, 1)) moves with its committed history to the neighbouring segment
 *     of that beam (b2b_pair_history_handover on the committed geometry),
 *     and on along both beams until a pair owns the point (at most
 *     "max_handover_hops" hops; across a ring's seam too). A pair that held
 *     its own committed contact keeps its own history.
 *   Crossing since the last commit (tunnelling): once there is a commit,
 *     each segment's box is swept from its committed to its current
 *     position (their union) in the broad phase and the near test, and a
 *     pair without a committed normal whose segments moved since the commit
 *     by more than its present axis distance is checked against the normal
 *     of its closest points on the committed geometry: on the other side
 *     now, it is evaluated with that normal, an active contact with its
 *     signed gap (pushed back, not pulled through). An active contact whose
 *     gap is below -(r_A + r_B) (its axes passed through each other) is
 *     counted in counts[B2B_COUNT_CROSSED]: within Newton's iterations the
 *     penalty pushes it back; a converged update that still has one is a
 *     step too large for the contact to be resolved, and the host cuts back
 *     (b2b_model_revert, a smaller step). Before the first commit there is
 *     no configuration to check against: a host whose first step moves the
 *     beams commits the initial configuration first (update, commit).
 *   The active contacts are listed in a fixed order (by pair), the same for
 *   any number of threads, with outputs bit for bit the same.
 * want_tangent = 0 skips the tangents (cheaper); get_contact then has none.
 *
 * Contacts (b2b_model_contact_count, b2b_model_get_contact; k = 0 .. count-1)
 *   nodes[8]   host node numbers of A's four patch slots, then B's; -1 where
 *              a slot holds no node (unused by the kind, or a missing node at a
 *              beam end, whose reflected ghost is folded into the real nodes)
 *   pair[4]    beam A, segment A, beam B, segment B (0-based)
 *   info[32]   as b2b_pair_eval (B2B_INFO_*)
 *   residual[24], tangent (24 x 24, leading dimension ldk >= 24): the
 *              element arrays on the 24 coordinates of nodes[] (rows and
 *              columns of -1 slots are zero). Any output may be NULL.
 *
 * Assembly (the translational dofs of the host's nodes)
 *   Sign: the residual is the contact contribution to the host's internal
 *   force vector, the gradient of the contact potential with respect to the
 *   coordinates (b2b_pair.h: it pushes the beams apart, so on a node pressed
 *   against another beam it points towards that beam, as an internal force
 *   does), and the tangent its derivative, to be added to the host's
 *   stiffness as it is. A host whose Newton right-hand side is
 *   F_int - F_ext adds both as they are (scale 1, the unscaled functions);
 *   a host whose right-hand side is F_ext - F_int (FEAP's, and most
 *   residual-form codes') adds the residual with scale -1 and the tangent
 *   with scale 1: the _scaled functions add scale * (the contacts' arrays)
 *   (scale = 1 gives the unscaled result bit for bit, scale = -1 exactly its
 *   negative; a non-finite scale is B2B_ERR_NONFINITE, nothing added).
 *   eq: an int array eq[ldeq*k + i] (i = 0, 1, 2 for x, y, z of node k),
 *   ldeq >= 3 (so an id(6, numnp) of a 6-dof beam code works as is): the
 *   host's equation numbers, numbered from eq_base (> INT_MIN, else
 *   B2B_ERR_RANGE; 0 for C style, 1 for
 *   Fortran style); an entry below eq_base is a constrained dof and skipped.
 *   n_eq: the number of equations (the length of f, the order of K); an
 *   equation number beyond it is B2B_ERR_RANGE.
 *   add_residual:        f[e - eq_base] += the contacts' residuals
 *   add_tangent_dense:   K(e_r, e_c) += ..., K column-major, ldk >= n_eq
 *   add_tangent_banded:  LAPACK general band storage as dgbsv wants it:
 *                        K(i, j) goes to AB[kl + ku + i - j + ldab*j]
 *                        (0-based), ldab >= 2 kl + ku + 1 (computed in 64
 *                        bits: kl and ku whose band needs more than an int
 *                        ldab are B2B_ERR_SIZE); an entry outside the band
 *                        is B2B_ERR_RANGE (nothing added)
 *   tangent_coo:         the nonzero entries (row, col, value) in the same
 *                        numbering (duplicates are to be summed). With
 *                        rows == NULL only *nnz is set (the size query);
 *                        else capacity must be >= that count.
 *   add_tangent_profile: FEAP's profile (skyline) storage, described below.
 *
 * Sparsity: contact couples dofs that no element of the host connects: the
 *   nodes of two segments that touch, on two different beams (or far apart
 *   on one beam), with friction in a non-symmetric block. So the contact
 *   tangent does not fit a profile, band or CSR structure computed from the
 *   host's element connectivity, and its pattern changes as contacts close,
 *   open and slide on to other segments. b2b_model_tangent_profile gives
 *   the pattern of the last update (every pair of unconstrained dofs of an
 *   active contact, also where a value is 0; no tangent needed):
 *     heights[j] (n_eq ints, j = 0 .. n_eq-1: equation j + eq_base):
 *       j - (the smallest row i <= j with (i, j) or (j, i) coupled), 0 if
 *       none: FEAP's column heights of the contacts alone, the input of its
 *       pointer sums (jp(1) = 0, jp(j) = jp(j-1) + height(j)); the profile
 *       is symmetric in structure (al and au share jp)
 *     *kl, *ku: the largest r - c and c - r of a coupled entry (r, c): the
 *       band dgbsv needs (0, 0 without contacts)
 *   (any of the three may be NULL). A host merges them with its own
 *   (height = max(host's, contacts'); kl, ku likewise), after EVERY update:
 *   when the pattern has grown it re-sizes its structure and re-factors
 *   (a band or profile solver refactors every iteration anyway; a sparse
 *   direct solver redoes its symbolic analysis), else the assembly helpers
 *   refuse the entries outside it with B2B_ERR_RANGE, adding nothing. To
 *   keep re-sizing rare, a host may size for the contacts' pattern plus
 *   what its own elements need once, and grow only. tangent_coo's size
 *   query and entries give the same pattern for a CSR or COO host.
 *
 * Profile (skyline) storage, FEAP's: jp (n_eq ints) the pointer array as
 *   FEAP's profil/nwprof leave it, passed as is from C or Fortran: jp for
 *   the first equation is 0, and each next one adds that column's height
 *   (between 0 and the number of equations before it; else B2B_ERR_RANGE
 *   naming the equation). In 0-based C terms, for 0 <= i < j < n_eq:
 *     K(j, j) is added to ad[j]
 *     K(i, j) to au[jp[j] - j + i]  (column j of the upper triangle, rows
 *                                    top down, its last entry K(j-1, j) at
 *                                    au[jp[j] - 1]),
 *     K(j, i) to al[jp[j] - j + i]  (row j of the lower triangle, where its
 *                                    transpose is in au)
 *   (Fortran, 1-based: ad(j), au(jp(j) - j + i + 1), al(jp(j) - j + i + 1),
 *   as FEAP's dasble adds them). al = NULL adds no lower triangle: for a
 *   host with a symmetric profile solver, which then gets only the upper
 *   triangle of a tangent that friction makes non-symmetric (info
 *   B2B_INFO_SYMMETRIC = 0); pass al with friction. au and al hold jp of
 *   the last equation doubles (not checked: the library cannot see their
 *   length; the Fortran wrapper checks it). An entry of a contact outside
 *   the profile (i < j - height(j)) is B2B_ERR_RANGE naming both equations,
 *   with nothing added.
 *
 * Prescribed dofs: the assembly helpers skip constrained equations (eq <
 *   eq_base): rows and columns. A host that prescribes a displacement
 *   increment du_c on constrained dofs (a support moved by a load step)
 *   needs the coupling of the free dofs to them, K_fc du_c, which it would
 *   otherwise never see: b2b_model_add_constrained_product adds
 *     f[e - eq_base] += scale * sum_c K(e, c) du_c
 *   over every free row e and constrained column c of every contact, du
 *   given per host node like the coordinates (node k's at du[ldu*k +
 *   0..2], ldu >= 3, n_cols >= n_nodes; only the entries of the contacts'
 *   constrained dofs are read, each must be finite: else B2B_ERR_NONFINITE
 *   naming the node and axis). The host's correction of the first
 *   iteration of a step with prescribed increments: rhs_free -= K_fc du_c,
 *   i.e. scale -1 with a right-hand side F_ext - F_int (the contact part;
 *   its own elements' part as it does for them), then the free dofs solve
 *   K_ff du_f = rhs_free, and the next update sees x + u with both.
 *
 * Commit, revert, restart
 *   commit: the state of the last update becomes the committed one (its
 *     histories, its coordinates, the dissipation of the step added to the
 *     total). revert: back to the last commit (a cut-back), as if the
 *     updates since had never been made. save: the committed state into a
 *     caller-owned byte buffer of b2b_model_save_size bytes; restore: into a
 *     finalized model built with the same n_nodes, beams (with their
 *     self-contact settings) and group pairs with the same parameters as
 *     at save time (every parameter of every set: a buffer saved before a
 *     penalty continuation restores into a model with the old set only).
 *     B2B_ERR_RANGE for a truncated, corrupted, foreign or crafted buffer,
 *     with the model unchanged: restore checks every field against the
 *     model (sizes, indices, every double finite and in its range, every
 *     pair one this model would form, its group pair, its history), not
 *     only the checksum. A restored model continues bit for bit as the
 *     original.
 *
 * Stats (b2b_model_stats): counts[B2B_MODEL_COUNTS_LEN] (B2B_COUNT_*) and
 * totals[B2B_MODEL_TOTALS_LEN] (B2B_TOTAL_*) of the last update; unused
 * entries are zero. Like the contacts they exist only while an update has
 * results: before the first update, after a revert and after a restore,
 * b2b_model_stats is B2B_ERR_STATE (never the values of a reverted update).
 *
 * Threads: a model is not shared between host threads without a lock (one
 * model per host thread, each with its own beams, is fine). Inside one model
 * the update runs its narrow phase on "threads" OpenMP threads (when built
 * with OpenMP). Other functions are thread-safe on distinct models.
 *
 * Bad input: B2B_ERR_NULL, B2B_ERR_STATE (wrong call order, a group pair
 * without parameters for self-contact, no group pair at all at finalize, an
 * unfinalized b2b_params), B2B_ERR_RANGE (a node number out of range or
 * repeated within a beam, a radius <= 0 or beyond B2B_COORD_MAX, a group < 0,
 * a coordinate beyond B2B_COORD_MAX, an equation number beyond n_eq, a
 * restore buffer; in an update, a contact whose force, energy or tangent
 * overflows, or whose terms make the model's totals overflow: the model is
 * then unchanged), B2B_ERR_NONFINITE (radius, coordinates, option values),
 * B2B_ERR_SIZE (a beam of too few nodes, ldx < 3, n_cols < n_nodes, ldeq < 3,
 * ldu, ldk, ldab, capacity, a replacement parameter set of another history
 * length, a restore size < 0, more than 2^29 segments at finalize, more
 * broad-phase pairs than
 * "max_candidates"), B2B_ERR_NOMEM (memory exhausted, in any thread), B2B_ERR_UNKNOWN_KIND (curve kind), B2B_ERR_UNKNOWN_KEY, and a
 * segment's B2B_ERR_COINCIDENT / B2B_ERR_FOLDED. Messages name the beam,
 * segment, host node or group.
 */
#ifndef B2B_MODEL_H
#define B2B_MODEL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct b2b_model b2b_model;

/* Entries of counts[] of b2b_model_stats. Values are fixed. */
enum {
  B2B_COUNT_CANDIDATES = 0,     /* pairs from the broad phase */
  B2B_COUNT_EVALUATED = 1,      /* pairs evaluated by the element (near pairs + handovers) */
  B2B_COUNT_ACTIVE = 2,         /* active contacts */
  B2B_COUNT_OPEN = 3,           /* evaluated, owned, no force */
  B2B_COUNT_OUTSIDE = 4,        /* evaluated, point on another pair (no end contact either) */
  B2B_COUNT_PARALLEL = 5,
  B2B_COUNT_NOT_CONVERGED = 6,
  B2B_COUNT_NO_NORMAL = 7,
  B2B_COUNT_FAR = 8,            /* candidates not evaluated: boxes apart */
  B2B_COUNT_SEARCH_BUILDS = 9,  /* broad-phase builds since finalize */
  B2B_COUNT_HANDOVERS = 10,     /* handover hops in the last update */
  B2B_COUNT_LOST = 11,          /* committed contacts not found again (beam end, hops) */
  B2B_COUNT_STICK = 12,         /* active contacts sticking */
  B2B_COUNT_SLIP = 13,          /* active contacts slipping */
  B2B_COUNT_CROSSED = 14,       /* active contacts whose axes passed through each other
                                   (gap below -(r_A + r_B)): cut back (see Update) */
  B2B_COUNT_LINE = 15           /* active contacts that are line contacts (Line contact);
                                   ACTIVE - LINE are point contacts */
};
#define B2B_MODEL_COUNTS_LEN 16

/* Entries of totals[] of b2b_model_stats. Values are fixed. Each is defined
 * after every update: the sums are 0 when nothing is active. */
enum {
  B2B_TOTAL_ENERGY = 0,            /* contact potential of the active contacts */
  B2B_TOTAL_DISSIPATION_STEP = 1,  /* frictional dissipation of the last update's step */
  B2B_TOTAL_DISSIPATION = 2,       /* committed total + the step's */
  B2B_TOTAL_NORMAL_FORCE = 3,      /* sum of f_N over the active contacts */
  B2B_TOTAL_MIN_GAP = 4,           /* smallest gap of the pairs that own a closest point
                                      (active or open); DBL_MAX when there is none
                                      (counts ACTIVE + OPEN = 0): nothing is near */
  B2B_TOTAL_LINE_POINTS = 5        /* integration points carrying force, summed over the
                                      line contacts (a count, exact in a double) */
};
#define B2B_MODEL_TOTALS_LEN 8

B2B_EXPORT int b2b_model_create(b2b_model **model, char *errmsg, int errmsg_len);
/* Frees the model and sets *model to NULL; NULL or *model == NULL is a no-op. */
B2B_EXPORT int b2b_model_destroy(b2b_model **model);

/* Adds a beam; *beam receives its index (0, 1, ...). */
B2B_EXPORT int b2b_model_add_beam(b2b_model *model, const int *nodes, int n_nodes, int closed,
                                  double radius, int kind, int group, int *beam, char *errmsg,
                                  int errmsg_len);
/* Groups ga and gb (either order) touch with this finalized parameter set. */
B2B_EXPORT int b2b_model_set_group_pair(b2b_model *model, int ga, int gb,
                                        const b2b_params *params, char *errmsg,
                                        int errmsg_len);
/* Self-contact of one beam: on (1) or off (0); exclusion_length < 0 for the
 * default 4 r. Before finalize. */
B2B_EXPORT int b2b_model_set_self_contact(b2b_model *model, int beam, int on,
                                          double exclusion_length, char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_model_set_real(b2b_model *model, const char *key, double value, char *errmsg,
                                  int errmsg_len);
B2B_EXPORT int b2b_model_set_int(b2b_model *model, const char *key, int value, char *errmsg,
                                 int errmsg_len);
/* Builds segments, patches and neighbour tables; node numbers must be < n_nodes.
 * Memory goes with the beams' nodes, not with n_nodes (a table of n_nodes ints
 * only while that is at most about 4 times the beams' nodes). */
B2B_EXPORT int b2b_model_finalize(b2b_model *model, int n_nodes, char *errmsg, int errmsg_len);

B2B_EXPORT int b2b_model_update(b2b_model *model, const double *x, int ldx, int n_cols,
                                int want_tangent, char *errmsg, int errmsg_len);
/* Update from reference coordinates x and displacements u: current x + u. */
B2B_EXPORT int b2b_model_update_xu(b2b_model *model, const double *x, int ldx, const double *u,
                                   int ldu, int n_cols, int want_tangent, char *errmsg,
                                   int errmsg_len);

B2B_EXPORT int b2b_model_contact_count(const b2b_model *model, int *n, char *errmsg,
                                       int errmsg_len);
B2B_EXPORT int b2b_model_get_contact(const b2b_model *model, int k, int nodes[8], int pair[4],
                                     double info[32], double residual[24], double *tangent,
                                     int ldk, char *errmsg, int errmsg_len);

B2B_EXPORT int b2b_model_add_residual(const b2b_model *model, const int *eq, int ldeq,
                                      int eq_base, int n_eq, double *f, char *errmsg,
                                      int errmsg_len);
B2B_EXPORT int b2b_model_add_tangent_dense(const b2b_model *model, const int *eq, int ldeq,
                                           int eq_base, int n_eq, double *K, int ldk,
                                           char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_model_add_tangent_banded(const b2b_model *model, const int *eq, int ldeq,
                                            int eq_base, int n_eq, int kl, int ku, double *AB,
                                            int ldab, char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_model_tangent_coo(const b2b_model *model, const int *eq, int ldeq,
                                     int eq_base, int n_eq, int *nnz, int *rows, int *cols,
                                     double *values, int capacity, char *errmsg,
                                     int errmsg_len);
/* scale * (the contacts' residual / tangent): see Assembly, Sign. */
B2B_EXPORT int b2b_model_add_residual_scaled(const b2b_model *model, const int *eq, int ldeq,
                                             int eq_base, int n_eq, double scale, double *f,
                                             char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_model_add_tangent_dense_scaled(const b2b_model *model, const int *eq,
                                                  int ldeq, int eq_base, int n_eq, double scale,
                                                  double *K, int ldk, char *errmsg,
                                                  int errmsg_len);
B2B_EXPORT int b2b_model_add_tangent_banded_scaled(const b2b_model *model, const int *eq,
                                                   int ldeq, int eq_base, int n_eq, int kl,
                                                   int ku, double scale, double *AB, int ldab,
                                                   char *errmsg, int errmsg_len);
/* The contacts' pattern: FEAP column heights and band widths (Sparsity). */
B2B_EXPORT int b2b_model_tangent_profile(const b2b_model *model, const int *eq, int ldeq,
                                         int eq_base, int n_eq, int *heights, int *kl, int *ku,
                                         char *errmsg, int errmsg_len);
/* scale * tangent into FEAP's profile storage ad, au, al (al may be NULL). */
B2B_EXPORT int b2b_model_add_tangent_profile(const b2b_model *model, const int *eq, int ldeq,
                                             int eq_base, int n_eq, double scale,
                                             const int *jp, double *ad, double *au, double *al,
                                             char *errmsg, int errmsg_len);
/* f += scale * K(free, constrained) du_c (Prescribed dofs). */
B2B_EXPORT int b2b_model_add_constrained_product(const b2b_model *model, const int *eq,
                                                 int ldeq, int eq_base, int n_eq,
                                                 const double *du, int ldu, int n_cols,
                                                 double scale, double *f, char *errmsg,
                                                 int errmsg_len);

B2B_EXPORT int b2b_model_commit(b2b_model *model, char *errmsg, int errmsg_len);
B2B_EXPORT int b2b_model_revert(b2b_model *model, char *errmsg, int errmsg_len);

/* Bytes b2b_model_save needs for the committed state now (int64: may exceed 2^31). */
B2B_EXPORT int b2b_model_save_size(const b2b_model *model, int64_t *size, char *errmsg,
                                   int errmsg_len);
B2B_EXPORT int b2b_model_save(const b2b_model *model, void *buffer, int64_t size, char *errmsg,
                              int errmsg_len);
B2B_EXPORT int b2b_model_restore(b2b_model *model, const void *buffer, int64_t size,
                                 char *errmsg, int errmsg_len);

B2B_EXPORT int b2b_model_stats(const b2b_model *model, int counts[16], double totals[8],
                               char *errmsg, int errmsg_len);

/*
 * Interpenetration audit (b2b_model_audit)
 * ----------------------------------------
 * For the configuration of the last update: every pair of segments that may
 * touch (their groups form a pair, they share no host node, on one beam only
 * with self-contact on) whose surfaces overlap, r_A + r_B - (centreline
 * distance) > tolerance * min(r_A, r_B), but that carries no force (no active
 * contact on it, nor on the pair across a joint where its closest point
 * lies). Detection is independent of the update's active set: its own search
 * (a uniform hash grid over the segments' boxes grown by their radii) and its
 * own distance (sampled, then projected Newton in [-1, 1]^2). Each finding:
 *   pairs[4k .. 4k+3]  beam A, segment A, beam B, segment B (0-based; A the
 *                      lower segment in model order), findings in that order
 *   overlap[k]         r_A + r_B - centreline distance (> 0)
 *   reasons[k]         B2B_AUDIT_*, the first that applies in this order:
 *     EXCLUDED_SELF    one beam, within its self-contact exclusion length
 *     NEVER_EVALUATED  not among the last update's broad-phase candidates
 *     CROSSED          the centrelines passed through each other since the
 *                      last commit (the separation at the closest points
 *                      points against the committed one)
 *     PARALLEL         crossing angle below the group pair's parallel_angle
 *     OUTSIDE_BOTH     the closest point is a joint or a beam end (the
 *                      segments on both sides of it point away: a convex
 *                      joint of straight segments)
 *     OTHER_RANK       (a rank's model of a distributed one) the closest
 *                      point is a joint, and a pair across it belongs to
 *                      another rank, whose contact may carry the overlap
 *                      (this model cannot see it): the host asks that rank
 *     OTHER            none of these (the element found no force)
 * A host runs it after the converged update of a step and before
 * b2b_model_commit (after the commit the committed configuration is the
 * current one, so CROSSED cannot be told), and cuts the step back or stops
 * when n_found > 0. tolerance: >= 0, relative to the smaller radius (e.g.
 * 0.01: overlaps under 1% of the radius are not reported).
 * With pairs, overlap and reasons all NULL only *n_found is set (the size
 * query); else all three must be given, with room for capacity findings:
 * capacity < the count is B2B_ERR_SIZE (nothing written; the message gives
 * the count). B2B_ERR_STATE before an update (or after revert/restore),
 * B2B_ERR_NONFINITE / B2B_ERR_RANGE for a NaN, infinite or negative
 * tolerance. Costs well under an update (doc/guide-model.md, "Interpenetration audit").
 */
enum {
  B2B_AUDIT_OTHER = 0,
  B2B_AUDIT_PARALLEL = 1,
  B2B_AUDIT_OUTSIDE_BOTH = 2,
  B2B_AUDIT_NEVER_EVALUATED = 3,
  B2B_AUDIT_EXCLUDED_SELF = 4,
  B2B_AUDIT_CROSSED = 5,
  B2B_AUDIT_OTHER_RANK = 6 /* ABI 1.4, distributed models: the closest point is on a
                              joint and a pair across it is evaluated by another rank
                              (whose contact may carry the overlap: ask it) */
};

B2B_EXPORT int b2b_model_audit(const b2b_model *model, double tolerance, int *n_found,
                               int *pairs, double *overlap, int *reasons, int capacity,
                               char *errmsg, int errmsg_len);

/*
 * Distributed models (ABI 1.4; doc/distributed.md)
 * -------------------------------------------------
 * For a host whose mesh is split over MPI ranks. b2b does no communication:
 * each rank builds a model of its own segments and of the ghost segments it
 * needs, and the host exchanges the ghosts' coordinates and the migrating
 * contacts (below) itself.
 *
 * Global ids. Every segment has a global id (global beam, segment within
 * that beam), the same on every rank. A local beam is a piece of a global
 * beam (b2b_model_set_beam_global); its local segment s is segment
 * first_segment + s of the global beam. Beams are added in increasing
 * global-beam order, pieces of one global beam in increasing segment order
 * and not overlapping: the local order of segments is then the global
 * order restricted to the model, and every order-dependent result (the
 * orientation A/B of a pair, the order of the contacts, sums) is that of
 * a single model holding everything.
 *
 * Ownership. A pair of segments is computed by exactly one rank: the rank
 * that owns the segment with the smaller global id (lexicographic on
 * (global beam, segment)). A model holds its own segments and ghosts
 * (b2b_model_set_ghost_segments: owned by another rank); it evaluates
 * exactly the pairs whose smaller segment is its own and whose other
 * segment is present and not padding. So, summed over the ranks, each pair
 * is evaluated once, its contact listed once and assembled once.
 *
 * Cuts and padding. Where a piece ends but its global beam goes on (a cut,
 * start_cut / end_cut), the piece's first / last segment is padding: its
 * patch would need the node beyond the cut, so it only lends its nodes to
 * its neighbour's patch (a Hermite segment reads one node beyond each of its
 * ends) and is never paired. A padding segment must be a ghost (finalize
 * says so otherwise): a piece reaches one segment beyond the segments it
 * needs. No end contact is held at a cut. A closed beam cannot be cut.
 *
 * Ghost depth. A rank's ghosts are every segment of another rank that can
 * come within contact reach of one of its own segments before the next
 * repartition: r_A + r_B + g0 + the search margin + how far a node may move
 * (doc/distributed.md), plus one padding segment beyond each cut.
 *
 * Not supported: self-contact between two pieces of one global beam (the
 * segments of one global beam in different local beams are never paired;
 * self-contact within a piece works), line-contact histories across a
 * partition (a line pair's integration points take over no history from a
 * pair another rank owns; they start fresh), a cut closed beam.
 *
 * Stats, audit and crossing count per rank: B2B_COUNT_ACTIVE, OPEN,
 * OUTSIDE, ..., CROSSED, LOST, HANDOVERS and the totals count this model's
 * own pairs (the host sums them over the ranks; MIN_GAP: the smallest);
 * CANDIDATES, FAR and SEARCH_BUILDS are this model's search's (not
 * additive). b2b_model_audit reports only pairs this model evaluates.
 *
 * Migration. A committed contact whose handover (the walk of its point from
 * segment to segment, see Update) reaches a pair this model does not
 * evaluate is "migrating": not lost (not in B2B_COUNT_LOST), not assembled
 * here. The host packs it and sends it to the rank that owns its target
 * pair, which unpacks it: there it serves as the committed history of the
 * target pair, exactly as the handed-over history serves in a single model
 * (evaluated with it; if the point is not there either, the walk goes on
 * from there). A walk that reaches a pair whose smaller segment is this
 * model's own but whose other segment is padding is lost (counted): the
 * ghost layer is too thin there.
 *
 * Host protocol in one Newton iteration (doc/distributed.md):
 *   1. every rank: b2b_model_update;
 *   2. every rank: for k < b2b_model_migration_count: migration_info,
 *      migration_pack, send to the owner of target (the rank owning the
 *      smaller of target's two segments);
 *   3. every rank: b2b_model_migration_unpack of each buffer it received,
 *      then b2b_model_migration_unpack(model, NULL, 0, &changed) (the end
 *      of the round: drops the received contacts that no rank sent again
 *      since the last update);
 *   4. if any rank's changed is 1 (MPI_Allreduce, MPI_LOR), every rank
 *      updates again with the same coordinates and goes to 2 (a contact
 *      crossing one partition boundary in a step needs one extra update;
 *      each repetition carries contacts one hop further, so it ends);
 *   5. assemble: each rank its own contacts, with the host's global
 *      equation numbers (eq holds them for the rank's local nodes).
 * Received contacts serve in every update until the next commit (which
 * keeps their results, as for any contact) or revert (which drops them).
 *
 * Identity of a migrating contact: the committed contact it comes from
 * (its source pair, in global ids). Unpacking a contact of the same source
 * again replaces the one received before (its walk may have reached another
 * pair since); *changed = 1 when this changed the model's received set (a
 * new source, or another target, history or hop count).
 */

/* Local beam `beam` is a piece of global beam `global_beam` (>= 0, the
 * host's numbering, the same on every rank); its first local segment is
 * segment `first_segment` (>= 0) of the global beam. start_cut / end_cut (0
 * or 1): the local beam's first / last node is not an end of the global
 * beam but a cut (the beam goes on, on another rank): no end contact there,
 * and the segment at a cut is padding (never paired; it must be a ghost).
 * start_cut = 1 needs first_segment > 0; a closed beam cannot be cut (and
 * starts at segment 0). first_segment + the beam's segments <= INT_MAX.
 * Before finalize; a second call for a beam replaces the first. Either
 * every beam of a model gets this call or none (then a beam's global id is
 * its local index and first_segment 0: a serial model); finalize checks it,
 * and the global order (B2B_ERR_RANGE naming both beams: out of order or
 * overlapping pieces; pieces of one global beam must agree on kind, radius,
 * group and self-contact). */
B2B_EXPORT int b2b_model_set_beam_global(b2b_model *model, int beam, int64_t global_beam,
                                         int first_segment, int start_cut, int end_cut,
                                         char *errmsg, int errmsg_len);
/* Local segments [first, first + count) of `beam` are ghosts: owned by
 * another rank, present for the search and for pairs with this rank's
 * segments. 0 <= first, count >= 0, first + count <= the beam's segments
 * (B2B_ERR_RANGE). Before finalize; ranges accumulate (overlaps are
 * harmless). A model with ghosts needs global ids (finalize:
 * B2B_ERR_STATE). */
B2B_EXPORT int b2b_model_set_ghost_segments(b2b_model *model, int beam, int first, int count,
                                            char *errmsg, int errmsg_len);
/* Contact k of the last update (as b2b_model_get_contact) in global ids:
 * global beam and segment of its A, then of its B. */
B2B_EXPORT int b2b_model_get_contact_global(const b2b_model *model, int k, int64_t pair[4],
                                            char *errmsg, int errmsg_len);

/* The number of migrating contacts of the last update (0 for a serial
 * model, and after a commit: the committed state no longer holds them).
 * B2B_ERR_STATE as b2b_model_contact_count (before the first update, after
 * a revert or restore). */
B2B_EXPORT int b2b_model_migration_count(const b2b_model *model, int *n, char *errmsg,
                                         int errmsg_len);
/* Migrating contact k (0 <= k < n): target[4] = global beam and segment of
 * the target pair's A, then of its B (its owner: the owner of the smaller),
 * and *size, the bytes of its packed form. Either output may be NULL. */
B2B_EXPORT int b2b_model_migration_info(const b2b_model *model, int k, int64_t target[4],
                                        int64_t *size, char *errmsg, int errmsg_len);
/* Packs migrating contact k into buffer (size >= its size from
 * migration_info, else B2B_ERR_SIZE). The packed form is native byte order
 * (ranks of one machine type), checksummed, and names its source, its
 * target, its group pair (with a fingerprint of the pair's parameters) and
 * its history. */
B2B_EXPORT int b2b_model_migration_pack(const b2b_model *model, int k, void *buffer,
                                        int64_t size, char *errmsg, int errmsg_len);
/* A packed contact from another rank (size: exactly its packed size). It
 * serves as the committed history of its target pair in this model's
 * following updates, exactly as the handed-over history serves in a single
 * model, until the next commit (which keeps its result, as for any contact)
 * or revert (which drops it); a target pair that holds its own active
 * committed contact keeps it (as in a single model). Unpacking a contact of
 * the same source again replaces it; *changed = 1 if the model's set of
 * received contacts changed, else 0. buffer NULL with size 0 ends a round
 * of receiving (Host protocol): the received contacts not unpacked since
 * the last update are dropped, *changed = 1 if there were any. A buffer
 * that is not a valid packed contact for this model (truncated, corrupted,
 * another format, sizes, a target it does not hold or does not evaluate, a
 * group pair or parameters other than the target pair's, a history length
 * or history that does not match) is B2B_ERR_RANGE with a message saying
 * which, the model and *changed untouched. After finalize. */
B2B_EXPORT int b2b_model_migration_unpack(b2b_model *model, const void *buffer, int64_t size,
                                          int *changed, char *errmsg, int errmsg_len);

#ifdef __cplusplus
}
#endif

#endif /* B2B_MODEL_H */
