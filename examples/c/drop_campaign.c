/* The drop campaign: no contact is lost in silence (issue 16, item 5).
 *
 * A small host of its own drives the contact model through random large
 * steps: beams of every curve kind, open and closed, each a rigid body that
 * translates (3 unknowns per beam, so the host's Newton system stays tiny),
 * hung on a spring (stiffness KS) from an anchor. Every step the anchors of
 * some beams jump by up to 12 radii towards the others, so the beams are
 * pushed onto and across each other; the host solves the equilibrium
 *   KS (u - a) + f_contact(u) = 0
 * by Newton with the model's exact tangent, in load increments that it
 * halves when Newton fails, and at random (a host's cut-back). After every
 * converged increment:
 *   - if the model counts beams whose axes passed through each other
 *     (B2B_COUNT_CROSSED), the increment is cut back, as b2b_model.h says;
 *   - else the interpenetration audit (b2b_model_audit: its own search and
 *     distances, independent of the active set) must find no pair that
 *     overlaps with no force. One it finds is a silent penetration, and the
 *     campaign fails. PARALLEL findings (beams within parallel_angle of each
 *     other, where point contact is undefined: line contact is its own
 *     issue) are counted and reported, not failures: the audit reports them.
 *   - then the increment is committed.
 *
 *   drop_campaign [--quick] [--steps N] [--seed S]
 * --quick: 150 converged increments (ctest); default: 10^4 (doc/guide-model.md, "Drop
 * campaign"). Exit 0 only with zero silent penetrations. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <b2b/b2b.h>

#define NB 6           /* beams */
#define MAXN 12        /* nodes per beam */
#define NDOF (3 * NB)  /* the host's unknowns */
#define RADIUS 0.05
#define KS 1.0         /* anchor springs */
#define PENALTY 1.0e3

static char msg[B2B_ERRMSG_LEN];

static void ok(int st, const char *what) {
  if (st != B2B_OK) {
    fprintf(stderr, "drop_campaign: %s failed (%d): %s\n", what, st, msg);
    exit(2);
  }
}

static uint64_t rng_state = 88172645463325252ULL;
static double uniform(double lo, double hi) {
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 7;
  rng_state ^= rng_state << 17;
  return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

typedef struct {
  int n_nodes, first[NB], count[NB];
  double x0[3 * NB * MAXN]; /* reference coordinates */
  int eq[3 * NB * MAXN];    /* node -> its beam's 3 unknowns */
} scene;

/* Beam b in cell b of a 3 x 2 grid of spacing 1.2: a ring (every third
 * beam) or an open, slightly bent polyline, in a random orientation. */
static void build_scene(scene *sc, b2b_model **mp, double mu) {
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), "create");
  int node = 0;
  for (int b = 0; b < NB; ++b) {
    const int closed = b % 3 == 2, n = closed ? 10 : 6 + b % 3;
    const double c[3] = {1.2 * (b % 3), 1.2 * (b / 3), 0.0};
    double e1[3], e2[3], e3[3];
    /* a random orthonormal frame */
    for (int i = 0; i < 3; ++i) e1[i] = uniform(-1, 1);
    double l = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int i = 0; i < 3; ++i) e1[i] /= l;
    const double t[3] = {0.3, -0.7, 0.65};
    e2[0] = e1[1] * t[2] - e1[2] * t[1];
    e2[1] = e1[2] * t[0] - e1[0] * t[2];
    e2[2] = e1[0] * t[1] - e1[1] * t[0];
    l = sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
    for (int i = 0; i < 3; ++i) e2[i] /= l;
    e3[0] = e1[1] * e2[2] - e1[2] * e2[1];
    e3[1] = e1[2] * e2[0] - e1[0] * e2[2];
    e3[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double bend = uniform(-0.3, 0.3);
    sc->first[b] = node;
    sc->count[b] = n;
    int nodes[MAXN];
    for (int k = 0; k < n; ++k, ++node) {
      double p, q;
      if (closed) {
        const double a = 2.0 * 3.14159265358979323846 * k / n;
        p = 0.35 * cos(a);
        q = 0.35 * sin(a);
      } else {
        p = -0.45 + 0.9 * k / (n - 1);
        q = bend * (p * p - 0.2);
      }
      for (int i = 0; i < 3; ++i) {
        sc->x0[3 * node + i] = c[i] + p * e1[i] + q * e2[i] + 0.0 * e3[i];
        sc->eq[3 * node + i] = 3 * b + i;
      }
      nodes[k] = node;
    }
    int beam;
    ok(b2b_model_add_beam(m, nodes, n, closed, RADIUS, b % B2B_CURVE_KIND_COUNT, b, &beam, msg,
                          sizeof msg),
       "add_beam");
  }
  sc->n_nodes = node;
  b2b_params *p = NULL;
  ok(b2b_params_create(&p, msg, sizeof msg), "params");
  ok(b2b_params_set_real(p, "penalty", PENALTY, msg, sizeof msg), "penalty");
  if (mu > 0.0) {
    ok(b2b_params_set_real(p, "friction", mu, msg, sizeof msg), "friction");
    ok(b2b_params_set_real(p, "tangential_penalty", PENALTY, msg, sizeof msg), "eps_T");
  }
  ok(b2b_params_finalize(p, msg, sizeof msg), "finalize params");
  for (int a = 0; a < NB; ++a)
    for (int b = a + 1; b < NB; ++b)
      ok(b2b_model_set_group_pair(m, a, b, p, msg, sizeof msg), "group pair");
  b2b_params_destroy(&p);
  ok(b2b_model_finalize(m, sc->n_nodes, msg, sizeof msg), "finalize");
  *mp = m;
}

