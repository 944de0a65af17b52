/* Distributed models (b2b_model.h, "Distributed models"; doc/distributed.md),
 * with two or three "rank" models in one process, each built from one scene
 * by a partition (pieces of beams, ghosts within reach, padding at cuts), and
 * the host's exchange of migrating contacts done by hand:
 *  - together they give exactly the single model's contacts: the same global
 *    pairs, each on one rank, info, residual and tangent bit for bit, the
 *    counts summed, the totals to 1e-12, over several committed steps;
 *  - a frictional contact sliding across partition boundaries keeps its
 *    history through pack/unpack (its friction force is the single model's
 *    bit for bit), and without the exchange it would not;
 *  - revert drops received contacts, a second unpack of one buffer changes
 *    nothing, the end of a round drops what was not sent again, a rank model
 *    restarts bit for bit;
 *  - hostile set-up and packed buffers (every byte flipped, every
 *    truncation, foreign buffers) give clear errors with outputs untouched;
 *  - the audit and the crossing count of rank models: owned pairs only,
 *    summed over the ranks they are the single model's. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define PI 3.14159265358979323846
#define MAXR 3
#define MAXSEG 128
#define MAXC 2048

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

static int n_segments(int kind, int n_nodes, int closed) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n;
  ok(b2b_beam_segment_count(kind, n_nodes, closed, &n, msg, sizeof msg), msg);
  return n;
}

/* ---------------------------------------------------------------------------
 * A partition of a tst_scene: the owner of every global segment, and per
 * rank the held segments (own, ghosts within ghost_reach of an own one),
 * cut into pieces with one padding segment beyond each cut.
 * ------------------------------------------------------------------------- */
typedef struct {
  const tst_scene *sc;
  int nr;
  int nseg[TST_MAX_BEAMS];
  int owner[TST_MAX_BEAMS][MAXSEG];
  b2b_model *m[MAXR];
  int pieces[MAXR];   /* local beams */
  int cuts[MAXR];     /* cuts (padding segments) */
  int ghosts[MAXR];   /* ghost segments (padding included) */
  int piece_gbeam[MAXR][4 * TST_MAX_BEAMS];  /* per local beam: its global beam, */
  int piece_first[MAXR][4 * TST_MAX_BEAMS];  /* and its first global segment */
} dist;

/* Host nodes of segment s of beam b (its patch; -1 none). */
static void seg_nodes(const tst_scene *sc, int b, int s, int nodes[4]) {
  char msg[B2B_ERRMSG_LEN] = "";
  int local[4], r0, r1;
  ok(b2b_beam_segment_patch(sc->kind[b], sc->count[b], sc->closed[b], s, local, &r0, &r1, msg,
                            sizeof msg), msg);
  for (int k = 0; k < 4; ++k) nodes[k] = local[k] < 0 ? -1 : sc->first[b] + local[k];
}

/* The smallest distance between the patch nodes of two segments. */
static double seg_distance(const tst_scene *sc, int b, int s, int c, int t) {
  int p[4], q[4];
  seg_nodes(sc, b, s, p);
  seg_nodes(sc, c, t, q);
  double best = HUGE_VAL;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (p[i] < 0 || q[j] < 0) continue;
      const double *x = sc->x + 3 * p[i], *y = sc->x + 3 * q[j];
      const double d = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                            (x[2] - y[2]) * (x[2] - y[2]));
      if (d < best) best = d;
    }
  return best;
}

static void dist_init(dist *d, const tst_scene *sc, int nr) {
  memset(d, 0, sizeof *d);
  d->sc = sc;
  d->nr = nr;
  for (int b = 0; b < sc->n_beams; ++b) {
    d->nseg[b] = n_segments(sc->kind[b], sc->count[b], sc->closed[b]);
    ck_assert_int_le(d->nseg[b], MAXSEG);
  }
}

/* Builds the rank models: held = own, plus every segment within ghost_reach
 * (node to node) of an own one; gaps of up to 2 segments filled (so that
 * padding never overlaps the next piece); a closed beam whole. */
static void dist_build(dist *d, const b2b_params *p, int all_pairs, double margin) {
  const tst_scene *sc = d->sc;
  char msg[B2B_ERRMSG_LEN] = "";
  static unsigned char held[TST_MAX_BEAMS][MAXSEG];
  for (int r = 0; r < d->nr; ++r) {
    for (int b = 0; b < sc->n_beams; ++b)
      for (int s = 0; s < d->nseg[b]; ++s) held[b][s] = d->owner[b][s] == r;
    for (int b = 0; b < sc->n_beams; ++b)
      for (int s = 0; s < d->nseg[b]; ++s) {
        if (held[b][s]) continue;
        for (int c = 0; c < sc->n_beams && !held[b][s]; ++c)
          for (int t = 0; t < d->nseg[c]; ++t)
            if (d->owner[c][t] == r && seg_distance(sc, b, s, c, t) < margin) {
              held[b][s] = 2;
              break;
            }
      }
    b2b_model *m = NULL;
    ok(b2b_model_create(&m, msg, sizeof msg), msg);
    int local = 0;
    for (int b = 0; b < sc->n_beams; ++b) {
      const int n = d->nseg[b];
      int any = 0;
      for (int s = 0; s < n; ++s) any |= held[b][s] != 0;
      if (!any) continue;
      if (sc->closed[b]) {
        for (int s = 0; s < n; ++s)
          if (!held[b][s]) held[b][s] = 2;
      } else {
        for (int s = 0; s < n; ++s) {  /* fill gaps of 1 or 2 */
          if (held[b][s]) continue;
          int e = s;
          while (e < n && !held[b][e]) ++e;
          if (s > 0 && e < n && e - s <= 2)
            for (int k = s; k < e; ++k) held[b][k] = 2;
          s = e;
        }
      }
      const int centred = sc->kind[b] == B2B_CURVE_HERMITE_MIDPOINT;
      for (int s = 0; s < n; ++s) {
        if (!held[b][s]) continue;
        int e = s;
        while (e < n && held[b][e]) ++e;
        /* the run [s, e), with padding beyond its cuts */
        const int s0 = !sc->closed[b] && s > 0 ? s - 1 : s;
        const int s1 = !sc->closed[b] && e < n ? e + 1 : e;
        const int start_cut = s0 > 0, end_cut = s1 < n;  /* (not at the beam's ends) */
        int nodes[MAXSEG + 1], beam;
        const int count = centred || sc->closed[b] ? s1 - s0 : s1 - s0 + 1;
        for (int k = 0; k < count; ++k) nodes[k] = sc->first[b] + s0 + k;
        ok(b2b_model_add_beam(m, nodes, count, sc->closed[b], sc->radius[b], sc->kind[b],
                              sc->group[b], &beam, msg, sizeof msg), msg);
        ck_assert_int_eq(beam, local);
        ck_assert_int_lt(local, 4 * TST_MAX_BEAMS);
        d->piece_gbeam[r][local] = b;
        d->piece_first[r][local] = s0;
        ok(b2b_model_set_beam_global(m, beam, b, s0, start_cut, end_cut, msg, sizeof msg), msg);
        for (int k = s0; k < s1; ++k)
          if (k < s || k >= e || held[b][k] == 2) {
            ok(b2b_model_set_ghost_segments(m, beam, k - s0, 1, msg, sizeof msg), msg);
            ++d->ghosts[r];
          }
        d->cuts[r] += start_cut + end_cut;
        ++local;
        s = e;
      }
    }
    ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
    ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
    if (all_pairs) ok(b2b_model_set_group_pair(m, 1, 1, p, msg, sizeof msg), msg);
    ok(b2b_model_set_real(m, "search_margin", 0.05, msg, sizeof msg), msg);
    ok(b2b_model_finalize(m, sc->n_nodes, msg, sizeof msg), msg);
    d->m[r] = m;
    d->pieces[r] = local;
  }
}

