/* lib/analysis/basins_atlas.c — the atlas of a basin computation: cells of
 * the section visited by classified seed trajectories, with their class
 * (cell recurrence: Datseris & Wagemakers, Chaos 32, 023104, 2022; see
 * whirl/basins.h).  The seeds are classified in parallel, each on its own,
 * and their cells are entered in seed order afterwards, so the atlas does
 * not depend on the number of threads.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "basins_impl.h"

#define EMPTY (-2)
#define MIXED (-1)

struct whirl_basins_atlas {
  size_t n, nk, npoints, fine, levels, nheld; /* nk = n + 1: a cell's key
                              is its n indices and the section phase */
  int *held_which;         /* classes of the points g = j*fine, j < nheld */
  unsigned *held_periods;
  double *lo, *h;          /* cell i of coordinate k: lo + [i, i+1) h */
  size_t cap, used;        /* hash table of cells (cap a power of 2) */
  int32_t *keys;           /* cap * n cell indices */
  signed char *cls;        /* EMPTY, MIXED or the class */
  /* what its rounds classify (borrowed until the last round is entered) */
  const whirl_problem *prob;
  const double *p, *x0;
  const whirl_attractor *att;
  size_t natt, entered;    /* rounds entered */
  whirl_basins_options o;
};

static uint64_t hash_key(const int32_t *q, size_t n) {
  uint64_t h = 0xcbf29ce484222325ULL; /* FNV-1a over the indices */
  for (size_t i = 0; i < n; ++i) {
    h ^= (uint32_t)q[i];
    h *= 0x100000001b3ULL;
    h ^= h >> 29;
  }
  return h;
}

static void cell_of(const whirl_basins_atlas *a, const double *x, size_t phase, int32_t *q) {
  for (size_t i = 0; i < a->n; ++i) {
    double c = floor((x[i] - a->lo[i]) / a->h[i]);
    q[i] = c > INT32_MAX / 2 ? INT32_MAX / 2 : c < INT32_MIN / 2 ? INT32_MIN / 2 : (int32_t)c;
  }
  q[a->n] = (int32_t)phase;
}

/* The slot of cell q: its own, or the empty one where it would go. */
static size_t slot_of(const whirl_basins_atlas *a, const int32_t *q) {
  size_t s = (size_t)hash_key(q, a->nk) & (a->cap - 1);
  while (a->cls[s] != EMPTY && memcmp(a->keys + s * a->nk, q, a->nk * sizeof *q))
    s = (s + 1) & (a->cap - 1);
  return s;
}

static int grow(whirl_basins_atlas *a, size_t want) {
  size_t cap = a->cap ? a->cap : 16;
  while (cap < 2 * want + 16) cap *= 2;
  if (cap == a->cap) return WHIRL_OK;
  int32_t *ok = a->keys;
  signed char *oc = a->cls;
  size_t ocap = a->cap;
  a->keys = malloc(cap * a->nk * sizeof *a->keys);
  a->cls = malloc(cap);
  if (!a->keys || !a->cls) {
    free(a->keys);
    free(a->cls);
    a->keys = ok, a->cls = oc;
    return WHIRL_ENOMEM;
  }
  memset(a->cls, EMPTY, cap);
  a->cap = cap;
  for (size_t s = 0; s < ocap; ++s) /* rehash the cells as they are */
    if (oc[s] != EMPTY) {
      size_t t = slot_of(a, ok + s * a->nk);
      memcpy(a->keys + t * a->nk, ok + s * a->nk, a->nk * sizeof *ok);
      a->cls[t] = oc[s];
    }
  free(ok);
  free(oc);
  return WHIRL_OK;
}

