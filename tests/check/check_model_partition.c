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
#define MAXSEG 512
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
                          B2B_COUNT_PARALLEL};
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
  arc_scene a, a2;
  arc_setup(&a, kind);
  arc_setup(&a2, kind);
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
  (void)a2;
}

START_TEST(slide_across_ranks) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    slide_run(kind, 2);
    slide_run(kind, 3);
  }
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_partition");
  TCase *tc = tcase_create("ranks");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, network_two_ranks);
  tcase_add_test(tc, network_three_ranks);
  tcase_add_test(tc, slide_across_ranks);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