static void dist_free(dist *d) {
  for (int r = 0; r < d->nr; ++r) b2b_model_destroy(&d->m[r]);
}

/* The rank owning the smaller of a pair's two segments (global ids). */
static int owner_of(const dist *d, const int64_t t[4]) {
  const int a_first = t[0] < t[2] || (t[0] == t[2] && t[1] < t[3]);
  return a_first ? d->owner[t[0]][t[1]] : d->owner[t[2]][t[3]];
}

/* One round of the host's exchange: pack every migrating contact, unpack it
 * at its owner, end the round everywhere. Returns whether a received set
 * changed; *sent counts the contacts sent. */
static int exchange(dist *d, int *sent) {
  char msg[B2B_ERRMSG_LEN] = "";
  int changed = 0;
  for (int r = 0; r < d->nr; ++r) {
    int n;
    ok(b2b_model_migration_count(d->m[r], &n, msg, sizeof msg), msg);
    for (int k = 0; k < n; ++k) {
      int64_t target[4], size;
      ok(b2b_model_migration_info(d->m[r], k, target, &size, msg, sizeof msg), msg);
      unsigned char *buf = malloc((size_t)size);
      ok(b2b_model_migration_pack(d->m[r], k, buf, size, msg, sizeof msg), msg);
      const int to = owner_of(d, target);
      ck_assert_msg(to != r, "rank %d sends a contact to itself", r);
      int ch = -1;
      ok(b2b_model_migration_unpack(d->m[to], buf, size, &ch, msg, sizeof msg), msg);
      ck_assert(ch == 0 || ch == 1);
      changed |= ch;
      free(buf);
      if (sent) ++*sent;
    }
  }
  for (int r = 0; r < d->nr; ++r) {
    int ch = -1;
    ok(b2b_model_migration_unpack(d->m[r], NULL, 0, &ch, msg, sizeof msg), msg);
    changed |= ch;
  }
  return changed;
}

/* The host protocol of one Newton iteration; returns the extra updates. */
static int dist_update(dist *d, const double *x, int n_nodes, int migrate, int *sent) {
  char msg[B2B_ERRMSG_LEN] = "";
  int extra = 0;
  for (int r = 0; r < d->nr; ++r) ok(b2b_model_update(d->m[r], x, 3, n_nodes, 1, msg, sizeof msg), msg);
  while (migrate && exchange(d, sent)) {
    ck_assert_int_lt(++extra, 10);
    for (int r = 0; r < d->nr; ++r)
      ok(b2b_model_update(d->m[r], x, 3, n_nodes, 1, msg, sizeof msg), msg);
  }
  return extra;
}

static void dist_commit(dist *d) {
  char msg[B2B_ERRMSG_LEN] = "";
  for (int r = 0; r < d->nr; ++r) ok(b2b_model_commit(d->m[r], msg, sizeof msg), msg);
}

/* The single model's contacts against the ranks': each global pair on one
 * rank, nodes, info, residual and tangent bit for bit; counts summed; the
 * totals to 1e-12. Returns the number of contacts. */