/* x: a recorded state, its n coordinates and its phase. */
static void insert(whirl_basins_atlas *a, const double *x, int which) {
  int32_t q[64], *qq = a->nk <= 64 ? q : malloc(a->nk * sizeof *qq);
  if (!qq) return; /* a cell left out only makes the atlas say less */
  cell_of(a, x, (size_t)x[a->n], qq);
  size_t s = slot_of(a, qq);
  if (a->cls[s] == EMPTY) {
    memcpy(a->keys + s * a->nk, qq, a->nk * sizeof *qq);
    a->cls[s] = (signed char)which;
    ++a->used;
  } else if (a->cls[s] != which) {
    a->cls[s] = MIXED;
  }
  if (qq != q) free(qq);
}

static int cell_class(const whirl_basins_atlas *a, const int32_t *q) {
  return a->cls[slot_of(a, q)];
}

int basins_atlas_lookup(const whirl_basins_atlas *a, const double *x, size_t phase) {
  if (!a || a->used == 0) return -1;
  int32_t q[64], *qq = a->nk <= 64 ? q : malloc(a->nk * sizeof *qq);
  if (!qq) return -1;
  cell_of(a, x, phase, qq);
  int c = cell_class(a, qq);
  for (size_t i = 0; c >= 0 && i < a->n; ++i)
    for (int d = -1; d <= 1 && c >= 0; d += 2) {
      qq[i] += d;
      int cn = cell_class(a, qq);
      if (cn != EMPTY && cn != c) c = -1;
      qq[i] -= d;
    }
  if (qq != q) free(qq);
  return c < 0 ? -1 : c;
}

/* Cell sizes from the range of the recorded states of classified points. */
static void set_cells(whirl_basins_atlas *a, const basins_record *rec, const size_t *idx,
                      size_t m, size_t cells) {
  for (size_t i = 0; i < a->n; ++i) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t j = 0; j < m; ++j) {
      if (a->held_which[idx[j] / a->fine] < 0) continue;
      for (size_t k = 0; k < rec[j].m; ++k) {
        double v = rec[j].x[k * a->nk + i];
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
      }
    }
    if (!(hi > lo)) lo = isfinite(lo) ? lo - 0.5 : -0.5, hi = lo + 1.0;
    a->lo[i] = lo;
    a->h[i] = (hi - lo) / (double)cells;
  }
}

/* Enter the states of the classified points idx[0..m) in index order. */
static int enter(whirl_basins_atlas *a, const basins_record *rec, const size_t *idx, size_t m) {
  size_t total = a->used;
  for (size_t j = 0; j < m; ++j)
    if (a->held_which[idx[j] / a->fine] >= 0) total += rec[j].m;
  if (grow(a, total) != WHIRL_OK) return WHIRL_ENOMEM;
  for (size_t j = 0; j < m; ++j) {
    int w = a->held_which[idx[j] / a->fine];
    for (size_t k = 0; w >= 0 && k < rec[j].m; ++k) insert(a, rec[j].x + k * a->nk, w);
  }
  return WHIRL_OK;
}

/* Classify the points idx[0..m) in parallel, each with its record, its
 * class and periods; with the atlas as it is (use_atlas) or by the tests
 * alone. */
static int classify_level(const whirl_basins_atlas *a, const size_t *idx, size_t m,
                          int use_atlas, basins_record *rec, int *which, unsigned *periods) {
  const whirl_basins_options *o = &a->o;
  int status = WHIRL_OK;
#ifdef _OPENMP
  int nth = o->nthreads > 0 ? o->nthreads : omp_get_max_threads();
#pragma omp parallel num_threads(nth)
#endif
  {
    whirl_ode *ode = whirl_ode_alloc(a->prob, a->p);
    int my = ode ? whirl_ode_set_tolerances(ode, o->rtol, o->atol) : WHIRL_ENOMEM;
    if (my == WHIRL_OK && o->method != WHIRL_ODE_DOPRI5) my = whirl_ode_set_method(ode, o->method);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (size_t j = 0; j < m; ++j) {
      int w = WHIRL_BASIN_FAILED, by = 0;
      unsigned per = 0;
      rec[j].n = a->nk;
      if (my == WHIRL_OK)
        my = basins_classify_ex(ode, a->x0 + idx[j] * a->n, a->att, a->natt, o,
                                use_atlas ? a : NULL, &rec[j], &w, &per, &by);
      if (rec[j].oom) my = WHIRL_ENOMEM;
      which[j] = w;
      periods[j] = per;
    }
    whirl_ode_free(ode);
#ifdef _OPENMP
#pragma omp critical(whirl_basins_atlas_status)
#endif
    if (my != WHIRL_OK && status == WHIRL_OK) status = my;
  }
  return status;
}

