/* Helpers of the model suites: scenes of beams as a host holds them (one
 * coordinate array, beams as node lists), models built from them, and the
 * brute-force reference (every allowed pair through b2b_pair_eval). */
#ifndef B2B_MODEL_SUPPORT_H
#define B2B_MODEL_SUPPORT_H

#include "pair_support.h"

#define TST_MAX_BEAMS 512

typedef struct {
  int n_beams, n_nodes;
  double *x;                     /* 3 x n_nodes */
  int first[TST_MAX_BEAMS];      /* first node of each beam (nodes are consecutive) */
  int count[TST_MAX_BEAMS];
  int closed[TST_MAX_BEAMS], kind[TST_MAX_BEAMS], group[TST_MAX_BEAMS], self[TST_MAX_BEAMS];
  double radius[TST_MAX_BEAMS];
  double exclusion[TST_MAX_BEAMS]; /* self-contact exclusion length */
} tst_scene;

/* n_fibres random fibres of nodes_per_fibre nodes (element length h) in a
 * cube of side box: random start and direction, turning up to max_turn per
 * node (0: straight); every closed_every-th fibre a ring (0: none), every
 * self_every-th with self-contact (0: none); kinds cycle through all of them;
 * groups alternate 0, 1. */
void tst_network(tst_rng *rng, int n_fibres, int nodes_per_fibre, double h, double box,
                 double radius, double max_turn, int closed_every, int self_every,
                 tst_scene *sc);
void tst_scene_free(tst_scene *sc);

/* A model of the scene: groups (0,0) and (0,1) interact with params, (1,1)
 * does not (unless all_pairs). Fails the test on error. */
b2b_model *tst_model(const tst_scene *sc, const b2b_params *params, int all_pairs);

/* b2b_model_update (fails the test on error). */
void tst_update(b2b_model *m, const tst_scene *sc, int want_tangent);

/* An active contact: beams and segments, residual and info. */
typedef struct {
  int pair[4];
  double residual[24], info[32];
} tst_contact;

/* Every allowed pair of the scene through b2b_pair_eval with fresh
 * histories: the active ones into out (at most max), in model order.
 * Returns the count. */
int tst_brute_force(const tst_scene *sc, const b2b_params *params, int all_pairs,
                    tst_contact *out, int max);

/* The model's contacts of the last update. Returns the count. */
int tst_model_contacts(const b2b_model *m, tst_contact *out, int max);

#endif

/* Everything the last update gives a host (counts, totals, every contact's
 * nodes, pair, info, residual and tangent if computed), flattened into buf
 * (at most cap bytes) for bitwise comparison. Returns the bytes used. */
size_t tst_model_record(const b2b_model *m, int with_tangent, unsigned char *buf, size_t cap);

/* Moves every node of the scene by step * v (v: 3 per node). */
void tst_scene_move(tst_scene *sc, const double *v, double step);
