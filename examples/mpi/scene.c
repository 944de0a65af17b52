/* The example's scenes (scene.h). */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static int alloc_nodes(scene *sc, int n_beams, const int *nodes_per_beam) {
  sc->n_beams = n_beams;
  sc->first_node = malloc(sizeof(int) * (size_t)(n_beams + 1));
  if (!sc->first_node) return 1;
  sc->first_node[0] = 0;
  for (int b = 0; b < n_beams; ++b) sc->first_node[b + 1] = sc->first_node[b] + nodes_per_beam[b];
  sc->n_nodes = sc->first_node[n_beams];
  sc->n_segments = sc->n_nodes - n_beams;
  sc->X = calloc((size_t)3 * (size_t)sc->n_nodes, sizeof(double));
  sc->anchor_k = calloc((size_t)3 * (size_t)sc->n_nodes, sizeof(double));
  return !sc->X || !sc->anchor_k;
}

void scene_free(scene *sc) {
  free(sc->first_node);
  free(sc->X);
  free(sc->anchor_k);
  memset(sc, 0, sizeof *sc);
}

/* Base beams 0 and 1 along x at y = -/+ 0.15 (20 segments of 0.1 from
 * x = -1 to 1, on a foundation k_f, their ends held by stiff anchors); the
 * slider, beam 2, along y at x = -0.22 (6 segments of 0.1), its axis 2r
 * above theirs (touching: the quadratic law's force starts at the
 * regularization gap), each node held in x and y by a drag spring whose
 * anchor moves +slide in x, loaded by press/7 down. Its contacts slide
 * across base nodes x = -0.2, -0.1, 0.0: the 2-rank cut is between. */
int scene_slide(scene *sc) {
  memset(sc, 0, sizeof *sc);
  sc->kind = SCENE_SLIDE;
  sc->name = "slide";
  const int nb = 21, ns = 7;
  const int per[3] = {nb, nb, ns};
  if (alloc_nodes(sc, 3, per)) return 1;
  sc->radius = 0.02;
  const double r = sc->radius;
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < nb; ++i) {
      const int k = sc->first_node[b] + i;
      sc->X[3 * k] = -1.0 + 0.1 * i;
      sc->X[3 * k + 1] = b == 0 ? -0.15 : 0.15;
      const double kf = (i == 0 || i == nb - 1) ? 1e5 : 2e3;
      for (int d = 0; d < 3; ++d) sc->anchor_k[3 * k + d] = kf;
    }
  sc->slider = 2;
  for (int j = 0; j < ns; ++j) {
    const int k = sc->first_node[2] + j;
    sc->X[3 * k] = -0.22;
    sc->X[3 * k + 1] = -0.3 + 0.1 * j;
    sc->X[3 * k + 2] = 2 * r;
    sc->anchor_k[3 * k] = 100.0;
    sc->anchor_k[3 * k + 1] = 100.0;
  }
  sc->EA = 1e3;
  sc->kb = 1.0;
  sc->penalty = 1e3;
  sc->reg_gap = 0.005;
  sc->mu = 0.3;
  sc->eps_t = 1e3;
  sc->press = 1.0;
  sc->slide = 0.3;
  sc->motion_margin = 0.3 + 2 * r; /* the slide, and the press */
  sc->search_margin = r;            /* b2b's default */
  /* t in [0, 1]: press; t in [1, 2]: slide */
  sc->t_end = 2.0;
  sc->n_steps = 17;
  sc->force_scale = sc->press;
  sc->direct_solver = 1;
  return 0;
}

static double urand(unsigned *s) { /* [0, 1) */
  *s = *s * 1664525u + 1013904223u;
  return (*s >> 8) / 16777216.0;
}

/* Layer l (of n_layers) at height z_l = l (2 r + gap): n_fibres fibres
 * side by side at spacing d, all along the layer's direction theta_l
 * (successive layers differ by 30..90 degrees, so fibres of adjacent layers
 * cross, and none of one layer touch), each wavy in the plane (amplitude
 * r, one or two waves) and raised by a fibre's own offset below gap/4.
 * Anchors: every node to its reference position mapped by z -> z_c + (1 -
 * t strain)(z - z_c), stiffness k_a: the layers are pressed together and
 * the crossings close. */