/* The points of round r (0 = coarsest): multiples of fine·4^(levels−1−r)
 * that are not multiples of the next coarser stride.  Returns the count;
 * idx may be NULL. */
static size_t level_points(const whirl_basins_atlas *a, size_t r, size_t *idx) {
  size_t st = a->fine, m = 0;
  for (size_t k = r + 1; k < a->levels; ++k) st *= 4;
  for (size_t g = 0; g < a->npoints; g += st)
    if (r == 0 || g % (4 * st)) {
      if (idx) idx[m] = g;
      m++;
    }
  return m;
}

size_t whirl_basins_atlas_rounds(const whirl_basins_atlas *a) {
  return a && a->npoints ? a->levels : 0;
}

size_t whirl_basins_atlas_round_seeds(const whirl_basins_atlas *a, size_t r) {
  return a && r < whirl_basins_atlas_rounds(a) ? level_points(a, r, NULL) : 0;
}

/* A seed's part of a round's result: its class, periods and the count of
 * its section states (each nk doubles) that follow. */
typedef struct seed_head {
  int32_t which;
  uint32_t periods;
  uint64_t m;
} seed_head;

/* The seeds j0 .. j0 + count − 1 of round r, one after another. */
static int pack(const whirl_basins_atlas *a, const basins_record *rec, const int *which,
                const unsigned *per, size_t count, void **buf, size_t *len) {
  size_t total = 0;
  for (size_t j = 0; j < count; ++j) total += sizeof(seed_head) + rec[j].m * a->nk * sizeof(double);
  unsigned char *b = malloc(total ? total : 1), *c = b;
  if (!b) return WHIRL_ENOMEM;
  for (size_t j = 0; j < count; ++j) {
    const seed_head h = {which[j], per[j], rec[j].m};
    memcpy(c, &h, sizeof h);
    c += sizeof h;
    if (rec[j].m) memcpy(c, rec[j].x, rec[j].m * a->nk * sizeof(double));
    c += rec[j].m * a->nk * sizeof(double);
  }
  *buf = b;
  *len = total;
  return WHIRL_OK;
}

int whirl_basins_atlas_classify(const whirl_basins_atlas *a, size_t r, size_t j0, size_t count,
                                void **buf, size_t *len) {
  if (!a || !buf || !len || r >= whirl_basins_atlas_rounds(a) || r != a->entered ||
      j0 > whirl_basins_atlas_round_seeds(a, r) || count > whirl_basins_atlas_round_seeds(a, r) - j0)
    return WHIRL_EINVAL;
  *buf = NULL;
  *len = 0;
  size_t *idx = malloc((level_points(a, r, NULL) + 1) * sizeof *idx);
  basins_record *rec = calloc(count + 1, sizeof *rec);
  int *which = malloc((count + 1) * sizeof *which);
  unsigned *per = malloc((count + 1) * sizeof *per);
  int rc = idx && rec && which && per ? WHIRL_OK : WHIRL_ENOMEM;
  if (rc == WHIRL_OK) {
    level_points(a, r, idx);
    rc = classify_level(a, idx + j0, count, r > 0, rec, which, per);
  }
  if (rc == WHIRL_OK) rc = pack(a, rec, which, per, count, buf, len);
  for (size_t j = 0; rec && j < count; ++j) free(rec[j].x);
  free(idx);
  free(rec);
  free(which);
  free(per);
  return rc;
}