static int compare(const b2b_model *single, const dist *d, const char *what) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n1;
  ok(b2b_model_contact_count(single, &n1, msg, sizeof msg), msg);
  static double K1[576], K2[576];
  int found_total = 0;
  int counts[MAXR][16];
  double totals[MAXR][8];
  for (int r = 0; r < d->nr; ++r) {
    int n;
    ok(b2b_model_contact_count(d->m[r], &n, msg, sizeof msg), msg);
    found_total += n;
    ok(b2b_model_stats(d->m[r], counts[r], totals[r], msg, sizeof msg), msg);
  }
  ck_assert_msg(found_total == n1, "%s: the ranks have %d contacts, the single model %d", what,
                found_total, n1);
  for (int k = 0; k < n1; ++k) {
    int nodes1[8], pair1[4];
    double info1[32], res1[24];
    ok(b2b_model_get_contact(single, k, nodes1, pair1, info1, res1, K1, 24, msg, sizeof msg), msg);
    int64_t g1[4];
    ok(b2b_model_get_contact_global(single, k, g1, msg, sizeof msg), msg);
    for (int i = 0; i < 4; ++i) ck_assert_int_eq(g1[i], pair1[i]);  /* serial: local = global */
    int hits = 0;
    for (int r = 0; r < d->nr; ++r) {
      int n;
      ok(b2b_model_contact_count(d->m[r], &n, msg, sizeof msg), msg);
      for (int j = 0; j < n; ++j) {
        int64_t g[4];
        ok(b2b_model_get_contact_global(d->m[r], j, g, msg, sizeof msg), msg);
        if (memcmp(g, g1, sizeof g)) continue;
        ++hits;
        int nodes[8], pair[4];
        double info[32], res[24];
        ok(b2b_model_get_contact(d->m[r], j, nodes, pair, info, res, K2, 24, msg, sizeof msg), msg);
        ck_assert_msg(memcmp(nodes, nodes1, sizeof nodes) == 0, "%s: contact %d: nodes differ", what, k);
        ck_assert_msg(memcmp(info, info1, sizeof info) == 0,
                      "%s: contact %d (%d %d / %d %d) on rank %d: info differs (f_N %.17g vs %.17g, "
                      "T %.17g vs %.17g)", what, k, pair1[0], pair1[1], pair1[2], pair1[3], r,
                      info[B2B_INFO_NORMAL_FORCE], info1[B2B_INFO_NORMAL_FORCE],
                      info[B2B_INFO_TANGENTIAL_FORCE], info1[B2B_INFO_TANGENTIAL_FORCE]);
        ck_assert_msg(memcmp(res, res1, sizeof res) == 0, "%s: contact %d: residual differs", what, k);
        ck_assert_msg(memcmp(K1, K2, sizeof K1) == 0, "%s: contact %d: tangent differs", what, k);
      }
    }
    ck_assert_msg(hits == 1, "%s: contact %d (%d %d / %d %d) is on %d ranks", what, k, pair1[0],
                  pair1[1], pair1[2], pair1[3], hits);
  }
  int c1[16];
  double t1[8];
  ok(b2b_model_stats(single, c1, t1, msg, sizeof msg), msg);
  const int additive[] = {B2B_COUNT_ACTIVE, B2B_COUNT_OPEN, B2B_COUNT_LOST, B2B_COUNT_HANDOVERS,
                          B2B_COUNT_STICK, B2B_COUNT_SLIP, B2B_COUNT_CROSSED, B2B_COUNT_LINE,
                          B2B_COUNT_PARALLEL, B2B_COUNT_OUTSIDE, B2B_COUNT_NOT_CONVERGED,
                          B2B_COUNT_NO_NORMAL, B2B_COUNT_EVALUATED};
  for (size_t i = 0; i < sizeof additive / sizeof additive[0]; ++i) {
    int sum = 0;
    for (int r = 0; r < d->nr; ++r) sum += counts[r][additive[i]];
    ck_assert_msg(sum == c1[additive[i]], "%s: count %d: ranks %d, single %d", what, additive[i],
                  sum, c1[additive[i]]);
  }
  const int summed[] = {B2B_TOTAL_ENERGY, B2B_TOTAL_DISSIPATION_STEP, B2B_TOTAL_DISSIPATION,
                        B2B_TOTAL_NORMAL_FORCE};
  for (size_t i = 0; i < sizeof summed / sizeof summed[0]; ++i) {
    double sum = 0.0;
    for (int r = 0; r < d->nr; ++r) sum += totals[r][summed[i]];
    const double ref = t1[summed[i]];
    ck_assert_msg(fabs(sum - ref) <= 1e-12 * fabs(ref) + 1e-300, "%s: total %d: ranks %.17g, "
                  "single %.17g", what, summed[i], sum, ref);
  }
  double gmin = HUGE_VAL;
  for (int r = 0; r < d->nr; ++r) gmin = fmin(gmin, totals[r][B2B_TOTAL_MIN_GAP]);
  ck_assert_msg(gmin == t1[B2B_TOTAL_MIN_GAP], "%s: min gap %.17g vs %.17g", what, gmin,
                t1[B2B_TOTAL_MIN_GAP]);
  return n1;
}

/* ---------------------------------------------------------------------------
 * 1. A fibre network in slabs, several steps with friction and commits.
 * ------------------------------------------------------------------------- */
static void network_run(int nr, int seed) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, (uint64_t)seed);
  tst_scene sc;
  const double box = 3.0;
  tst_network(&rng, 24, 12, 0.3, box, 0.06, 0.3, 6, 0, &sc);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 2e3);
  b2b_model *single = tst_model(&sc, p, 1);
  ok(b2b_model_set_real(single, "search_margin", 0.05, msg, sizeof msg), msg);
  dist d;
  dist_init(&d, &sc, nr);
  /* slabs in x of the segment's first patch node */
  for (int b = 0; b < sc.n_beams; ++b)
    for (int s = 0; s < d.nseg[b]; ++s) {
      int nodes[4];
      seg_nodes(&sc, b, s, nodes);
      const double x = sc.x[3 * nodes[1]];
      int r = (int)floor(x / box * nr);
      d.owner[b][s] = r < 0 ? 0 : r >= nr ? nr - 1 : r;
    }
  dist_build(&d, p, 1, 1.2);
  int cuts = 0, pieces = 0;
  for (int r = 0; r < nr; ++r) {
    cuts += d.cuts[r];
    pieces += d.pieces[r];
  }
  ck_assert_msg(cuts >= 5 && pieces > sc.n_beams, "the partition cuts beams (%d cuts, %d pieces)",
                cuts, pieces);
  /* a random velocity per node, the beams drawn together */
  double *v = malloc(sizeof(double) * 3 * (size_t)sc.n_nodes);
  for (int k = 0; k < 3 * sc.n_nodes; ++k) v[k] = tst_uniform(&rng, -1, 1);
  int contacts = 0, sent = 0, extra = 0;
  char what[64];
  for (int step = 0; step < 8; ++step) {
    if (step > 0) tst_scene_move(&sc, v, 0.01);
    tst_update(single, &sc, 1);
    extra += dist_update(&d, sc.x, sc.n_nodes, 1, &sent);
    snprintf(what, sizeof what, "%d ranks, seed %d, step %d", nr, seed, step);
    contacts += compare(single, &d, what);
    ok(b2b_model_commit(single, msg, sizeof msg), msg);
    dist_commit(&d);
  }
  ck_assert_msg(contacts > 40, "the scene has contacts (%d over the steps)", contacts);
  free(v);
  dist_free(&d);
  b2b_model_destroy(&single);
  b2b_params_destroy(&p);
  tst_scene_free(&sc);
}

START_TEST(network_two_ranks) { network_run(2, 11); }
END_TEST

START_TEST(network_three_ranks) { network_run(3, 12); }
END_TEST

/* ---------------------------------------------------------------------------
 * 2. A frictional contact sliding along an arc across partition boundaries
 *    (check_model_sliding's scene): A (global beam 0) in three blocks, B
 *    (global beam 1) owned by rank 0, a ghost on the others.
 * ------------------------------------------------------------------------- */
#define NA 21
#define NB 9
typedef struct {
  tst_scene sc;
  double x[3 * (NA + NB)];
} arc_scene;