static void coords(const scene *sc, const double *u, double *x) {
  for (int b = 0; b < NB; ++b)
    for (int k = sc->first[b]; k < sc->first[b] + sc->count[b]; ++k)
      for (int i = 0; i < 3; ++i) x[3 * k + i] = sc->x0[3 * k + i] + u[3 * b + i];
}

/* Solves A y = r (n x n, column-major, destroyed) by Gaussian elimination
 * with partial pivoting; 0 if singular. */
static int solve(double *A, double *r, int n) {
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int i = c + 1; i < n; ++i)
      if (fabs(A[i + n * c]) > fabs(A[p + n * c])) p = i;
    if (!(fabs(A[p + n * c]) > 0.0)) return 0;
    if (p != c) {
      for (int j = 0; j < n; ++j) {
        const double t = A[c + n * j];
        A[c + n * j] = A[p + n * j];
        A[p + n * j] = t;
      }
      const double t = r[c];
      r[c] = r[p];
      r[p] = t;
    }
    for (int i = c + 1; i < n; ++i) {
      const double f = A[i + n * c] / A[c + n * c];
      for (int j = c; j < n; ++j) A[i + n * j] -= f * A[c + n * j];
      r[i] -= f * r[c];
    }
  }
  for (int c = n - 1; c >= 0; --c) {
    for (int j = c + 1; j < n; ++j) r[c] -= A[c + n * j] * r[j];
    r[c] /= A[c + n * c];
  }
  return 1;
}

/* Newton on KS (u - a) + f_c(u) = 0 from u; 1 if converged. */
static int newton(b2b_model *m, const scene *sc, const double *a, double *u) {
  static double x[3 * NB * MAXN];
  for (int it = 0; it < 40; ++it) {
    coords(sc, u, x);
    if (b2b_model_update(m, x, 3, sc->n_nodes, 1, msg, sizeof msg) != B2B_OK) return 0;
    double r[NDOF], K[NDOF * NDOF];
    memset(K, 0, sizeof K);
    double scale = 1.0;
    for (int i = 0; i < NDOF; ++i) {
      r[i] = KS * (u[i] - a[i]);
      K[i + NDOF * i] = KS;
      scale = fmax(scale, fabs(KS * a[i]));
    }
    ok(b2b_model_add_residual(m, sc->eq, 3, 0, NDOF, r, msg, sizeof msg), "add_residual");
    ok(b2b_model_add_tangent_dense(m, sc->eq, 3, 0, NDOF, K, NDOF, msg, sizeof msg), "tangent");
    double nr = 0.0;
    for (int i = 0; i < NDOF; ++i) nr = fmax(nr, fabs(r[i]));
    if (nr <= 1e-9 * scale) return 1;
    for (int i = 0; i < NDOF; ++i) r[i] = -r[i];
    if (!solve(K, r, NDOF)) return 0;
    for (int i = 0; i < NDOF; ++i) u[i] += r[i];
  }
  return 0;
}