/* The records of round r's seeds from the parts, views into them (rec[j].x
 * points into a part, not copied): WHIRL_OK, or WHIRL_EINVAL when the parts
 * do not hold exactly the round's seeds. */
static int unpack(whirl_basins_atlas *a, const size_t *idx, size_t m, const void *const *parts,
                  const size_t *lens, size_t nparts, basins_record *rec) {
  size_t j = 0;
  for (size_t q = 0; q < nparts; ++q) {
    const unsigned char *c = parts[q], *end = c + lens[q];
    while (c < end) {
      seed_head h;
      if ((size_t)(end - c) < sizeof h || j >= m) return WHIRL_EINVAL;
      memcpy(&h, c, sizeof h);
      c += sizeof h;
      if (h.m > (size_t)(end - c) / (a->nk * sizeof(double))) return WHIRL_EINVAL;
      a->held_which[idx[j] / a->fine] = h.which;
      a->held_periods[idx[j] / a->fine] = h.periods;
      rec[j].x = (double *)(uintptr_t)c; /* read only */
      rec[j].m = (size_t)h.m;
      rec[j].n = a->nk;
      c += h.m * a->nk * sizeof(double);
      ++j;
    }
  }
  return j == m ? WHIRL_OK : WHIRL_EINVAL;
}

int whirl_basins_atlas_enter(whirl_basins_atlas *a, size_t r, const void *const *parts,
                             const size_t *lens, size_t nparts) {
  if (!a || (nparts && (!parts || !lens)) || r >= whirl_basins_atlas_rounds(a) || r != a->entered)
    return WHIRL_EINVAL;
  const size_t m = level_points(a, r, NULL);
  size_t *idx = malloc((m + 1) * sizeof *idx);
  basins_record *rec = calloc(m + 1, sizeof *rec);
  int rc = idx && rec ? WHIRL_OK : WHIRL_ENOMEM;
  /* the records are doubles: a part not aligned for them is copied */
  const void **al = calloc(nparts + 1, sizeof *al);
  void **copies = calloc(nparts + 1, sizeof *copies);
  if (!al || !copies) rc = WHIRL_ENOMEM;
  for (size_t q = 0; rc == WHIRL_OK && q < nparts; ++q) {
    al[q] = parts[q];
    if ((uintptr_t)parts[q] % sizeof(double) == 0) continue;
    if (!(copies[q] = malloc(lens[q] ? lens[q] : 1))) rc = WHIRL_ENOMEM;
    else al[q] = memcpy(copies[q], parts[q], lens[q]);
  }
  if (rc == WHIRL_OK) {
    level_points(a, r, idx);
    rc = unpack(a, idx, m, al, lens, nparts, rec);
  }
  if (rc == WHIRL_OK && r == 0) set_cells(a, rec, idx, m, a->o.cells ? a->o.cells : 64);
  if (rc == WHIRL_OK) rc = enter(a, rec, idx, m);
  if (rc == WHIRL_OK) a->entered++;
  for (size_t q = 0; copies && q < nparts; ++q) free(copies[q]);
  free(copies);
  free(al);
  free(idx);
  free(rec);
  return rc;
}