static void arc_place(arc_scene *a, double theta) {
  const double R = 4.0, ra = 0.2, rb = 0.2, delta = 0.12, h = PI / 20;
  double phi = 0.0;
  for (int k = 0; k < NA; ++k) {
    a->x[3 * k] = R * cos(phi);
    a->x[3 * k + 1] = R * sin(phi);
    a->x[3 * k + 2] = 0.0;
    phi += (k % 2 ? 0.75 : 1.25) * h;
  }
  const double rho = R + ra + rb - delta;
  for (int k = 0; k < NB; ++k) {
    double *p = a->x + 3 * (NA + k);
    p[0] = rho * cos(theta);
    p[1] = rho * sin(theta);
    p[2] = 0.15 * (k - 4) + 0.0123;
  }
}

static void arc_setup(arc_scene *a, int kind) {
  memset(a, 0, sizeof *a);
  tst_scene *sc = &a->sc;
  sc->n_beams = 2;
  sc->n_nodes = NA + NB;
  sc->x = a->x;
  sc->first[0] = 0;
  sc->count[0] = NA;
  sc->kind[0] = kind;
  sc->group[0] = 0;
  sc->radius[0] = 0.2;
  sc->first[1] = NA;
  sc->count[1] = NB;
  sc->kind[1] = B2B_CURVE_LINEAR;
  sc->group[1] = 1;
  sc->radius[1] = 0.2;
  sc->exclusion[0] = sc->exclusion[1] = -1.0;
}

/* A's segments in nr blocks; B on rank 0. */
static void arc_partition(dist *d, int nr) {
  for (int s = 0; s < d->nseg[0]; ++s) d->owner[0][s] = s * nr / d->nseg[0];
  for (int s = 0; s < d->nseg[1]; ++s) d->owner[1][s] = 0;
}

static void slide_run(int kind, int nr) {
  char msg[B2B_ERRMSG_LEN] = "";
  arc_scene a;
  arc_setup(&a, kind);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 2e3);
  arc_place(&a, 0.25);
  b2b_model *single = tst_model(&a.sc, p, 0);
  ok(b2b_model_set_real(single, "search_margin", 0.05, msg, sizeof msg), msg);
  dist d, nomig;
  dist_init(&d, &a.sc, nr);
  arc_partition(&d, nr);
  dist_build(&d, p, 0, 20.0);  /* B travels along all of A: a ghost everywhere */
  dist_init(&nomig, &a.sc, nr);
  arc_partition(&nomig, nr);
  dist_build(&nomig, p, 0, 20.0);
  int sent = 0, extra = 0, slips = 0, differs = 0, rank_prev = -1, crossings = 0;
  char what[96];
  for (double theta = 0.25; theta <= 2.85; theta += 0.05) {
    arc_place(&a, theta);
    tst_update(single, &a.sc, 1);
    extra += dist_update(&d, a.x, a.sc.n_nodes, 1, &sent);
    dist_update(&nomig, a.x, a.sc.n_nodes, 0, NULL);
    snprintf(what, sizeof what, "%s, %d ranks, theta %.2f", tst_kind_name(kind), nr, theta);
    ck_assert_int_eq(compare(single, &d, what), 1);
    double info1[32];
    int pair1[4];
    ok(b2b_model_get_contact(single, 0, NULL, pair1, info1, NULL, NULL, 0, msg, sizeof msg), msg);
    slips += info1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP;
    const int rank = d.owner[0][pair1[1]];
    if (rank_prev >= 0 && rank != rank_prev) {
      ++crossings;
      /* without the exchange: the contact on its new rank started afresh */
      int found = 0;
      for (int r = 0; r < nr; ++r) {
        int n;
        ok(b2b_model_contact_count(nomig.m[r], &n, msg, sizeof msg), msg);
        for (int j = 0; j < n; ++j) {
          double info[32];
          ok(b2b_model_get_contact(nomig.m[r], j, NULL, NULL, info, NULL, NULL, 0, msg, sizeof msg),
             msg);
          ++found;
          const double dT = fabs(info[B2B_INFO_TANGENTIAL_FORCE] - info1[B2B_INFO_TANGENTIAL_FORCE]) +
                            fabs(info[B2B_INFO_TANGENTIAL_FORCE + 1] -
                                 info1[B2B_INFO_TANGENTIAL_FORCE + 1]) +
                            fabs(info[B2B_INFO_TANGENTIAL_FORCE + 2] -
                                 info1[B2B_INFO_TANGENTIAL_FORCE + 2]);
          const double T = fabs(info1[B2B_INFO_TANGENTIAL_FORCE]) +
                           fabs(info1[B2B_INFO_TANGENTIAL_FORCE + 1]) +
                           fabs(info1[B2B_INFO_TANGENTIAL_FORCE + 2]);
          differs += dT > 1e-3 * T;
        }
      }
      int counts[16], lost = 0, leaving = 0;
      for (int r = 0; r < nr; ++r) {
        int n;
        ok(b2b_model_stats(nomig.m[r], counts, NULL, msg, sizeof msg), msg);
        lost += counts[B2B_COUNT_LOST];
        ok(b2b_model_migration_count(nomig.m[r], &n, msg, sizeof msg), msg);
        leaving += n;
      }
      /* the old rank's contact is migrating (not lost), the new rank's fresh */
      ck_assert_msg(found == 1 && lost == 0 && leaving == 1, "%s: without the exchange: %d "
                    "contacts, %d lost, %d migrating", what, found, lost, leaving);
    }
    rank_prev = rank;
    ok(b2b_model_commit(single, msg, sizeof msg), msg);
    dist_commit(&d);
    dist_commit(&nomig);
  }
  ck_assert_msg(crossings == nr - 1, "%s: the contact crossed %d partition boundaries", what,
                crossings);
  ck_assert_msg(sent >= crossings && extra >= crossings, "%s: %d contacts sent, %d extra updates",
                what, sent, extra);
  ck_assert_msg(differs == crossings, "%s: without the exchange the friction force differs at "
                "%d of %d crossings", what, differs, crossings);
  ck_assert_msg(slips > 30, "%s: the contact slips (%d steps)", what, slips);
  dist_free(&d);
  dist_free(&nomig);
  b2b_model_destroy(&single);
  b2b_params_destroy(&p);
}

START_TEST(slide_across_ranks) {
  /* quick mode: each kind on 2 or on 3 ranks, alternately */
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    if (!tst_quick() || kind % 2 == 0) slide_run(kind, 2);
    if (!tst_quick() || kind % 2 == 1) slide_run(kind, 3);
  }
}
END_TEST


/* ---------------------------------------------------------------------------
 * 3. Received contacts: a second unpack, the end of a round, revert, restart.
 * ------------------------------------------------------------------------- */
#define REC_CAP (1 << 16)

