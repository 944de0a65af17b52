/* The example's scenes, built the same on every rank (the host's "mesh",
 * replicated at setup; b2b and the solve see only each rank's part):
 * global beams (open chains of global nodes), their reference coordinates,
 * element constants, anchor springs and the load path. */
#ifndef MPI_SCENE_H
#define MPI_SCENE_H

#include <stdint.h>

enum { SCENE_SLIDE = 0, SCENE_NETWORK = 1 };

typedef struct {
  int kind;
  const char *name;
  int n_beams;
  int *first_node;   /* n_beams + 1: node i of beam b is global node first_node[b] + i */
  int n_nodes, n_segments;
  double *X;         /* 3 * n_nodes reference coordinates */
  double radius;
  double EA, kb;     /* axial stiffness EA, bending constant kb (beam_element.h) */
  int balance_reference; /* 1: the reference is curved; each element's forces there are
                            subtracted, so the reference is stress-free */
  double *anchor_k;  /* 3 * n_nodes: stiffness of each dof's anchor spring */
  /* contact (b2b_params): quadratic law */
  double penalty, reg_gap, mu, eps_t;
  double motion_margin; /* the most any two segments approach over the run (ghost layer) */
  double search_margin; /* b2b's "search_margin" on every rank's model (the same everywhere) */
  /* load path over t in [0, t_end] (scene_load) */
  double t_end;
  int n_steps;       /* nominal load steps */
  double force_scale; /* for the convergence test */
  int direct_solver;  /* 1: MUMPS LU; 0: GMRES + block Jacobi ILU(0) (fe_host.c) */
  /* scene data */
  double press, slide;            /* slide: total press force, slide distance */
  int slider;                     /* slide: the slider's global beam */
  double strain;                  /* network: compressive strain in z */
  double zc;                      /* network: the box's mid-height */
} scene;

/* Segment s of beam b as one flat index, and back. */
static inline int scene_segment(const scene *sc, int b, int s) { return sc->first_node[b] - b + s; }
static inline int scene_beam_segments(const scene *sc, int b) {
  return sc->first_node[b + 1] - sc->first_node[b] - 1;
}

/* The slide scene: two base beams on a weak foundation and a slider across
 * them pressed with force `press` and dragged `slide` along them. */
int scene_slide(scene *sc);
/* The fibre network: n_layers layers of n_fibres curved fibres of n_seg
 * segments each (n_layers * n_fibres * n_seg segments), compressed by
 * `strain` in z through anchor springs. */
int scene_network(scene *sc, int n_layers, int n_fibres, int n_seg, unsigned seed);
void scene_free(scene *sc);

/* Anchor position a[3] and external force f[3] of node k at load parameter t. */
void scene_load(const scene *sc, int k, double t, double a[3], double f[3]);

#endif
