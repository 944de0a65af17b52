/* Partitioning and each part's ghost layer and pieces (partition.h). */
#include "partition.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void partition_free(partition *pt) {
  free(pt->seg_owner);
  free(pt->node_owner);
  memset(pt, 0, sizeof *pt);
}

static void segment_mid(const scene *sc, int b, int s, double m[3]) {
  const double *a = sc->X + 3 * (sc->first_node[b] + s);
  for (int d = 0; d < 3; ++d) m[d] = 0.5 * (a[d] + a[d + 3]);
}

typedef struct {
  double key;
  int seg;
} keyed;

static int by_key(const void *a, const void *b) {
  const keyed *x = a, *y = b;
  if (x->key != y->key) return x->key < y->key ? -1 : 1;
  return (x->seg > y->seg) - (x->seg < y->seg); /* ties: global order */
}

/* Parts [p0, p0 + np) share the segments segs[0 .. n). */
static void rcb(const double *mid, keyed *segs, int n, int p0, int np, int *owner) {
  if (np == 1) {
    for (int i = 0; i < n; ++i) owner[segs[i].seg] = p0;
    return;
  }
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = fmin(lo[d], mid[3 * segs[i].seg + d]);
      hi[d] = fmax(hi[d], mid[3 * segs[i].seg + d]);
    }
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
  for (int i = 0; i < n; ++i) segs[i].key = mid[3 * segs[i].seg + axis];
  qsort(segs, (size_t)n, sizeof *segs, by_key);
  const int nl = np / 2;
  const int cut = (int)((int64_t)n * nl / np);
  rcb(mid, segs, cut, p0, nl, owner);
  rcb(mid, segs + cut, n - cut, p0 + nl, np - nl, owner);
}

int partition_rcb(const scene *sc, int n_parts, partition *pt) {
  memset(pt, 0, sizeof *pt);
  pt->n_parts = n_parts;
  const int ns = sc->n_segments;
  pt->seg_owner = malloc(sizeof(int) * (size_t)ns);
  pt->node_owner = malloc(sizeof(int) * (size_t)sc->n_nodes);
  double *mid = malloc(sizeof(double) * 3 * (size_t)ns);
  keyed *segs = malloc(sizeof(keyed) * (size_t)ns);
  if (!pt->seg_owner || !pt->node_owner || !mid || !segs) {
    free(mid);
    free(segs);
    return 1;
  }
  for (int b = 0; b < sc->n_beams; ++b)
    for (int s = 0; s < scene_beam_segments(sc, b); ++s)
      segment_mid(sc, b, s, mid + 3 * scene_segment(sc, b, s));
  for (int i = 0; i < ns; ++i) segs[i].seg = i;
  rcb(mid, segs, ns, 0, n_parts, pt->seg_owner);
  for (int b = 0; b < sc->n_beams; ++b) {
    const int nseg = scene_beam_segments(sc, b);
    for (int i = 0; i <= nseg; ++i)
      pt->node_owner[sc->first_node[b] + i] = pt->seg_owner[scene_segment(sc, b, i < nseg ? i : nseg - 1)];
  }
  free(mid);
  free(segs);
  return 0;
}

double partition_reach(const scene *sc) {
  return 2 * sc->radius + sc->reg_gap + sc->search_margin + sc->motion_margin;
}

/* The box of segment s of beam b: the nodes of its Hermite patch (s-1 .. s+2). */
static void segment_box(const scene *sc, int b, int s, double lo[3], double hi[3]) {
  const int nseg = scene_beam_segments(sc, b);
  for (int d = 0; d < 3; ++d) {
    lo[d] = INFINITY;
    hi[d] = -INFINITY;
  }
  for (int i = s - 1; i <= s + 2; ++i) {
    if (i < 0 || i > nseg) continue;
    const double *x = sc->X + 3 * (sc->first_node[b] + i);
    for (int d = 0; d < 3; ++d) {
      lo[d] = fmin(lo[d], x[d]);
      hi[d] = fmax(hi[d], x[d]);
    }
  }
}

typedef struct {
  int64_t cell;
  int seg;
} celled;

static int by_cell(const void *a, const void *b) {
  const celled *x = a, *y = b;
  if (x->cell != y->cell) return x->cell < y->cell ? -1 : 1;
  return (x->seg > y->seg) - (x->seg < y->seg);
}

int near_pairs(const scene *sc, double reach, void (*pair)(int i, int j, void *data), void *data) {
  const int ns = sc->n_segments;
  double *box = malloc(sizeof(double) * 6 * (size_t)ns);
  celled *cells = malloc(sizeof(celled) * (size_t)ns);
  if (!box || !cells) {
    free(box);
    free(cells);
    return 1;
  }
  double glo[3] = {INFINITY, INFINITY, INFINITY}, size = 0.0;
  for (int b = 0; b < sc->n_beams; ++b)
    for (int s = 0; s < scene_beam_segments(sc, b); ++s) {
      double *bx = box + 6 * scene_segment(sc, b, s);
      segment_box(sc, b, s, bx, bx + 3);
      for (int d = 0; d < 3; ++d) {
        glo[d] = fmin(glo[d], bx[d]);
        size = fmax(size, bx[3 + d] - bx[d]);
      }
    }
  /* a box's centre cell; boxes within reach have centres within size + reach per axis */
  const double c = size + reach;
  const int64_t M = 1 << 20;
  for (int i = 0; i < ns; ++i) {
    int64_t key = 0;
    for (int d = 0; d < 3; ++d) {
      const int64_t q = (int64_t)floor((0.5 * (box[6 * i + d] + box[6 * i + 3 + d]) - glo[d]) / c) + 1;
      key = key * M + q;
    }
    cells[i].cell = key;
    cells[i].seg = i;
  }
  qsort(cells, (size_t)ns, sizeof *cells, by_cell);
  for (int a = 0; a < ns; ++a) {
    const int i = cells[a].seg;
    const int64_t k = cells[a].cell;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const int64_t kk = k + (dx * M + dy) * M + dz;
          if (kk < k) continue; /* each pair of cells once; the same cell below */
          /* first entry of cell kk */
          int lo = 0, hi = ns;
          while (lo < hi) {
            const int m = (lo + hi) / 2;
            if (cells[m].cell < kk) lo = m + 1;
            else hi = m;
          }
          for (int e = lo; e < ns && cells[e].cell == kk; ++e) {
            const int j = cells[e].seg;
            if (kk == k && e <= a) continue;
            const double *bi = box + 6 * i, *bj = box + 6 * j;
            double d2 = 0.0;
            for (int d = 0; d < 3; ++d) {
              const double g = fmax(0.0, fmax(bi[d] - bj[3 + d], bj[d] - bi[3 + d]));
              d2 += g * g;
            }
            if (d2 <= reach * reach) pair(i < j ? i : j, i < j ? j : i, data);
          }
        }
  }
  free(box);
  free(cells);
  return 0;
}