static size_t record(const b2b_model *m, unsigned char *buf) {
  return tst_model_record(m, 1, buf, REC_CAP);
}

/* Runs the sliding scene on two ranks, committing, up to the first update
 * whose rank 0 has a migrating contact; returns its theta (the models are
 * updated there, before any exchange). */
static double run_to_migration(dist *d, arc_scene *a, b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  dist_init(d, &a->sc, 2);
  arc_partition(d, 2);
  dist_build(d, p, 0, 20.0);
  for (double theta = 0.25; theta <= 2.85; theta += 0.05) {
    arc_place(a, theta);
    for (int r = 0; r < 2; ++r)
      ok(b2b_model_update(d->m[r], a->x, 3, a->sc.n_nodes, 1, msg, sizeof msg), msg);
    int n;
    ok(b2b_model_migration_count(d->m[0], &n, msg, sizeof msg), msg);
    if (n == 1) return theta;
    ck_assert_int_eq(n, 0);
    dist_commit(d);
  }
  ck_abort_msg("no contact migrated");
  return 0.0;
}

/* Packs rank 0's migrating contact 0 (malloc'ed). */
static unsigned char *pack0(const dist *d, int64_t *size) {
  char msg[B2B_ERRMSG_LEN] = "";
  int64_t target[4];
  ok(b2b_model_migration_info(d->m[0], 0, target, size, msg, sizeof msg), msg);
  ck_assert_int_eq(owner_of(d, target), 1);
  unsigned char *buf = malloc((size_t)*size);
  ok(b2b_model_migration_pack(d->m[0], 0, buf, *size, msg, sizeof msg), msg);
  return buf;
}

