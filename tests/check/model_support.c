#include "model_support.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tst_network(tst_rng *rng, int n_fibres, int nodes_per_fibre, double h, double box,
                 double radius, double max_turn, int closed_every, int self_every,
                 tst_scene *sc) {
  memset(sc, 0, sizeof *sc);
  ck_assert_int_le(n_fibres, TST_MAX_BEAMS);
  sc->n_beams = n_fibres;
  sc->n_nodes = n_fibres * nodes_per_fibre;
  sc->x = malloc(sizeof(double) * 3 * (size_t)sc->n_nodes);
  for (int f = 0; f < n_fibres; ++f) {
    const int closed = closed_every > 0 && f % closed_every == closed_every - 1;
    sc->first[f] = f * nodes_per_fibre;
    sc->count[f] = nodes_per_fibre;
    sc->closed[f] = closed;
    sc->kind[f] = f % B2B_CURVE_KIND_COUNT;
    sc->group[f] = f % 2;
    sc->self[f] = self_every > 0 && f % self_every == 0;
    sc->radius[f] = radius * tst_uniform(rng, 0.8, 1.2);
    sc->exclusion[f] = -1.0;
    double *x = sc->x + 3 * sc->first[f];
    if (closed) { /* a ring, tilted at random */
      const double R = nodes_per_fibre * h / (2.0 * 3.14159265358979);
      double c[3], u[3] = {1, 0, 0}, v[3], n[3];
      for (int i = 0; i < 3; ++i) c[i] = tst_uniform(rng, 0, box);
      for (int i = 0; i < 3; ++i) n[i] = tst_uniform(rng, -1, 1);
      /* u, v: an orthonormal pair normal to n */
      double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int i = 0; i < 3; ++i) n[i] /= nn;
      double d = u[0] * n[0];
      for (int i = 0; i < 3; ++i) u[i] -= d * n[i];
      nn = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      for (int i = 0; i < 3; ++i) u[i] /= nn;
      v[0] = n[1] * u[2] - n[2] * u[1];
      v[1] = n[2] * u[0] - n[0] * u[2];
      v[2] = n[0] * u[1] - n[1] * u[0];
      for (int k = 0; k < nodes_per_fibre; ++k) {
        const double t = 2.0 * 3.14159265358979 * k / nodes_per_fibre;
        for (int i = 0; i < 3; ++i) x[3 * k + i] = c[i] + R * (cos(t) * u[i] + sin(t) * v[i]);
      }
      continue;
    }
    double p[3], dir[3];
    for (int i = 0; i < 3; ++i) p[i] = tst_uniform(rng, 0, box);
    double nd;
    do {
      for (int i = 0; i < 3; ++i) dir[i] = tst_uniform(rng, -1, 1);
      nd = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    } while (nd < 0.1 || nd > 1.0);
    for (int i = 0; i < 3; ++i) dir[i] /= nd;
    for (int k = 0; k < nodes_per_fibre; ++k) {
      for (int i = 0; i < 3; ++i) x[3 * k + i] = p[i];
      /* turn the direction a little, then step */
      double w[3];
      for (int i = 0; i < 3; ++i) w[i] = dir[i] + max_turn * tst_uniform(rng, -1, 1);
      nd = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      for (int i = 0; i < 3; ++i) dir[i] = w[i] / nd;
      const double step = h * tst_uniform(rng, 0.7, 1.3);
      for (int i = 0; i < 3; ++i) p[i] += step * dir[i];
    }
  }
}

void tst_scene_free(tst_scene *sc) {
  free(sc->x);
  sc->x = NULL;
}

static void ok(int status, const char *msg) {
  ck_assert_msg(status == B2B_OK, "status %d: %s", status, msg);
}