typedef struct {
  const partition *pt;
  unsigned char **ghost;
} ghost_data;

static void mark_ghost(int i, int j, void *data) {
  ghost_data *g = data;
  const int pi = g->pt->seg_owner[i], pj = g->pt->seg_owner[j];
  if (pi == pj) return;
  g->ghost[pi][j] = 1;
  g->ghost[pj][i] = 1;
}

int ghost_flags(const scene *sc, const partition *pt, double reach, unsigned char **ghost) {
  for (int p = 0; p < pt->n_parts; ++p) memset(ghost[p], 0, (size_t)sc->n_segments);
  ghost_data g = {pt, ghost};
  return near_pairs(sc, reach, mark_ghost, &g);
}

void part_free(part *pp) {
  free(pp->seg_state);
  free(pp->pieces);
  free(pp->local_nodes);
  memset(pp, 0, sizeof *pp);
}

int part_build(const scene *sc, const partition *pt, int p, const unsigned char *ghost_of,
               part *out) {
  memset(out, 0, sizeof *out);
  out->rank = p;
  const int ns = sc->n_segments;
  unsigned char *st = out->seg_state = calloc((size_t)ns, 1);
  out->pieces = malloc(sizeof(piece) * (size_t)(ns + 1));
  unsigned char *node_in = calloc((size_t)sc->n_nodes, 1);
  if (!st || !out->pieces || !node_in) {
    free(node_in);
    return 1;
  }
  for (int i = 0; i < ns; ++i)
    st[i] = pt->seg_owner[i] == p ? SEG_OWN : ghost_of[i] ? SEG_GHOST : SEG_ABSENT;
  for (int b = 0; b < sc->n_beams; ++b) {
    const int nseg = scene_beam_segments(sc, b);
    unsigned char *s = st + scene_segment(sc, b, 0);
    /* gaps of 1 or 2 segments between needed runs become ghosts */
    int last = -1;
    for (int i = 0; i < nseg; ++i)
      if (s[i] != SEG_ABSENT) {
        if (last >= 0 && i - last - 1 >= 1 && i - last - 1 <= 2)
          for (int j = last + 1; j < i; ++j) s[j] = SEG_GHOST;
        last = i;
      }
    /* runs, each with a padding segment beyond a cut */
    for (int i = 0; i < nseg;) {
      if (s[i] == SEG_ABSENT || s[i] == SEG_PADDING) {
        ++i;
        continue;
      }
      int j = i;
      while (j < nseg && s[j] != SEG_ABSENT) ++j;
      piece pc = {b, i, j - i, 0, 0};
      /* the segment before the run lends its node to the run's first patch:
       * padding at a cut, or (the beam's first segment) a ghost, no cut */
      if (i > 0) {
        s[i - 1] = i - 1 == 0 ? SEG_GHOST : SEG_PADDING;
        pc.first_segment = i - 1;
        pc.n_segments++;
        pc.start_cut = i - 1 > 0;
      }
      if (j < nseg) {
        s[j] = j == nseg - 1 ? SEG_GHOST : SEG_PADDING;
        pc.n_segments++;
        pc.end_cut = j < nseg - 1;
      }
      out->pieces[out->n_pieces++] = pc;
      i = j + 1;
    }
    for (int i = 0; i < nseg; ++i) {
      if (s[i] == SEG_ABSENT) continue;
      node_in[sc->first_node[b] + i] = node_in[sc->first_node[b] + i + 1] = 1;
      if (s[i] == SEG_OWN) out->n_own_segments++;
      if (s[i] == SEG_GHOST) out->n_ghost_segments++;
      if (s[i] == SEG_PADDING) out->n_padding_segments++;
    }
  }
  int n_local = 0, n_own = 0;
  for (int k = 0; k < sc->n_nodes; ++k)
    if (node_in[k]) {
      ++n_local;
      n_own += pt->node_owner[k] == p;
    }
  out->local_nodes = malloc(sizeof(int) * (size_t)(n_local + 1));
  if (!out->local_nodes) {
    free(node_in);
    return 1;
  }
  int a = 0, g = n_own;
  for (int k = 0; k < sc->n_nodes; ++k)
    if (node_in[k]) out->local_nodes[pt->node_owner[k] == p ? a++ : g++] = k;
  out->n_own_nodes = n_own;
  out->n_local_nodes = n_local;
  free(node_in);
  return 0;
}
