/* test/unit/t_colloc_basis.c — the map of node values between collocation
 * meshes (lib/systems/colloc_basis.c), which carries a solution and its
 * directions onto an adapted mesh: a piecewise polynomial of degree NCOL
 * that is one polynomial on [0, 1] is reproduced exactly at the new
 * nodes (the closed form), and the plan applied to several vectors gives
 * the same bytes as colloc_basis_map_nodes vector by vector.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "systems/colloc_basis.h"
#include "tap.h"

static uint64_t state = 0x2545f4914f6cdd1dull;
static double uniform(void) { /* xorshift64, in [0, 1) */
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return (double)(state >> 11) / 9007199254740992.0;
}

/* a mesh of N intervals on [0, 1] with random lengths */
static void random_mesh(size_t N, double *mesh) {
  double s = 0.0;
  mesh[0] = 0.0;
  for (size_t i = 1; i <= N; ++i) mesh[i] = s += 0.2 + uniform();
  for (size_t i = 1; i < N; ++i) mesh[i] /= s;
  mesh[N] = 1.0;
}

/* component r of the polynomial at t: degree m, coefficients c[r][k] */
static double poly(const double *c, size_t m, double t) {
  double v = 0.0;
  for (size_t k = m + 1; k-- > 0;) v = v * t + c[k];
  return v;
}

/* node j's time on mesh (NCOL + 1 equally spaced nodes an interval) */
static double node_time(const double *mesh, size_t m, size_t j, size_t nnodes) {
  if (j == nnodes - 1) return 1.0;
  const size_t i = j / m, k = j % m;
  return mesh[i] + (mesh[i + 1] - mesh[i]) * (double)k / (double)m;
}

static void test_map(size_t n, size_t m, size_t N) {
  const size_t nnodes = N * m + 1;
  double *old = malloc((N + 1) * sizeof *old), *mesh = malloc((N + 1) * sizeof *mesh);
  double *v[3], *w[3], *copy = malloc(nnodes * n * sizeof *copy);
  double *L = malloc(nnodes * (m + 1) * sizeof *L), *c = malloc(n * (m + 1) * sizeof *c);
  size_t *idx = malloc(nnodes * sizeof *idx);
  random_mesh(N, old);
  random_mesh(N, mesh);
  for (size_t r = 0; r < n * (m + 1); ++r) c[r] = 2.0 * uniform() - 1.0;
  for (int q = 0; q < 3; ++q) {
    v[q] = malloc(nnodes * n * sizeof *v[q]);
    w[q] = malloc(nnodes * n * sizeof *w[q]);
    for (size_t j = 0; j < nnodes; ++j)
      for (size_t r = 0; r < n; ++r)
        v[q][n * j + r] = q == 0 ? poly(c + r * (m + 1), m, node_time(old, m, j, nnodes))
                                 : 2.0 * uniform() - 1.0;
    memcpy(w[q], v[q], nnodes * n * sizeof *v[q]);
  }
  colloc_basis_map_plan(m, N, old, mesh, idx, L);
  for (int q = 0; q < 3; ++q) {
    colloc_basis_map_apply(n, m, N, idx, L, copy, v[q]);
    colloc_basis_map_nodes(n, m, N, old, mesh, copy, w[q]);
  }
  double err = 0.0;
  for (size_t j = 0; j < nnodes; ++j)
    for (size_t r = 0; r < n; ++r)
      err = fmax(err, fabs(v[0][n * j + r] - poly(c + r * (m + 1), m, node_time(mesh, m, j, nnodes))));
  ok(err < 1e-12, "n %zu, NCOL %zu, NTST %zu: a polynomial of degree NCOL onto the new nodes "
     "exactly (max error %.1e)", n, m, N, err);
  int same = 1;
  for (int q = 0; q < 3; ++q) same &= !memcmp(v[q], w[q], nnodes * n * sizeof *v[q]);
  ok(same, "n %zu, NCOL %zu, NTST %zu: the plan applied to three vectors gives "
     "colloc_basis_map_nodes' bytes", n, m, N);
  /* on three threads, three vectors and two more: the same bytes again */
  double *u[5], *scr = malloc(3 * nnodes * n * sizeof *scr);
  for (int q = 0; q < 5; ++q) {
    u[q] = malloc(nnodes * n * sizeof *u[q]);
    for (size_t j = 0; j < nnodes * n; ++j) u[q][j] = 2.0 * uniform() - 1.0;
  }
  for (int q = 0; q < 3; ++q) memcpy(w[q], u[q], nnodes * n * sizeof *u[q]);
  colloc_basis_map_many(n, m, N, idx, L, scr, u, 3, u + 3, 2, 3);
  same = 1;
  for (int q = 0; q < 3; ++q) {
    colloc_basis_map_apply(n, m, N, idx, L, copy, w[q]);
    same &= !memcmp(u[q], w[q], nnodes * n * sizeof *u[q]);
  }
  for (size_t j = 0; j < nnodes * n; ++j) same &= u[3][j] != 0.0 || u[4][j] != 0.0;
  ok(same, "n %zu, NCOL %zu, NTST %zu: map_many on three threads gives map_apply's bytes",
     n, m, N);
  for (int q = 0; q < 5; ++q) free(u[q]);
  free(scr);
  for (int q = 0; q < 3; ++q) free(v[q]), free(w[q]);
  free(old), free(mesh), free(copy), free(L), free(c), free(idx);
}

int main(void) {
  test_map(1, 1, 3);
  test_map(2, 4, 20);
  test_map(5, 7, 33);
  test_map(3, 3, 200);
  return done_testing();
}