b2b_model *tst_model(const tst_scene *sc, const b2b_params *params, int all_pairs) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  for (int b = 0; b < sc->n_beams; ++b) {
    int nodes[4096], beam;
    ck_assert_int_le(sc->count[b], 4096);
    for (int k = 0; k < sc->count[b]; ++k) nodes[k] = sc->first[b] + k;
    ok(b2b_model_add_beam(m, nodes, sc->count[b], sc->closed[b], sc->radius[b], sc->kind[b],
                          sc->group[b], &beam, msg, sizeof msg), msg);
    ck_assert_int_eq(beam, b);
    if (sc->self[b])
      ok(b2b_model_set_self_contact(m, b, 1, sc->exclusion[b], msg, sizeof msg), msg);
  }
  ok(b2b_model_set_group_pair(m, 0, 0, params, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 0, 1, params, msg, sizeof msg), msg);
  if (all_pairs) ok(b2b_model_set_group_pair(m, 1, 1, params, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, sc->n_nodes, msg, sizeof msg), msg);
  return m;
}

void tst_update(b2b_model *m, const tst_scene *sc, int want_tangent) {
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_model_update(m, sc->x, 3, sc->n_nodes, want_tangent, msg, sizeof msg), msg);
}

/* Patch of segment s of beam b with its rules; fills the host node numbers. */
static void patch_of(const tst_scene *sc, int b, int s, double X[12], int seg[3], int nodes[4]) {
  char msg[B2B_ERRMSG_LEN] = "";
  int local[4];
  ok(b2b_beam_segment_patch(sc->kind[b], sc->count[b], sc->closed[b], s, local, &seg[1], &seg[2],
                            msg, sizeof msg), msg);
  seg[0] = sc->kind[b];
  for (int k = 0; k < 4; ++k) {
    nodes[k] = local[k] < 0 ? -1 : sc->first[b] + local[k];
    for (int i = 0; i < 3; ++i) X[3 * k + i] = local[k] < 0 ? 0.0 : sc->x[3 * nodes[k] + i];
  }
}

static int n_segments(const tst_scene *sc, int b) {
  int n;
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_beam_segment_count(sc->kind[b], sc->count[b], sc->closed[b], &n, msg, sizeof msg), msg);
  return n;
}

/* A sphere that holds the segment's curve: around the centroid of its patch
 * nodes, through the farthest of them, grown by a third of the longest
 * element (a Hermite end tangent is at most half an element long, so the
 * Bezier control points lie within a third of an element of the nodes). */
static void bounding_sphere(const double X[12], const int nodes[4], double c[3], double *r) {
  int n = 0;
  c[0] = c[1] = c[2] = 0.0;
  for (int k = 0; k < 4; ++k)
    if (nodes[k] >= 0) {
      for (int i = 0; i < 3; ++i) c[i] += X[3 * k + i];
      ++n;
    }
  for (int i = 0; i < 3; ++i) c[i] /= n;
  double far = 0.0, longest = 0.0, prev[3];
  int have_prev = 0;
  for (int k = 0; k < 4; ++k) {
    if (nodes[k] < 0) continue;
    const double *p = X + 3 * k;
    const double d = sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
                          (p[2] - c[2]) * (p[2] - c[2]));
    if (d > far) far = d;
    if (have_prev) {
      const double l = sqrt((p[0] - prev[0]) * (p[0] - prev[0]) +
                            (p[1] - prev[1]) * (p[1] - prev[1]) + (p[2] - prev[2]) * (p[2] - prev[2]));
      if (l > longest) longest = l;
    }
    for (int i = 0; i < 3; ++i) prev[i] = p[i];
    have_prev = 1;
  }
  *r = far + longest / 3.0;
}

static int share(const int a[4], const int b[4]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (a[i] >= 0 && a[i] == b[j]) return 1;
  return 0;
}

/* Self-contact exclusion as the model documents it, for the nodal and linear
 * kinds (segment s spans nodes s .. s+1): the chord length between them. */