int scene_network(scene *sc, int n_layers, int n_fibres, int n_seg, unsigned seed) {
  memset(sc, 0, sizeof *sc);
  sc->kind = SCENE_NETWORK;
  sc->name = "network";
  const int n_beams = n_layers * n_fibres;
  int *per = malloc(sizeof(int) * (size_t)n_beams);
  if (!per) return 1;
  for (int b = 0; b < n_beams; ++b) per[b] = n_seg + 1;
  const int bad = alloc_nodes(sc, n_beams, per);
  free(per);
  if (bad) return 1;
  sc->radius = 0.01;
  const double r = sc->radius, gap = 0.1 * r, dz = 2 * r + gap, spacing = 5 * r, h = 5 * r;
  const double len = n_seg * h, width = (n_fibres - 1) * spacing;
  unsigned s = seed;
  double theta = 0.0;
  for (int l = 0; l < n_layers; ++l) {
    theta += (30.0 + 60.0 * urand(&s)) * PI / 180.0;
    const double c = cos(theta), sn = sin(theta);
    for (int f = 0; f < n_fibres; ++f) {
      const int b = l * n_fibres + f;
      const double off = -0.5 * width + f * spacing, lift = 0.25 * gap * urand(&s);
      const double waves = 1.0 + (urand(&s) < 0.5), phase = 2 * PI * urand(&s);
      for (int i = 0; i <= n_seg; ++i) {
        const int k = sc->first_node[b] + i;
        const double u = -0.5 * len + i * h;
        const double v = off + r * sin(2 * PI * waves * (u / len) + phase);
        /* the box is longer in x (the 2-rank cut's axis): stretch the layer's x by 1.5 */
        sc->X[3 * k] = 1.5 * (c * u - sn * v);
        sc->X[3 * k + 1] = sn * u + c * v;
        sc->X[3 * k + 2] = l * dz + lift;
        for (int d = 0; d < 3; ++d) sc->anchor_k[3 * k + d] = 20.0;
      }
    }
  }
  sc->zc = 0.5 * (n_layers - 1) * dz;
  sc->EA = 50.0;
  sc->kb = 0.02;
  sc->balance_reference = 1;
  sc->penalty = 2e3;
  sc->reg_gap = 0.1 * r;
  /* Coulomb friction, mu = 0.1, with a tangential penalty of the anchors'
   * stiffness. The contacts' tangential motions in a step are 1e-6 .. 3e-5
   * (the layers spread sideways as they are pressed); with eps_t = 2e3
   * (the normal penalty) the stick limit mu f_N / eps_t is ~2e-7, so they
   * slip by a few micro-units in directions that each Newton correction
   * (~1e-4) turned over: Newton alternated between two states (period 2,
   * |F| constant) at every step size down to 1/128 of the load. With eps_t = 20 the stick limit is
   * ~2e-5, and Newton converges as without friction (README, "Friction"). */
  sc->mu = 0.1;
  sc->eps_t = 20.0;
  sc->strain = 0.03;
  /* layers approach by strain dz; margin for that and the waviness' sway */
  sc->motion_margin = 2 * r;
  /* b2b's search margin: r / 5, not its default r. The narrow phase
   * evaluates every pair whose boxes come within 2 r + g0 + margin: a
   * crossing of two layers 2 r + 0.1 r apart is already within that, and a
   * larger margin only adds neighbours of the crossing segments (4800
   * segments: 137546 pairs evaluated per update with r, 106227 with r / 5,
   * for 2523 contacts; mpi_host -verbose prints the counts). The broad
   * phase is rebuilt when a node has moved s / 2 = 0.1 r: twice in the run. */
  sc->search_margin = 0.2 * r;
  sc->t_end = 1.0;
  /* two steps: 9 + 7 Newton iterations at 4800 segments, 10 + 11 at 24500,
   * against 9 + 8 + 7 and 9 + 8 + 14 in three; one step's first iterate
   * presses the layers too far (the linear solve fails there) */
  sc->n_steps = 2;
  sc->force_scale = 20.0 * sc->strain * dz;
  return 0;
}

void scene_load(const scene *sc, int k, double t, double a[3], double f[3]) {
  const double *X = sc->X + 3 * k;
  for (int d = 0; d < 3; ++d) {
    a[d] = X[d];
    f[d] = 0.0;
  }
  if (sc->kind == SCENE_SLIDE) {
    if (k >= sc->first_node[sc->slider]) {
      const int n = sc->first_node[sc->slider + 1] - sc->first_node[sc->slider];
      f[2] = -sc->press / n * (t < 1.0 ? t : 1.0);
      if (t > 1.0) a[0] += sc->slide * (t - 1.0);
    }
  } else {
    a[2] = sc->zc + (1.0 - t * sc->strain) * (X[2] - sc->zc);
  }
}