START_TEST(received_contacts) {
  char msg[B2B_ERRMSG_LEN] = "";
  static unsigned char r0[REC_CAP], r1[REC_CAP], r2[REC_CAP];
  arc_scene a;
  arc_setup(&a, B2B_CURVE_HERMITE_NODAL);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 2e3);
  dist d;
  run_to_migration(&d, &a, p);
  b2b_model *m1 = d.m[1];
  const size_t n0 = record(m1, r0);  /* rank 1 without the contact */
  int64_t size;
  unsigned char *buf = pack0(&d, &size);
  int ch = -1;
  ok(b2b_model_migration_unpack(m1, buf, size, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 1);
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  const size_t n1 = record(m1, r1);
  ck_assert_msg(n1 != n0 || memcmp(r0, r1, n0) != 0, "the received contact changes rank 1");
  /* the same contact again: nothing changes */
  ok(b2b_model_migration_unpack(m1, buf, size, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 0);
  ok(b2b_model_migration_unpack(m1, NULL, 0, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 0);  /* it was unpacked since the last update */
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  ck_assert(record(m1, r2) == n1 && memcmp(r1, r2, n1) == 0);
  /* a round in which nobody sends it again drops it */
  ok(b2b_model_migration_unpack(m1, NULL, 0, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 1);
  ok(b2b_model_migration_unpack(m1, NULL, 0, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 0);
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  ck_assert(record(m1, r2) == n0 && memcmp(r0, r2, n0) == 0);
  /* revert drops it */
  ok(b2b_model_migration_unpack(m1, buf, size, &ch, msg, sizeof msg), msg);
  ck_assert_int_eq(ch, 1);
  ok(b2b_model_revert(m1, msg, sizeof msg), msg);
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  ck_assert(record(m1, r2) == n0 && memcmp(r0, r2, n0) == 0);
  /* a commit keeps its result and ends it: rank 0 no longer has it either */
  ok(b2b_model_migration_unpack(m1, buf, size, &ch, msg, sizeof msg), msg);
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  ck_assert(record(m1, r2) == n1 && memcmp(r1, r2, n1) == 0);
  dist_commit(&d);
  int n;
  ok(b2b_model_migration_count(d.m[0], &n, msg, sizeof msg), msg);
  ck_assert_int_eq(n, 0);
  ok(b2b_model_contact_count(d.m[1], &n, msg, sizeof msg), msg);
  ck_assert_int_eq(n, 1);
  ok(b2b_model_contact_count(d.m[0], &n, msg, sizeof msg), msg);
  ck_assert_int_eq(n, 0);
  free(buf);
  dist_free(&d);
  b2b_params_destroy(&p);
}
END_TEST

/* A rank model saved after a migration restores into a model built the same
 * way and continues bit for bit; a buffer of another rank is refused. */
START_TEST(rank_restart) {
  char msg[B2B_ERRMSG_LEN] = "";
  static unsigned char ra[REC_CAP], rb[REC_CAP];
  arc_scene a;
  arc_setup(&a, B2B_CURVE_HERMITE_NODAL_WEIGHTED);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 2e3);
  dist d, e;
  double theta = run_to_migration(&d, &a, p);
  while (exchange(&d, NULL))
    for (int r = 0; r < 2; ++r)
      ok(b2b_model_update(d.m[r], a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  dist_commit(&d);
  dist_init(&e, &a.sc, 2);
  arc_partition(&e, 2);
  dist_build(&e, p, 0, 20.0);
  unsigned char *saved[2];
  int64_t size[2];
  for (int r = 0; r < 2; ++r) {
    ok(b2b_model_save_size(d.m[r], &size[r], msg, sizeof msg), msg);
    saved[r] = malloc((size_t)size[r]);
    ok(b2b_model_save(d.m[r], saved[r], size[r], msg, sizeof msg), msg);
  }
  /* rank 0's buffer into rank 1's model: another set-up */
  int st = b2b_model_restore(e.m[1], saved[0], size[0], msg, sizeof msg);
  ck_assert_int_eq(st, B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "another model") != NULL, "%s", msg);
  for (int r = 0; r < 2; ++r) ok(b2b_model_restore(e.m[r], saved[r], size[r], msg, sizeof msg), msg);
  int sent = 0;
  for (int step = 0; step < 12; ++step) {
    theta += 0.05;
    arc_place(&a, theta);
    dist_update(&d, a.x, a.sc.n_nodes, 1, &sent);
    dist_update(&e, a.x, a.sc.n_nodes, 1, NULL);
    for (int r = 0; r < 2; ++r) {
      const size_t na = record(d.m[r], ra), nb = record(e.m[r], rb);
      ck_assert_msg(na == nb && memcmp(ra, rb, na) == 0, "step %d, rank %d: the restored model "
                    "differs", step, r);
    }
    dist_commit(&d);
    dist_commit(&e);
  }
  for (int r = 0; r < 2; ++r) free(saved[r]);
  dist_free(&d);
  dist_free(&e);
  b2b_params_destroy(&p);
}
END_TEST

/* ---------------------------------------------------------------------------
 * 4. Hostile input.
 * ------------------------------------------------------------------------- */
static void expect(int st, int want, const char *msg, const char *word) {
  ck_assert_msg(st == want, "status %d (want %d): %s", st, want, msg);
  ck_assert_msg(strstr(msg, word) != NULL, "message without \"%s\": %s", word, msg);
}

/* A model of three beams (nodes 0-5, 6-11, 12-16 closed) before finalize. */
static b2b_model *three_beams(const b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  int nodes[6], beam;
  for (int b = 0; b < 3; ++b) {
    for (int k = 0; k < 6; ++k) nodes[k] = 6 * b + k;
    ok(b2b_model_add_beam(m, nodes, b == 2 ? 5 : 6, b == 2, 0.1, B2B_CURVE_HERMITE_NODAL, 0,
                          &beam, msg, sizeof msg), msg);
  }
  ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
  return m;
}

START_TEST(hostile_setup) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = three_beams(p);
  expect(b2b_model_set_beam_global(NULL, 0, 0, 0, 0, 0, msg, sizeof msg), B2B_ERR_NULL, msg, "model");
  expect(b2b_model_set_beam_global(m, 3, 0, 0, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "beam 3");
  expect(b2b_model_set_beam_global(m, -1, 0, 0, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "beam -1");
  expect(b2b_model_set_beam_global(m, 0, -1, 0, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "global_beam");
  expect(b2b_model_set_beam_global(m, 0, 0, -2, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "first_segment");
  expect(b2b_model_set_beam_global(m, 0, 0, 4, 2, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "start_cut");
  expect(b2b_model_set_beam_global(m, 0, 0, 4, 0, -1, msg, sizeof msg), B2B_ERR_RANGE, msg, "end_cut");
  expect(b2b_model_set_beam_global(m, 0, 0, 0, 1, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "nothing lies before");
  expect(b2b_model_set_beam_global(m, 2, 2, 0, 0, 1, msg, sizeof msg), B2B_ERR_RANGE, msg, "closed beam cannot be cut");
  expect(b2b_model_set_beam_global(m, 2, 2, 3, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "whole");
  expect(b2b_model_set_beam_global(m, 0, 0, 2147483647 - 3, 0, 0, msg, sizeof msg), B2B_ERR_RANGE, msg, "INT_MAX");
  expect(b2b_model_set_ghost_segments(NULL, 0, 0, 1, msg, sizeof msg), B2B_ERR_NULL, msg, "model");
  expect(b2b_model_set_ghost_segments(m, 5, 0, 1, msg, sizeof msg), B2B_ERR_RANGE, msg, "beam 5");
  expect(b2b_model_set_ghost_segments(m, 0, 0, -1, msg, sizeof msg), B2B_ERR_RANGE, msg, "count");
  expect(b2b_model_set_ghost_segments(m, 0, 5, 1, msg, sizeof msg), B2B_ERR_RANGE, msg, "beyond");
  expect(b2b_model_set_ghost_segments(m, 0, -1, 1, msg, sizeof msg), B2B_ERR_RANGE, msg, "beyond");
  expect(b2b_model_set_ghost_segments(m, 0, 3, 3, msg, sizeof msg), B2B_ERR_RANGE, msg, "beyond");
  {  /* unpack needs a finalized model */
    unsigned char junk[16] = {0};
    int ch = 7;
    expect(b2b_model_migration_unpack(m, junk, 16, &ch, msg, sizeof msg), B2B_ERR_STATE, msg,
           "not finalized");
    ck_assert_int_eq(ch, 7);
  }
  /* finalize: ghosts without ids */
  ok(b2b_model_set_ghost_segments(m, 0, 0, 2, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_STATE, msg, "no beam has a global id");
  /* some beams without ids */
  ok(b2b_model_set_beam_global(m, 0, 0, 0, 0, 0, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_STATE, msg, "beam 1 has no global id");
  /* out of global order */
  ok(b2b_model_set_beam_global(m, 0, 5, 0, 0, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 1, 4, 0, 0, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 2, 6, 0, 0, 0, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_RANGE, msg, "global order");
  /* overlapping pieces of one global beam (5 segments from 0, then from 3) */
  ok(b2b_model_set_beam_global(m, 1, 5, 3, 1, 0, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_RANGE, msg, "overlaps");
  /* the same piece order reversed */
  ok(b2b_model_set_beam_global(m, 0, 5, 6, 1, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 1, 5, 0, 0, 1, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_RANGE, msg, "global order");
  /* a cut whose padding is own */
  ok(b2b_model_set_beam_global(m, 0, 5, 0, 0, 1, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 1, 5, 6, 1, 0, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_RANGE, msg, "padding");
  ck_assert_int_eq(b2b_model_update(m, NULL, 3, 18, 0, msg, sizeof msg), B2B_ERR_STATE);
  /* made right: the pads are ghosts */
  ok(b2b_model_set_ghost_segments(m, 0, 4, 1, msg, sizeof msg), msg);
  ok(b2b_model_set_ghost_segments(m, 1, 0, 1, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 18, msg, sizeof msg), msg);
  expect(b2b_model_set_beam_global(m, 0, 5, 0, 0, 1, msg, sizeof msg), B2B_ERR_STATE, msg, "finalized");
  expect(b2b_model_set_ghost_segments(m, 0, 0, 1, msg, sizeof msg), B2B_ERR_STATE, msg, "finalized");
  /* before an update */
  int n = -7;
  int64_t g[4] = {-7, -7, -7, -7}, size = -7;
  expect(b2b_model_get_contact_global(m, 0, g, msg, sizeof msg), B2B_ERR_STATE, msg, "update");
  expect(b2b_model_migration_count(m, &n, msg, sizeof msg), B2B_ERR_STATE, msg, "update");
  expect(b2b_model_migration_info(m, 0, g, &size, msg, sizeof msg), B2B_ERR_STATE, msg, "update");
  ck_assert(n == -7 && g[0] == -7 && g[3] == -7 && size == -7);
  b2b_model_destroy(&m);
  /* pieces of one global beam that differ */
  m = three_beams(p);
  ok(b2b_model_set_beam_global(m, 0, 0, 0, 0, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 1, 0, 5, 0, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_beam_global(m, 2, 1, 0, 0, 0, msg, sizeof msg), msg);
  ok(b2b_model_set_self_contact(m, 1, 1, -1.0, msg, sizeof msg), msg);
  expect(b2b_model_finalize(m, 18, msg, sizeof msg), B2B_ERR_RANGE, msg, "differ");
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

static uint64_t fnv1a(const unsigned char *q, size_t n) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; ++i) {
    h ^= q[i];
    h *= 1099511628211ULL;
  }
  return h;
}

/* A crafted copy of buf: 8 bytes at `at` replaced by v, the checksum made
 * right again. */
static void craft(unsigned char *dst, const unsigned char *buf, int64_t size, size_t at,
                  const void *v) {
  memcpy(dst, buf, (size_t)size);
  memcpy(dst + at, v, 8);
  const uint64_t sum = fnv1a(dst, (size_t)size - 8);
  memcpy(dst + size - 8, &sum, 8);
}

START_TEST(hostile_buffers) {
  char msg[B2B_ERRMSG_LEN] = "";
  static unsigned char r0[REC_CAP], r1[REC_CAP];
  arc_scene a;
  arc_setup(&a, B2B_CURVE_HERMITE_NODAL);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 2e3);
  dist d;
  run_to_migration(&d, &a, p);
  b2b_model *m1 = d.m[1];
  int64_t size;
  unsigned char *buf = pack0(&d, &size);
  unsigned char *bad = malloc((size_t)size + 64);
  const size_t n0 = record(m1, r0);
  int ch = 7;
  /* calls */
  expect(b2b_model_migration_unpack(m1, buf, size, NULL, msg, sizeof msg), B2B_ERR_NULL, msg, "changed");
  expect(b2b_model_migration_unpack(NULL, buf, size, &ch, msg, sizeof msg), B2B_ERR_NULL, msg, "model");
  expect(b2b_model_migration_unpack(m1, NULL, 5, &ch, msg, sizeof msg), B2B_ERR_NULL, msg, "buffer");
  expect(b2b_model_migration_unpack(m1, buf, -1, &ch, msg, sizeof msg), B2B_ERR_SIZE, msg, "size");
  expect(b2b_model_migration_pack(d.m[0], 0, bad, size - 1, msg, sizeof msg), B2B_ERR_SIZE, msg, "needs");
  expect(b2b_model_migration_pack(d.m[0], 0, NULL, size, msg, sizeof msg), B2B_ERR_NULL, msg, "buffer");
  expect(b2b_model_migration_pack(d.m[0], 1, bad, size, msg, sizeof msg), B2B_ERR_RANGE, msg, "does not exist");
  expect(b2b_model_migration_info(d.m[0], -1, NULL, NULL, msg, sizeof msg), B2B_ERR_RANGE, msg, "does not exist");
  int64_t g[4] = {-7, -7, -7, -7};
  expect(b2b_model_get_contact_global(m1, 5, g, msg, sizeof msg), B2B_ERR_RANGE, msg, "does not exist");
  expect(b2b_model_get_contact_global(m1, 0, NULL, msg, sizeof msg), B2B_ERR_NULL, msg, "pair");
  ck_assert(g[0] == -7 && g[3] == -7);
  /* the target is rank 1's: rank 0 does not evaluate it */
  expect(b2b_model_migration_unpack(d.m[0], buf, size, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
         "not one this model evaluates");
  /* every byte flipped in turn, every truncation, trailing bytes */
  for (int64_t k = 0; k < size; ++k) {
    memcpy(bad, buf, (size_t)size);
    bad[k] ^= 0xFF;
    const int st = b2b_model_migration_unpack(m1, bad, size, &ch, msg, sizeof msg);
    ck_assert_msg(st == B2B_ERR_RANGE && ch == 7, "byte %lld flipped: status %d, changed %d",
                  (long long)k, st, ch);
  }
  for (int64_t k = 0; k < size; ++k) {
    const int st = b2b_model_migration_unpack(m1, buf, k, &ch, msg, sizeof msg);
    ck_assert_msg(st == B2B_ERR_RANGE && ch == 7, "truncated to %lld: status %d", (long long)k, st);
  }
  memcpy(bad, buf, (size_t)size);
  memset(bad + size, 0, 64);
  expect(b2b_model_migration_unpack(m1, bad, size + 8, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg, "size");
  /* crafted fields with a right checksum */
  struct { size_t at; int64_t v; const char *word; } cases[] = {
      {16, 2, "format version"},
      {24, -1, "global id"},
      {56, 7, "not held"},           /* target A: global beam 7 */
      {64, 999, "not held"},         /* target A: segment 999 */
      {88, 5000, "hop count"},
      {96, 3, "groups"},             /* groups (3, 1) */
      {112, 12345, "parameters"},    /* the parameters' fingerprint */
      {120, 8, "history length"},
      {128, 2, "could not have written"},  /* history tag 2 */
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
    craft(bad, buf, size, cases[c].at, &cases[c].v);
    expect(b2b_model_migration_unpack(m1, bad, size, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
           cases[c].word);
    ck_assert_int_eq(ch, 7);
  }
  /* target B on A's beam, segment 12 (rank 1's): one beam, self-contact off */
  {
    const int64_t beam0 = 0, seg12 = 12;
    unsigned char *two = malloc((size_t)size);
    craft(two, buf, size, 72, &beam0);
    craft(bad, two, size, 80, &seg12);
    free(two);
    expect(b2b_model_migration_unpack(m1, bad, size, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
           "never pairs");
  }
  /* a normal of length 2 in the history */
  {
    const double two = 2.0;
    craft(bad, buf, size, 128 + 8 * 2, &two);
    expect(b2b_model_migration_unpack(m1, bad, size, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
           "could not have written");
  }
  /* a restart buffer is no packed contact */
  int64_t rs;
  ok(b2b_model_save_size(d.m[0], &rs, msg, sizeof msg), msg);
  unsigned char *rbuf = malloc((size_t)rs);
  ok(b2b_model_save(d.m[0], rbuf, rs, msg, sizeof msg), msg);
  expect(b2b_model_migration_unpack(m1, rbuf, rs, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
         "not a packed b2b contact");
  free(rbuf);
  /* a contact of a model with other parameters (friction 0.4) */
  {
    b2b_params *q = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.4, 2e3);
    arc_scene a2;
    arc_setup(&a2, B2B_CURVE_HERMITE_NODAL);
    dist d2;
    run_to_migration(&d2, &a2, q);
    int64_t s2;
    unsigned char *b2 = pack0(&d2, &s2);
    expect(b2b_model_migration_unpack(m1, b2, s2, &ch, msg, sizeof msg), B2B_ERR_RANGE, msg,
           "parameters differ");
    free(b2);
    dist_free(&d2);
    b2b_params_destroy(&q);
  }
  ck_assert_int_eq(ch, 7);
  /* nothing of it reached the model */
  ok(b2b_model_update(m1, a.x, 3, a.sc.n_nodes, 1, msg, sizeof msg), msg);
  ck_assert(record(m1, r1) == n0 && memcmp(r0, r1, n0) == 0);
  free(bad);
  free(buf);
  dist_free(&d);
  b2b_params_destroy(&p);
}
END_TEST

/* ---------------------------------------------------------------------------
 * 5. The audit and the crossing count of rank models.
 * ------------------------------------------------------------------------- */
typedef struct {
  int64_t g[4];
  double overlap;
  int reason;
} finding;

/* The findings of a rank model in global ids (local beam -> piece). */
static int rank_findings(const dist *d, int r, finding *out, int max) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n;
  ok(b2b_model_audit(d->m[r], 0.01, &n, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
  ck_assert_int_le(n, max);
  int pairs[4 * 256], reasons[256];
  double overlap[256];
  ok(b2b_model_audit(d->m[r], 0.01, &n, pairs, overlap, reasons, 256, msg, sizeof msg), msg);
  for (int k = 0; k < n; ++k) {
    /* a local (beam, segment) to global ids through a contact-free route:
     * the pieces as dist_build made them are in order, so count segments */
    for (int side = 0; side < 2; ++side) {
      const int lb = pairs[4 * k + 2 * side], ls = pairs[4 * k + 2 * side + 1];
      out[k].g[2 * side] = d->piece_gbeam[r][lb];
      out[k].g[2 * side + 1] = d->piece_first[r][lb] + ls;
    }
    out[k].overlap = overlap[k];
    out[k].reason = reasons[k];
  }
  return n;
}

START_TEST(audit_and_crossing) {
  char msg[B2B_ERRMSG_LEN] = "";
  /* beam 0 along x; beam 1 parallel to it, overlapping (PARALLEL findings);
   * beam 2 along y, above beam 0, pushed through it in one step (CROSSED) */
  enum { N0 = 11, N1 = 11, N2 = 7 };
  static double x[3 * (N0 + N1 + N2)];
  tst_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.n_beams = 3;
  sc.n_nodes = N0 + N1 + N2;
  sc.x = x;
  const int count[3] = {N0, N1, N2}, group[3] = {0, 1, 1};
  int first = 0;
  for (int b = 0; b < 3; ++b) {
    sc.first[b] = first;
    sc.count[b] = count[b];
    sc.kind[b] = B2B_CURVE_HERMITE_NODAL;
    sc.group[b] = group[b];
    sc.radius[b] = 0.1;
    sc.exclusion[b] = -1.0;
    first += count[b];
  }
  for (int k = 0; k < N0; ++k) {
    x[3 * k] = 0.3 * k;
    x[3 * k + 1] = x[3 * k + 2] = 0.0;
  }
  for (int k = 0; k < N1; ++k) {
    x[3 * (N0 + k)] = 0.3 * k + 0.05;
    x[3 * (N0 + k) + 1] = 0.15;  /* axes 0.15 apart, radii 0.1: overlap 0.05 */
    x[3 * (N0 + k) + 2] = 0.0;
  }
  for (int k = 0; k < N2; ++k) {
    x[3 * (N0 + N1 + k)] = 1.62;
    x[3 * (N0 + N1 + k) + 1] = 0.2 * (k - 3) - 0.6;
    x[3 * (N0 + N1 + k) + 2] = 0.25;
  }
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *single = tst_model(&sc, p, 0);
  ok(b2b_model_set_real(single, "search_margin", 0.05, msg, sizeof msg), msg);
  dist d;
  dist_init(&d, &sc, 2);
  for (int b = 0; b < 3; ++b)
    for (int s = 0; s < d.nseg[b]; ++s) d.owner[b][s] = b == 0 ? s * 2 / d.nseg[0] : 1 - (s & 1);
  dist_build(&d, p, 0, 1.0);
  for (int step = 0; step < 2; ++step) {
    if (step == 1)
      for (int k = 0; k < N2; ++k) x[3 * (N0 + N1 + k) + 2] = -0.18;  /* through beam 0 */
    tst_update(single, &sc, 1);
    dist_update(&d, x, sc.n_nodes, 1, NULL);
    compare(single, &d, step ? "crossed" : "parallel");  /* CROSSED summed too */
    int c1[16];
    ok(b2b_model_stats(single, c1, NULL, msg, sizeof msg), msg);
    ck_assert_int_eq(c1[B2B_COUNT_CROSSED], step);
    int n1, pairs1[4 * 256], reasons1[256];
    double overlap1[256];
    ok(b2b_model_audit(single, 0.01, &n1, pairs1, overlap1, reasons1, 256, msg, sizeof msg), msg);
    ck_assert_msg(n1 >= 8, "the parallel beams overlap (%d findings)", n1);
    finding f[MAXR][256];
    int nf[MAXR], total = 0;
    for (int r = 0; r < 2; ++r) total += nf[r] = rank_findings(&d, r, f[r], 256);
    ck_assert_int_eq(total, n1);
    for (int k = 0; k < n1; ++k) {
      int hits = 0;
      for (int r = 0; r < 2; ++r)
        for (int j = 0; j < nf[r]; ++j) {
          int same = 1;
          for (int i = 0; i < 4; ++i) same &= f[r][j].g[i] == pairs1[4 * k + i];
          if (!same) continue;
          ++hits;
          ck_assert(f[r][j].overlap == overlap1[k] && f[r][j].reason == reasons1[k]);
        }
      ck_assert_msg(hits == 1, "finding %d is on %d ranks", k, hits);
    }
    ok(b2b_model_commit(single, msg, sizeof msg), msg);
    dist_commit(&d);
  }
  dist_free(&d);
  b2b_model_destroy(&single);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_partition");
  TCase *tc = tcase_create("ranks");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, network_two_ranks);
  tcase_add_test(tc, network_three_ranks);
  tcase_add_test(tc, slide_across_ranks);
  tcase_add_test(tc, received_contacts);
  tcase_add_test(tc, rank_restart);
  tcase_add_test(tc, hostile_setup);
  tcase_add_test(tc, hostile_buffers);
  tcase_add_test(tc, audit_and_crossing);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