static int self_excluded(const tst_scene *sc, int b, int sa, int sb) {
  const int n = sc->count[b];
  double cum[4097];
  cum[0] = 0.0;
  const int last = sc->closed[b] ? n : n - 1;
  for (int k = 0; k < last; ++k) {
    const double *p = sc->x + 3 * (sc->first[b] + k);
    const double *q = sc->x + 3 * (sc->first[b] + (k + 1) % n);
    cum[k + 1] = cum[k] + sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
                               (q[2] - p[2]) * (q[2] - p[2]));
  }
  const double total = cum[last];
  double gap = cum[sb] - cum[sa + 1];
  if (gap < 0) gap = 0;
  if (sc->closed[b]) {
    double g2 = cum[sa] + total - cum[sb + 1];
    if (g2 < 0) g2 = 0;
    if (g2 < gap) gap = g2;
  }
  const double excl = sc->exclusion[b] >= 0 ? sc->exclusion[b] : 4.0 * sc->radius[b];
  return !(gap > excl);
}

/* The end-contact rule of the model (b2b_model.h, doc/contact-element.md
 * section 14), written again from its documentation: a pair whose free
 * evaluation is OUTSIDE holds a node of a segment that starts there (at a
 * beam start, or at a joint of two straight segments) or ends an open beam,
 * if the distance grows into the segment and into the one before the node;
 * the closest of the candidates wins. */
typedef struct {
  int start_held, end_held, has_prev;
  double prev_tangent[3];
} seg_ends;

static seg_ends ends_of(const tst_scene *sc, int b, int s, int n_seg) {
  seg_ends e = {0, 0, 0, {0, 0, 0}};
  const int closed = sc->closed[b];
  e.has_prev = closed || s > 0;
  e.end_held = !closed && s == n_seg - 1;
  if (!e.has_prev) {
    e.start_held = 1;
  } else if (sc->kind[b] == B2B_CURVE_LINEAR) {
    const int n = sc->count[b];
    const int k0 = sc->first[b] + (s - 1 + n) % n, k1 = sc->first[b] + s;
    for (int i = 0; i < 3; ++i)
      e.prev_tangent[i] = 0.5 * (sc->x[3 * k1 + i] - sc->x[3 * k0 + i]);
    e.start_held = 1;
  }
  return e;
}

static int held_end(double t, const seg_ends *e) {
  if (t < -1.0 && e->start_held) return -1;
  if (t >= 1.0 - 1e-12 && e->end_held) return 1;
  return 0;
}

static int node_closest(const int seg[3], const double X[12], int end, const seg_ends *e,
                        const double d[3]) {
  double x[9];
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_segment_eval(seg[0], seg[1], seg[2], X, NULL, (double)end, x, NULL, NULL, msg,
                      sizeof msg), msg);
  const double *t = x + 3;
  if (-end * (d[0] * t[0] + d[1] * t[1] + d[2] * t[2]) < 0.0) return 0;
  const double *p = e->prev_tangent;
  return !(end == -1 && e->has_prev && d[0] * p[0] + d[1] * p[1] + d[2] * p[2] > 0.0);
}

typedef struct {
  const b2b_params *params;
  const int *segs;
  const double *X, *radii, *h0;
  const seg_ends *ea, *eb;
  int nh, found;
  double best_dist;
  double trial_info[32]; /* of the last attempt */
  tst_contact best;
} end_search;

static int end_attempt(end_search *es, int ca, int cb) {
  char msg[B2B_ERRMSG_LEN] = "";
  const int ends[2] = {ca, cb};
  double h1[16];
  int status;
  tst_contact c;
  ok(b2b_pair_eval_ends(es->params, es->segs, es->X, NULL, es->radii, ends, es->h0, h1, es->nh,
                        &status, c.info, c.residual, NULL, 24, msg, sizeof msg), msg);
  memcpy(es->trial_info, c.info, sizeof c.info);
  if (status != B2B_CONTACT_ACTIVE && status != B2B_CONTACT_OPEN) return status;
  double d[3], e[3];
  for (int i = 0; i < 3; ++i) {
    d[i] = c.info[B2B_INFO_POINT_A + i] - c.info[B2B_INFO_POINT_B + i];
    e[i] = -d[i];
  }
  if (ca && !node_closest(es->segs, es->X, ca, es->ea, d)) return status;
  if (cb && !node_closest(es->segs + 3, es->X + 12, cb, es->eb, e)) return status;
  const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (es->found && !(dist < es->best_dist)) return status;
  es->found = 1;
  es->best_dist = dist;
  es->best = c;
  return status;
}

