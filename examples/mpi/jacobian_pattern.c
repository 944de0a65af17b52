/* The grown-only Jacobian pattern (jacobian_pattern.h). */
#include "jacobian_pattern.h"

#include <stdlib.h>
#include <string.h>

/* --- an open-addressing hash map of non-negative int64 keys to ints --- */

static uint64_t mix(uint64_t x) { /* splitmix64's finalizer */
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

static int set_alloc(key_set *s, size_t cap) {
  s->keys = malloc(sizeof(int64_t) * cap);
  s->vals = malloc(sizeof(int) * cap);
  if (!s->keys || !s->vals) return 1;
  for (size_t i = 0; i < cap; ++i) s->keys[i] = -1;
  s->cap = cap;
  s->n = 0;
  return 0;
}

static void set_free(key_set *s) {
  free(s->keys);
  free(s->vals);
  memset(s, 0, sizeof *s);
}

/* The slot of key: where it is, or the empty slot where it would go. */
static size_t set_slot(const key_set *s, int64_t key) {
  size_t i = (size_t)(mix((uint64_t)key) & (s->cap - 1));
  while (s->keys[i] != -1 && s->keys[i] != key) i = (i + 1) & (s->cap - 1);
  return i;
}

/* Inserts key with value val if absent: *added = 1 then. Returns 1 on
 * allocation failure (the set unchanged). */
static int set_insert(key_set *s, int64_t key, int val, int *added) {
  if (2 * (s->n + 1) > s->cap) { /* at most half full */
    key_set t;
    if (set_alloc(&t, 2 * s->cap)) {
      set_free(&t);
      return 1;
    }
    for (size_t i = 0; i < s->cap; ++i)
      if (s->keys[i] != -1) {
        const size_t j = set_slot(&t, s->keys[i]);
        t.keys[j] = s->keys[i];
        t.vals[j] = s->vals[i];
      }
    t.n = s->n;
    set_free(s);
    *s = t;
  }
  const size_t i = set_slot(s, key);
  *added = s->keys[i] == -1;
  if (*added) {
    s->keys[i] = key;
    s->vals[i] = val;
    s->n++;
  }
  return 0;
}

/* --- the pattern --- */

int jac_pattern_init(jac_pattern *jp, MPI_Comm comm, int n_local, int n_own,
                     int64_t n_blocks_global, const int *block, const int *row_lo,
                     const int *row_hi) {
  memset(jp, 0, sizeof *jp);
  jp->comm = comm;
  jp->n_local = n_local;
  jp->n_own = n_own;
  jp->n_blocks_global = n_blocks_global;
  jp->block = block;
  jp->row_lo = row_lo;
  jp->row_hi = row_hi;
  jp->d_count = calloc((size_t)n_local + 1, sizeof(PetscInt));
  jp->o_count = calloc((size_t)n_local + 1, sizeof(PetscInt));
  if (!jp->d_count || !jp->o_count || set_alloc(&jp->pairs, 1024) ||
      set_alloc(&jp->blocks, 1024))
    return 1;
  return 0;
}

void jac_pattern_free(jac_pattern *jp) {
  set_free(&jp->pairs);
  set_free(&jp->blocks);
  free(jp->pair_nodes);
  free(jp->d_count);
  free(jp->o_count);
  memset(jp, 0, sizeof *jp);
}

int jac_pattern_add_element(jac_pattern *jp, const int *nodes, int n) {
  for (int a = 0; a < n; ++a) {
    const int r = nodes[a];
    if (r < 0) continue;
    for (int b = 0; b < n; ++b) {
      const int c = nodes[b];
      if (c < 0) continue;
      const int64_t br = jp->block[r], bc = jp->block[c];
      int added = 0;
      if (set_insert(&jp->blocks, br * jp->n_blocks_global + bc, 0, &added)) return 1;
      if (added) {
        if (bc >= jp->row_lo[r] && bc < jp->row_hi[r]) jp->d_count[r]++;
        else jp->o_count[r]++;
      }
    }
  }
  return 0;
}

int jac_pattern_add_pair(jac_pattern *jp, int64_t key, const int nodes[8], int *added) {
  if (set_insert(&jp->pairs, key, jp->n_pairs, added)) return 1;
  if (!*added) return 0;
  if (jp->n_pairs == jp->cap_pairs) {
    const int cap = jp->cap_pairs ? 2 * jp->cap_pairs : 1024;
    int *p = realloc(jp->pair_nodes, sizeof(int) * 8 * (size_t)cap);
    if (!p) return 1;
    jp->pair_nodes = p;
    jp->cap_pairs = cap;
  }
  memcpy(jp->pair_nodes + 8 * (size_t)jp->n_pairs, nodes, sizeof(int) * 8);
  jp->n_pairs++;
  jp->n_new++;
  return jac_pattern_add_element(jp, nodes, 8);
}

PetscErrorCode jac_pattern_matrix(jac_pattern *jp, MatType type, Mat *J) {
  const PetscInt no = jp->n_own, N = (PetscInt)jp->n_blocks_global;
  /* each row's counts summed on its owner */
  Vec c;
  PetscCall(VecCreateMPI(jp->comm, 2 * no, 2 * N, &c));
  PetscCall(VecSet(c, 0.0));
  for (int l = 0; l < jp->n_local; ++l) {
    if (!jp->d_count[l] && !jp->o_count[l]) continue;
    const PetscInt idx[2] = {2 * (PetscInt)jp->block[l], 2 * (PetscInt)jp->block[l] + 1};
    const PetscScalar v[2] = {(PetscScalar)jp->d_count[l], (PetscScalar)jp->o_count[l]};
    PetscCall(VecSetValues(c, 2, idx, v, ADD_VALUES));
  }
  PetscCall(VecAssemblyBegin(c));
  PetscCall(VecAssemblyEnd(c));
  PetscInt *d, *o;
  PetscCall(PetscMalloc2(no + 1, &d, no + 1, &o));
  const PetscScalar *a;
  PetscCall(VecGetArrayRead(c, &a));
  for (PetscInt l = 0; l < no; ++l) {
    /* own local node l is block row row_lo + l; two ranks may have added the same block */
    d[l] = PetscMin((PetscInt)(a[2 * l] + 0.5), no);
    o[l] = PetscMin((PetscInt)(a[2 * l + 1] + 0.5), N - no);
  }
  PetscCall(VecRestoreArrayRead(c, &a));
  PetscCall(VecDestroy(&c));
  PetscCall(MatCreate(jp->comm, J));
  PetscCall(MatSetSizes(*J, 3 * no, 3 * no, 3 * N, 3 * N));
  PetscCall(MatSetType(*J, type));
  PetscCall(MatSetBlockSize(*J, 3));
  PetscCall(MatXAIJSetPreallocation(*J, 3, d, o, NULL, NULL));
  PetscCall(PetscFree2(d, o));
  /* every assembly sends a subset of the first one's off-process entries */
  PetscCall(MatSetOption(*J, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE));
  static const PetscScalar zeros[576];
  for (int p = 0; p < jp->n_pairs; ++p) {
    PetscInt idx[8];
    for (int s = 0; s < 8; ++s) {
      const int l = jp->pair_nodes[8 * p + s];
      idx[s] = l < 0 ? -1 : jp->block[l];
    }
    PetscCall(MatSetValuesBlocked(*J, 8, idx, 8, idx, zeros, ADD_VALUES));
  }
  jp->n_new = 0;
  return 0;
}