int whirl_basins_atlas_begin(const whirl_problem *prob, const double *p, size_t npoints,
                             const double *x0, const whirl_attractor *att, size_t natt,
                             const whirl_basins_options *o, whirl_basins_atlas **out,
                             char *errbuf, size_t errlen) {
  char dummy[1];
  if (!errbuf || errlen == 0) errbuf = dummy, errlen = sizeof dummy;
  if (!out) return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "basins atlas: missing argument");
  *out = NULL;
  int rc = basins_check(prob, p, npoints, x0, att, natt, o, errbuf, errlen);
  if (rc != WHIRL_OK) return rc;
  if (o->seed_stride == 0 || o->atlas_levels > 8)
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_EINVAL, "basins atlas: need seed_stride >= 1 "
                        "and atlas_levels <= 8 (got %zu, %zu)", o->seed_stride, o->atlas_levels);
  whirl_basins_atlas *a = calloc(1, sizeof *a);
  if (!a) return WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "basins atlas: out of memory");
  a->n = prob->n;
  a->nk = prob->n + 1;
  a->npoints = npoints;
  a->fine = o->seed_stride;
  a->levels = o->atlas_levels ? o->atlas_levels : 1;
  a->nheld = npoints ? (npoints - 1) / a->fine + 1 : 1;
  a->prob = prob, a->p = p, a->x0 = x0, a->att = att, a->natt = natt;
  a->o = *o;
  a->o.fixed_horizon = 0;
  a->o.progress = NULL;
  a->held_which = malloc(a->nheld * sizeof *a->held_which);
  a->held_periods = malloc(a->nheld * sizeof *a->held_periods);
  a->lo = malloc(a->n * sizeof *a->lo);
  a->h = malloc(a->n * sizeof *a->h);
  if (!a->held_which || !a->held_periods || !a->lo || !a->h) {
    whirl_basins_atlas_free(a);
    return WHIRL_ERRMSG(errbuf, errlen, WHIRL_ENOMEM, "basins atlas: out of memory");
  }
  *out = a;
  return WHIRL_OK;
}

int whirl_basins_atlas_build(const whirl_problem *prob, const double *p, size_t npoints,
                             const double *x0, const whirl_attractor *att, size_t natt,
                             const whirl_basins_options *o, whirl_basins_atlas **out,
                             char *errbuf, size_t errlen) {
  whirl_basins_atlas *a;
  if (out) *out = NULL;
  int rc = whirl_basins_atlas_begin(prob, p, npoints, x0, att, natt, o, &a, errbuf, errlen);
  if (rc != WHIRL_OK) return rc;
  for (size_t r = 0; rc == WHIRL_OK && r < whirl_basins_atlas_rounds(a); ++r) {
    void *buf = NULL;
    size_t len = 0;
    rc = whirl_basins_atlas_classify(a, r, 0, whirl_basins_atlas_round_seeds(a, r), &buf, &len);
    const void *const parts[1] = {buf};
    if (rc == WHIRL_OK) rc = whirl_basins_atlas_enter(a, r, parts, &len, 1);
    free(buf);
  }
  if (rc != WHIRL_OK) {
    whirl_basins_atlas_free(a);
    char dummy[1];
    if (!errbuf || errlen == 0) errbuf = dummy, errlen = sizeof dummy;
    return WHIRL_ERRMSG(errbuf, errlen, rc, "basins atlas: %s", whirl_strerror(rc));
  }
  *out = a;
  return WHIRL_OK;
}

/* The seed's class if point g is a seed: 1 and *which, *periods. */
int basins_atlas_seed(const whirl_basins_atlas *a, size_t g, int *which, unsigned *periods) {
  if (!a || g >= a->npoints || g % a->fine) return 0;
  *which = a->held_which[g / a->fine];
  *periods = a->held_periods[g / a->fine];
  return 1;
}

size_t basins_atlas_points(const whirl_basins_atlas *a) { return a ? a->npoints : 0; }
size_t basins_atlas_dim(const whirl_basins_atlas *a) { return a ? a->n : 0; }

void whirl_basins_atlas_free(whirl_basins_atlas *a) {
  if (!a) return;
  free(a->held_which);
  free(a->held_periods);
  free(a->lo);
  free(a->h);
  free(a->keys);
  free(a->cls);
  free(a);
}

size_t whirl_basins_atlas_seeds(const whirl_basins_atlas *a) { return a ? a->nheld : 0; }
size_t whirl_basins_atlas_cells(const whirl_basins_atlas *a) { return a ? a->used : 0; }