/* 1 and *c the end contact if the pair (free evaluation OUTSIDE with info)
 * owns one. */
static int end_contact(end_search *es, const double *info, tst_contact *c) {
  const int ca = held_end(info[B2B_INFO_XI], es->ea), cb = held_end(info[B2B_INFO_ETA], es->eb);
  if (ca && end_attempt(es, ca, 0) == B2B_CONTACT_OUTSIDE) {
    const int cb2 = held_end(es->trial_info[B2B_INFO_ETA], es->eb);
    if (cb2) end_attempt(es, ca, cb2);
  }
  if (cb && end_attempt(es, 0, cb) == B2B_CONTACT_OUTSIDE) {
    const int ca2 = held_end(es->trial_info[B2B_INFO_XI], es->ea);
    if (ca2) end_attempt(es, ca2, cb);
  }
  if (es->found) *c = es->best;
  return es->found;
}

int tst_brute_force(const tst_scene *sc, const b2b_params *params, int all_pairs,
                    tst_contact *out, int max) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nh;
  double g0;
  ok(b2b_params_history_size(params, &nh, msg, sizeof msg), msg);
  ok(b2b_params_get_real(params, "regularization_gap", &g0, msg, sizeof msg), msg);
  /* every segment's patch, rules, host nodes and bounding sphere, once */
  int total = 0, first_seg[TST_MAX_BEAMS + 1];
  for (int b = 0; b < sc->n_beams; ++b) {
    first_seg[b] = total;
    total += n_segments(sc, b);
  }
  first_seg[sc->n_beams] = total;
  double *X = malloc(sizeof(double) * 12 * (size_t)total), *sph = malloc(sizeof(double) * 4 * (size_t)total);
  int *rules = malloc(sizeof(int) * 3 * (size_t)total), *nodes = malloc(sizeof(int) * 4 * (size_t)total);
  for (int b = 0; b < sc->n_beams; ++b)
    for (int s = first_seg[b]; s < first_seg[b + 1]; ++s) {
      patch_of(sc, b, s - first_seg[b], X + 12 * s, rules + 3 * s, nodes + 4 * s);
      bounding_sphere(X + 12 * s, nodes + 4 * s, sph + 4 * s, sph + 4 * s + 3);
    }
  double h0[16] = {0}, h1[16];
  int found = 0;
  for (int ba = 0; ba < sc->n_beams; ++ba)
    for (int bb = ba; bb < sc->n_beams; ++bb) {
      if (sc->group[ba] == 1 && sc->group[bb] == 1 && !all_pairs) continue;
      if (ba == bb && !sc->self[ba]) continue;
      const double radii[2] = {sc->radius[ba], sc->radius[bb]};
      for (int ga = first_seg[ba]; ga < first_seg[ba + 1]; ++ga)
        for (int gb = (ba == bb ? ga + 1 : first_seg[bb]); gb < first_seg[bb + 1]; ++gb) {
          /* pairs that cannot touch: spheres around both curves farther apart
           * than the radii and the regularization gap (skipped for speed only) */
          const double *ca = sph + 4 * ga, *cb = sph + 4 * gb;
          const double dc = sqrt((ca[0] - cb[0]) * (ca[0] - cb[0]) + (ca[1] - cb[1]) * (ca[1] - cb[1]) +
                                 (ca[2] - cb[2]) * (ca[2] - cb[2]));
          if (dc > ca[3] + cb[3] + radii[0] + radii[1] + g0 + 1e-9) continue;
          if (share(nodes + 4 * ga, nodes + 4 * gb)) continue;
          const int sa = ga - first_seg[ba], sb = gb - first_seg[bb];
          if (ba == bb && self_excluded(sc, ba, sa, sb)) continue;
          double XX[24];
          int segs[6];
          memcpy(XX, X + 12 * ga, sizeof(double) * 12);
          memcpy(XX + 12, X + 12 * gb, sizeof(double) * 12);
          memcpy(segs, rules + 3 * ga, sizeof(int) * 3);
          memcpy(segs + 3, rules + 3 * gb, sizeof(int) * 3);
          int status;
          tst_contact c;
          ok(b2b_pair_eval(params, segs, XX, NULL, radii, h0, h1, nh, &status, c.info, c.residual,
                           NULL, 24, msg, sizeof msg), msg);
          if (status == B2B_CONTACT_OUTSIDE) {
            const seg_ends ea = ends_of(sc, ba, sa, first_seg[ba + 1] - first_seg[ba]);
            const seg_ends eb = ends_of(sc, bb, sb, first_seg[bb + 1] - first_seg[bb]);
            end_search es = {params, segs, XX, radii, h0, &ea, &eb, nh, 0, 0.0, {0}, c};
            if (end_contact(&es, c.info, &c)) status = c.info[B2B_INFO_NORMAL_FORCE] > 0.0
                                                          ? B2B_CONTACT_ACTIVE
                                                          : B2B_CONTACT_OPEN;
          }
          if (status != B2B_CONTACT_ACTIVE) continue;
          c.pair[0] = ba;
          c.pair[1] = sa;
          c.pair[2] = bb;
          c.pair[3] = sb;
          ck_assert_int_lt(found, max);
          out[found++] = c;
        }
    }
  free(X);
  free(sph);
  free(rules);
  free(nodes);
  return found;
}