int main(int argc, char **argv) {
  int target = 10000;
  for (int k = 1; k < argc; ++k) {
    if (strcmp(argv[k], "--quick") == 0) target = 150;
    else if (strcmp(argv[k], "--steps") == 0 && k + 1 < argc) target = atoi(argv[++k]);
    else if (strcmp(argv[k], "--seed") == 0 && k + 1 < argc)
      rng_state ^= (uint64_t)strtoull(argv[++k], NULL, 10) * 0x9E3779B97F4A7C15ULL;
    else {
      fprintf(stderr, "usage: drop_campaign [--quick] [--steps N] [--seed S]\n");
      return 2;
    }
  }
  long converged = 0, crossed_cuts = 0, random_cuts = 0, newton_cuts = 0, abandoned = 0;
  long findings[6] = {0}, contacts_seen = 0, lost = 0, scenes = 0;
  static double x[3 * NB * MAXN];
  while (converged < target) {
    /* a scene per 500 increments, friction in every other one */
    scene sc;
    b2b_model *m = NULL;
    build_scene(&sc, &m, scenes % 2 ? 0.2 : 0.0);
    ++scenes;
    double u[NDOF] = {0}, a[NDOF] = {0};
    coords(&sc, u, x);
    ok(b2b_model_update(m, x, 3, sc.n_nodes, 0, msg, sizeof msg), "initial update");
    ok(b2b_model_commit(m, msg, sizeof msg), "initial commit");
    for (int step = 0; step < 50 && converged < target; ++step) {
      /* new anchors: some beams jump by up to 12 radii towards the centre */
      double a_new[NDOF];
      memcpy(a_new, a, sizeof a);
      for (int b = 0; b < NB; ++b) {
        if (uniform(0, 1) < 0.4) continue;
        const double c[3] = {1.2, 0.6, 0.0};
        for (int i = 0; i < 3; ++i) {
          const double home = 1.2 * (i == 0 ? b % 3 : (i == 1 ? b / 3 : 0));
          const double toward = c[i] - (home + a[3 * b + i]);
          a_new[3 * b + i] += 0.5 * toward * uniform(0, 1) + 12.0 * RADIUS * uniform(-0.5, 0.5);
        }
      }
      double lam = 0.0, dlam = 1.0;
      while (lam < 1.0) {
        dlam = fmin(dlam, 1.0 - lam);
        double a_try[NDOF], u_try[NDOF];
        for (int i = 0; i < NDOF; ++i) a_try[i] = a[i] + (lam + dlam) * (a_new[i] - a[i]);
        memcpy(u_try, u, sizeof u);
        int good = newton(m, &sc, a_try, u_try);
        int counts[16];
        if (good) {
          ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg), "stats");
          if (counts[B2B_COUNT_CROSSED] > 0) {
            ++crossed_cuts;
            good = 0;
          } else if (uniform(0, 1) < 0.1) {
            ++random_cuts;
            good = 0;
          }
        } else {
          ++newton_cuts;
        }
        if (!good) {
          ok(b2b_model_revert(m, msg, sizeof msg), "revert");
          dlam *= 0.5;
          if (dlam < 1.0 / 4096) {  /* give the jump up: back to where we are */
            ++abandoned;
            memcpy(a_new, a, sizeof a);
            for (int i = 0; i < NDOF; ++i) a_new[i] = a[i] + lam * (a_new[i] - a[i]);
            break;
          }
          continue;
        }
        /* converged and nothing crossed: the audit must be silent */
        int n_found = 0;
        ok(b2b_model_audit(m, 0.01, &n_found, NULL, NULL, NULL, 0, msg, sizeof msg), "audit");
        if (n_found > 0) {
          int pairs[4 * 64], reasons[64];
          double overlap[64];
          const int cap = n_found < 64 ? n_found : 64;
          if (n_found <= 64)
            ok(b2b_model_audit(m, 0.01, &n_found, pairs, overlap, reasons, cap, msg, sizeof msg),
               "audit");
          for (int k = 0; k < cap; ++k) {
            ++findings[reasons[k]];
            if (reasons[k] != B2B_AUDIT_PARALLEL)
              printf("silent penetration: scene %ld, step %d: beams %d/%d and %d/%d overlap by "
                     "%.3g with no force (reason %d)\n",
                     scenes, step, pairs[4 * k], pairs[4 * k + 1], pairs[4 * k + 2],
                     pairs[4 * k + 3], overlap[k], reasons[k]);
          }
        }
        contacts_seen += counts[B2B_COUNT_ACTIVE];
        lost += counts[B2B_COUNT_LOST];
        ok(b2b_model_commit(m, msg, sizeof msg), "commit");
        memcpy(u, u_try, sizeof u);
        lam += dlam;
        ++converged;
      }
      memcpy(a, a_new, sizeof a);
    }
    b2b_model_destroy(&m);
  }
  long silent = 0;
  for (int r = 0; r < 6; ++r)
    if (r != B2B_AUDIT_PARALLEL) silent += findings[r];
  printf("drop campaign: %ld scenes of %d beams (every curve kind, open and closed), %ld converged "
         "increments, %ld active contacts in them, %ld committed contacts lost\n",
         scenes, NB, converged, contacts_seen, lost);
  printf("  cut-backs: %ld crossed (B2B_COUNT_CROSSED), %ld Newton, %ld at random; %ld jumps "
         "abandoned\n",
         crossed_cuts, newton_cuts, random_cuts, abandoned);
  printf("  audit after every converged increment: %ld parallel overlaps (reported), %ld silent "
         "penetrations\n",
         findings[B2B_AUDIT_PARALLEL], silent);
  return silent == 0 ? 0 : 1;
}