int tst_model_contacts(const b2b_model *m, tst_contact *out, int max) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  ck_assert_int_le(n, max);
  for (int k = 0; k < n; ++k)
    ok(b2b_model_get_contact(m, k, NULL, out[k].pair, out[k].info, out[k].residual, NULL, 0, msg,
                             sizeof msg), msg);
  return n;
}

size_t tst_model_record(const b2b_model *m, int with_tangent, unsigned char *buf, size_t cap) {
  char msg[B2B_ERRMSG_LEN] = "";
  size_t used = 0;
#define PUT(ptr, bytes)                                  \
  do {                                                   \
    ck_assert_msg(used + (bytes) <= cap, "record full"); \
    memcpy(buf + used, (ptr), (bytes));                  \
    used += (bytes);                                     \
  } while (0)
  int counts[16], n;
  double totals[8];
  ok(b2b_model_stats(m, counts, totals, msg, sizeof msg), msg);
  /* the search counts depend on when the search ran, not on the results */
  counts[B2B_COUNT_CANDIDATES] = counts[B2B_COUNT_FAR] = counts[B2B_COUNT_SEARCH_BUILDS] = 0;
  counts[B2B_COUNT_EVALUATED] = counts[B2B_COUNT_OPEN] = counts[B2B_COUNT_OUTSIDE] = 0;
  counts[B2B_COUNT_PARALLEL] = counts[B2B_COUNT_NOT_CONVERGED] = 0;
  totals[B2B_TOTAL_MIN_GAP] = 0.0;
  PUT(counts, sizeof counts);
  PUT(totals, sizeof totals);
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  PUT(&n, sizeof n);
  for (int k = 0; k < n; ++k) {
    int nodes[8], pair[4];
    double info[32], res[24], K[576];
    ok(b2b_model_get_contact(m, k, nodes, pair, info, res, with_tangent ? K : NULL, 24, msg,
                             sizeof msg), msg);
    PUT(nodes, sizeof nodes);
    PUT(pair, sizeof pair);
    PUT(info, sizeof info);
    PUT(res, sizeof res);
    if (with_tangent) PUT(K, sizeof K);
  }
#undef PUT
  return used;
}

void tst_scene_move(tst_scene *sc, const double *v, double step) {
  for (int k = 0; k < 3 * sc->n_nodes; ++k) sc->x[k] += step * v[k];
}
