/* test/unit/t_spectrum.c — amplitude spectra and peaks (lib/analysis/
 * spectrum.c) and Poincaré-section classification (lib/analysis/section.c)
 * on constructed data whose answer is known in closed form: bin layout and
 * the Hann kernel on an exact bin, off-bin tones, two incommensurate tones
 * with combination tones, DC offset, deterministic noise and side lobes;
 * fixed points, cycles, invariant curves of irrational rotations, uniformly
 * filled areas, the Hénon attractor, and argument errors; the steady
 * state those points sample (whirl_steady_classify): fixed, period 3, a
 * long cycle, a quasiperiodic circle, an area, a converging spiral, a
 * diverging one, a record too short, a non-finite point.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/section.h>
#include <whirl/spectrum.h>

#include "../tap.h"

#define PI 3.14159265358979323846


/* x[i] = offset + Σ amp[j] cos(2π f[j] t_i + ph[j]), t_i = i dt */
static void tones(double *x, size_t m, double dt, double offset, size_t nt,
                  const double *f, const double *amp, const double *ph) {
  for (size_t i = 0; i < m; ++i) {
    const double t = (double)i * dt;
    double s = offset;
    for (size_t j = 0; j < nt; ++j)
      s += amp[j] * cos(2.0 * PI * f[j] * t + ph[j]);
    x[i] = s;
  }
}

/* ------------------------------------------------------------------------
 * Spectrum */

/* m = 1024, dt = 1/128: padded length 4·1024, bin 1/32; a tone with an
 * integer number of cycles in the record sits on a bin and the DFT-even Hann
 * kernel gives exactly A there, A/2 one resolution bin (4 bins) away and 0
 * at 2, 3, ... resolution bins. */
static void test_bins(void) {
  enum { M = 1024 };
  const double dt = 1.0 / 128.0, A = 0.8, f0 = 5.0; /* 40 cycles */
  double *x = malloc((M + 1) * sizeof *x);
  tones(x, M + 1, dt, 0.0, 1, &f0, &A, (const double[]){0.9});
  size_t nf = 0;
  ok(whirl_spectrum(x, M, dt, NULL, NULL, 0, &nf) == WHIRL_OK && nf == 2049,
     "size query: N = 4*1024 gives %zu = 2049 bins", nf);
  double *freq = malloc(nf * sizeof *freq), *amp = malloc(nf * sizeof *amp);
  size_t got = 0;
  ok(whirl_spectrum(x, M, dt, freq, amp, nf, &got) == WHIRL_OK && got == 2049,
     "spectrum fills 2049 bins");
  is_abs(freq[0], 0.0, 0.0, "freq[0] = 0");
  is_rel(freq[1], 1.0 / 32.0, 1e-15, "freq[1] = 1/(N dt) = 1/32");
  is_rel(freq[2048], 64.0, 1e-15, "last bin at Nyquist 1/(2 dt) = 64");
  is_rel(freq[160], f0, 1e-15, "bin 160 is 5");
  is_rel(amp[160], A, 1e-12,
         "on-bin tone: amplitude A (coherent gain corrected)");
  is_rel(amp[156], 0.5 * A, 1e-12, "Hann kernel: A/2 one resolution bin below");
  is_rel(amp[164], 0.5 * A, 1e-12, "Hann kernel: A/2 one resolution bin above");
  is_abs(amp[168], 0.0, 1e-13, "Hann kernel zero 2 resolution bins away");
  is_abs(amp[172], 0.0, 1e-13, "Hann kernel zero 3 resolution bins away");
  is_abs(amp[0], 0.0, 1e-13, "no DC for whole cycles");

  /* nmax below the full count: the lowest nmax bins */
  double f2[100], a2[100];
  ok(whirl_spectrum(x, M, dt, f2, a2, 100, &got) == WHIRL_OK && got == 100,
     "nmax = 100 returns 100 bins");
  int same = 1;
  for (size_t k = 0; k < 100; ++k)
    same = same && f2[k] == freq[k] && a2[k] == amp[k];
  ok(same, "truncated spectrum equals the first 100 bins");

  /* m just above a power of two: N = 4*2048 */
  ok(whirl_spectrum(x, 1025, dt, NULL, NULL, 0, &nf) == WHIRL_OK && nf == 4097,
     "m = 1025 pads to 8192: 4097 bins (got %zu)", nf);
  free(freq);
  free(amp);
  free(x);
}

/* an off-bin tone: frequency and amplitude from the Gaussian interpolation */
static void test_single_tone(void) {
  enum { M = 32000 };
  const double dt = 1.0 / 32.0;
  double *x = malloc(M * sizeof *x);
  const double fs[3] = {1.2345678, 3.00037, 0.51234};
  const double as[3] = {0.75, 2.5, 1e-3};
  for (int c = 0; c < 3; ++c) {
    tones(x, M, dt, 0.0, 1, &fs[c], &as[c], (const double[]){0.4 + c});
    whirl_peak p[4];
    size_t np = 99;
    int st = whirl_spectrum_peaks(x, M, dt, 1e-8, p, 4, &np);
    ok(st == WHIRL_OK && np == 1,
       "tone f=%g: one peak even at threshold 1e-8 (side lobes dropped), got "
       "%zu",
       fs[c], np);
    is_abs(p[0].freq, fs[c], 1e-6, "tone f=%g: frequency to 1e-6", fs[c]);
    is_rel(p[0].amp, as[c], 1e-4, "tone f=%g: amplitude %g to 1e-4", fs[c],
           as[c]);
  }
  /* a short record: the bias bound in resolution bins, 1/T = 1/31.25 */
  tones(x, 1000, dt, 0.0, 1, (const double[]){2.71828}, (const double[]){1.0},
        (const double[]){0.0});
  whirl_peak p;
  size_t np = 0;
  ok(whirl_spectrum_peaks(x, 1000, dt, 1e-3, &p, 1, &np) == WHIRL_OK && np == 1,
     "short record: a peak");
  is_abs(p.freq, 2.71828, 1e-3 / 31.25,
         "short record: frequency to 1e-3 resolution bin");
  is_rel(p.amp, 1.0, 5e-4, "short record: amplitude to 5e-4");
  free(x);
}

/* 1000 periods of f1 = 1 plus f2 = 0.2974 and combination tones, dt = 1/32 */
static void test_two_tones(void) {
  enum { M = 32000 };
  const double dt = 1.0 / 32.0;
  const double f[4] = {1.0, 0.2974, 1.0 - 0.2974, 1.0 + 0.2974};
  const double a[4] = {1.0, 0.3, 0.02, 0.005};
  const double ph[4] = {0.3, 1.1, 2.0, -0.7};
  double *x = malloc(M * sizeof *x);
  tones(x, M, dt, 0.0, 4, f, a, ph);
  whirl_peak p[8];
  size_t np = 0;
  int st = whirl_spectrum_peaks(x, M, dt, 1e-3, p, 8, &np);
  ok(st == WHIRL_OK && np == 4, "two tones + 2 combinations: 4 peaks (got %zu)",
     np);
  for (size_t j = 0; j < 4 && j < np; ++j) {
    is_rel(p[j].freq, f[j], 1e-5, "peak %zu: frequency %g to 1e-5", j, f[j]);
    is_rel(p[j].amp, a[j], 1e-3, "peak %zu: amplitude %g to 1e-3", j, a[j]);
  }
  whirl_peak q[2];
  ok(whirl_spectrum_peaks(x, M, dt, 1e-3, q, 2, &np) == WHIRL_OK && np == 2,
     "maxpeaks = 2 gives 2 peaks");
  ok(np == 2 && fabs(q[0].freq - 1.0) < 1e-5 && fabs(q[1].freq - 0.2974) < 1e-5,
     "maxpeaks = 2: the two largest, in order");
  ok(whirl_spectrum_peaks(x, M, dt, 0.1, p, 8, &np) == WHIRL_OK && np == 2,
     "threshold 0.1 keeps f1 and f2 only (got %zu)", np);
  ok(whirl_spectrum_peaks(x, M, dt, 1e-3, p, 0, &np) == WHIRL_OK && np == 0,
     "maxpeaks = 0: no peaks");
  free(x);
}

/* DC offset, constant record, noise, a weak tone next to a strong one */
static void test_offset_noise(void) {
  enum { M = 8192 };
  const double dt = 1.0 / 32.0;
  double *x = malloc(M * sizeof *x);
  tones(x, M, dt, 5.0, 1, (const double[]){2.3}, (const double[]){0.5},
        (const double[]){0.2});
  whirl_peak p[4];
  size_t np = 0;
  ok(whirl_spectrum_peaks(x, M, dt, 1e-3, p, 4, &np) == WHIRL_OK && np == 1,
     "offset 5 + tone: one peak (got %zu)", np);
  is_abs(p[0].freq, 2.3, 1e-5, "offset: tone frequency");
  is_rel(p[0].amp, 0.5, 1e-3, "offset: tone amplitude");
  size_t nf = 0;
  whirl_spectrum(x, M, dt, NULL, NULL, 0, &nf);
  double *fr = malloc(nf * sizeof *fr), *am = malloc(nf * sizeof *am);
  ok(whirl_spectrum(x, M, dt, fr, am, nf, &nf) == WHIRL_OK, "offset: spectrum");
  /* what is left of the DC bin is the tone's own leakage, ~1e-4 of it */
  is_abs(am[0], 0.0, 1e-3, "offset removed: DC bin below 1e-3 (offset 5)");

  for (size_t i = 0; i < M; ++i) x[i] = 3.0;
  ok(whirl_spectrum_peaks(x, M, dt, 1e-3, p, 4, &np) == WHIRL_OK && np == 0,
     "constant record: no peaks");

  /* tone + uniform noise of half-width 1e-2: the noise floor per bin is
   * ~1e-2 sqrt(2/M) ≈ 1.6e-4, well below the threshold 5e-3 */
  for (size_t i = 0; i < M; ++i)
    x[i] = cos(2.0 * PI * 1.1 * (double)i * dt) + tap_urand(-1e-2, 1e-2);
  ok(whirl_spectrum_peaks(x, M, dt, 5e-3, p, 4, &np) == WHIRL_OK && np == 1,
     "tone + noise: no spurious peak above 5e-3 (got %zu)", np);
  is_abs(p[0].freq, 1.1, 1e-4, "tone + noise: frequency");
  is_rel(p[0].amp, 1.0, 1e-2, "tone + noise: amplitude");

  /* a tone 10 times weaker, 5 resolution bins (5/256) away, is resolved */
  const double T = (double)M * dt, fa = 3.0, fb = 3.0 + 5.3 / T;
  tones(x, M, dt, 0.0, 2, (const double[]){fa, fb}, (const double[]){1.0, 0.1},
        (const double[]){0.0, 1.0});
  ok(whirl_spectrum_peaks(x, M, dt, 1e-3, p, 4, &np) == WHIRL_OK && np == 2,
     "weak tone 5.3 resolution bins away: 2 peaks (got %zu)", np);
  is_abs(p[1].freq, fb, 0.02 / T,
         "weak tone: frequency to 0.02 resolution bin");
  is_rel(p[1].amp, 0.1, 2e-2, "weak tone: amplitude to 2e-2");
  free(fr);
  free(am);
  free(x);
}

static void test_spectrum_errors(void) {
  double x[64], fr[200], am[200];
  whirl_peak p[4];
  size_t n = 0;
  for (size_t i = 0; i < 64; ++i) x[i] = sin(0.3 * (double)i);
  ok(whirl_spectrum_peaks(x, 64, 0.1, 1e-3, p, 4, &n) == WHIRL_OK,
     "64 samples: fine");
  ok(whirl_spectrum_peaks(x, 15, 0.1, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "m = 15: EINVAL");
  ok(whirl_spectrum_peaks(x, 64, 0.0, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "dt = 0: EINVAL");
  ok(whirl_spectrum_peaks(x, 64, -0.1, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "dt < 0: EINVAL");
  ok(whirl_spectrum_peaks(x, 64, NAN, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "dt NaN: EINVAL");
  ok(whirl_spectrum_peaks(x, 64, 0.1, -1.0, p, 4, &n) == WHIRL_EINVAL,
     "negative threshold: EINVAL");
  ok(whirl_spectrum_peaks(x, 64, 0.1, 1e-3, p, 4, NULL) == WHIRL_EINVAL,
     "npeaks NULL: EINVAL");
  ok(whirl_spectrum_peaks(NULL, 64, 0.1, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "x NULL: EINVAL");
  ok(whirl_spectrum(x, 15, 0.1, NULL, NULL, 0, &n) == WHIRL_EINVAL,
     "spectrum m = 15: EINVAL");
  ok(whirl_spectrum(x, 64, -1.0, fr, am, 200, &n) == WHIRL_EINVAL,
     "spectrum dt < 0: EINVAL");
  ok(whirl_spectrum(x, 64, 0.1, NULL, am, 200, &n) == WHIRL_EINVAL,
     "spectrum freq NULL, amp not: EINVAL");
  x[17] = NAN;
  ok(whirl_spectrum_peaks(x, 64, 0.1, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "NaN sample: EINVAL");
  ok(whirl_spectrum(x, 64, 0.1, fr, am, 200, &n) == WHIRL_EINVAL,
     "spectrum NaN: EINVAL");
  x[17] = INFINITY;
  ok(whirl_spectrum_peaks(x, 64, 0.1, 1e-3, p, 4, &n) == WHIRL_EINVAL,
     "Inf sample: EINVAL");
}

/* ------------------------------------------------------------------------
 * Poincaré sections */

static int classify(const double *pts, size_t n, size_t dim, double tol,
                    size_t kmax, whirl_section_kind *kind, size_t *per,
                    double *d) {
  *kind = (whirl_section_kind)-1;
  *per = 999;
  *d = -1.0;
  return whirl_section_classify(pts, n, dim, tol, kmax, kind, per, d);
}

static void test_fixed_periodic(void) {
  enum { N = 300 };
  double *p = malloc(3 * N * sizeof *p);
  whirl_section_kind kind;
  size_t per;
  double d;
  int st;
  for (size_t i = 0; i < N; ++i) {
    p[3 * i] = 0.3 + tap_urand(-1e-13, 1e-13);
    p[3 * i + 1] = -0.2 + tap_urand(-1e-13, 1e-13);
    p[3 * i + 2] = 1.1 + tap_urand(-1e-13, 1e-13);
  }
  st = classify(p, N, 3, 1e-9, 8, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_FIXED && per == 1 && d == 0.0,
     "constant points + 1e-13 noise: FIXED, period 1");
  st = classify(p, 2, 3, 1e-9, 1, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_FIXED,
     "two coincident points: FIXED");

  const double cyc[3][2] = {{1.0, 0.0}, {-0.5, 0.8}, {-0.4, -0.9}};
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = cyc[i % 3][0] + tap_urand(-1e-13, 1e-13);
    p[2 * i + 1] = cyc[i % 3][1] + tap_urand(-1e-13, 1e-13);
  }
  st = classify(p, N, 2, 1e-9, 8, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 3 && d == 0.0,
     "3-cycle: PERIODIC, period 3 (got kind %d period %zu)", (int)kind, per);
  st = classify(p, 6, 2, 1e-9, 3, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 3,
     "3-cycle, 6 points, max_period 3: period 3");
  st = classify(p, N, 2, 1e-9, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 0,
     "3-cycle with max_period 2: PERIODIC, period 0 (repeating points)");

  /* a 2-cycle drifting by 6e-10 per return (9e-8 in all, tolerance 2e-9):
   * |P_{i+2} − P_i| is always small, but the points do not repeat — two
   * lines of points, dimension 1 */
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = i % 2 ? 1.0 : -1.0;
    p[2 * i + 1] = 3e-10 * (double)i;
  }
  st = classify(p, N, 2, 1e-9, 8, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE && per == 0,
     "drifting 2-cycle: not periodic but CURVE (got kind %d period %zu)",
     (int)kind, per);
  is_rel(d, 1.0, 0.05, "drifting 2-cycle: dimension 1");

  /* a 7-cycle with max_period 5: PERIODIC, period 0 */
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = cos(2.0 * PI * 3.0 * (double)(i % 7) / 7.0);
    p[2 * i + 1] = sin(2.0 * PI * 3.0 * (double)(i % 7) / 7.0);
  }
  st = classify(p, N, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 0,
     "7-cycle with max_period 5: PERIODIC, period 0");
  st = classify(p, N, 2, 1e-9, 7, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 7,
     "7-cycle with max_period 7: period 7");

  /* a period-2 cycle whose points are 1e-6 apart: distinct at tol 1e-9,
   * coincident at tol 1e-5 */
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = 0.5 + (i % 2 ? 1e-6 : 0.0);
    p[2 * i + 1] = 0.5;
  }
  st = classify(p, N, 2, 1e-9, 8, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_PERIODIC && per == 2,
     "points 1e-6 apart, tol 1e-9: period 2");
  st = classify(p, N, 2, 1e-5, 8, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_FIXED,
     "points 1e-6 apart, tol 1e-5: FIXED");
  free(p);
}

/* closed curves through the points of an irrational rotation θ_{k+1} = θ_k
 * + 2πρ (the Poincaré section of a quasi-periodic orbit): dimension 1 */
static void test_curves(void) {
  enum { N = 20000 };
  double *p = malloc(3 * N * sizeof *p);
  whirl_section_kind kind;
  size_t per;
  double d;
  int st;

  /* ellipse with semi-axes 2 and 0.5, rotation number 0.2974 (as a period
   * ratio; 3000 points, so no repetition of 0.2974 = 1487/5000) */
  for (size_t i = 0; i < 3000; ++i) {
    const double th = 2.0 * PI * 0.2974 * (double)i;
    p[2 * i] = 2.0 * cos(th) + 0.3;
    p[2 * i + 1] = 0.5 * sin(th) - 1.0;
  }
  st = classify(p, 3000, 2, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE && per == 0,
     "rotation 0.2974 on an ellipse: CURVE (got kind %d, d = %g)", (int)kind,
     d);
  ok(d >= 0.8 && d <= 1.2, "ellipse: dimension %g in [0.8, 1.2]", d);

  /* golden-mean rotation on a wobbly closed curve; a 1st-neighbour
   * estimate would give d ≈ 20 at this N (three-distance theorem) */
  const double gold = 0.5 * (sqrt(5.0) - 1.0);
  for (size_t i = 0; i < 4000; ++i) {
    const double th = 2.0 * PI * gold * (double)i;
    const double r = 1.0 + 0.3 * cos(3.0 * th) + 0.1 * sin(5.0 * th);
    p[2 * i] = r * cos(th);
    p[2 * i + 1] = 0.7 * r * sin(th + 0.3 * sin(th));
  }
  st = classify(p, 4000, 2, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE,
     "golden rotation on a wobbly curve: CURVE (d = %g)", d);
  ok(d >= 0.8 && d <= 1.2, "wobbly curve: dimension %g in [0.8, 1.2]", d);

  /* a period-doubled torus: two ellipses visited in turn, each by a golden
   * rotation (every 4th point would lie on one of them only) */
  for (size_t i = 0; i < 4000; ++i) {
    const double th = 2.0 * PI * gold * (double)(i / 2);
    p[2 * i] = (i % 2 ? 1.5 : -1.5) + 0.5 * cos(th);
    p[2 * i + 1] = 0.3 * sin(th);
  }
  st = classify(p, 4000, 2, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE,
     "doubled torus (two curves in turn): CURVE (d = %g)", d);
  ok(d >= 0.8 && d <= 1.2, "doubled torus: dimension %g in [0.8, 1.2]", d);

  /* a trefoil knot in 3-D at angles 2π k (√2 − 1), 20000 points */
  const double rho = sqrt(2.0) - 1.0;
  for (size_t i = 0; i < N; ++i) {
    const double th = 2.0 * PI * rho * (double)i;
    p[3 * i] = sin(th) + 2.0 * sin(2.0 * th);
    p[3 * i + 1] = cos(th) - 2.0 * cos(2.0 * th);
    p[3 * i + 2] = -sin(3.0 * th);
  }
  st = classify(p, N, 3, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE,
     "20000 points on a trefoil knot in 3-D: CURVE (d = %g)", d);
  ok(d >= 0.8 && d <= 1.2, "3-D curve: dimension %g in [0.8, 1.2]", d);
  free(p);
}

/* uniformly filled areas (dimension 2) and the Hénon attractor */
static void test_irregular(void) {
  enum { N = 20000 };
  double *p = malloc(3 * N * sizeof *p);
  whirl_section_kind kind;
  size_t per;
  double d;
  int st;

  for (size_t i = 0; i < 4000; ++i) {
    p[2 * i] = tap_urand(0.0, 1.0);
    p[2 * i + 1] = tap_urand(0.0, 1.0);
  }
  st = classify(p, 4000, 2, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_IRREGULAR && per == 0,
     "4000 uniform points in a square: IRREGULAR (d = %g)", d);
  ok(d >= 1.7 && d <= 2.3, "square: dimension %g in [1.7, 2.3]", d);

  /* a 2-torus surface in 3-D, uniform in both angles, 20000 points */
  for (size_t i = 0; i < N; ++i) {
    const double u = tap_urand(0.0, 2.0 * PI), v = tap_urand(0.0, 2.0 * PI);
    p[3 * i] = (2.0 + 0.7 * cos(u)) * cos(v);
    p[3 * i + 1] = (2.0 + 0.7 * cos(u)) * sin(v);
    p[3 * i + 2] = 0.7 * sin(u);
  }
  st = classify(p, N, 3, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_IRREGULAR,
     "20000 points on a torus surface: IRREGULAR (d = %g)", d);
  ok(d >= 1.7 && d <= 2.3, "torus surface: dimension %g in [1.7, 2.3]", d);

  /* Hénon map a = 1.4, b = 0.3: correlation dimension 1.21 ± 0.01
   * (Grassberger & Procaccia 1983) — below 1.5, so the rule calls it a
   * curve; only the dimension is checked */
  double x = 0.1, y = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double xn = 1.0 - 1.4 * x * x + y;
    y = 0.3 * x;
    x = xn;
  }
  for (size_t i = 0; i < N; ++i) {
    const double xn = 1.0 - 1.4 * x * x + y;
    y = 0.3 * x;
    x = xn;
    p[2 * i] = x;
    p[2 * i + 1] = y;
  }
  st = classify(p, N, 2, 1e-9, 10, &kind, &per, &d);
  ok(st == WHIRL_OK, "Hénon attractor: classified");
  ok(d >= 1.05 && d <= 1.4, "Hénon: dimension %g in [1.05, 1.4] (1.21)", d);
  free(p);
}

static void test_section_errors(void) {
  double p[200];
  whirl_section_kind kind;
  size_t per;
  double d;
  int st;
  for (size_t i = 0; i < 100; ++i) {
    p[2 * i] = cos(2.0 * PI * 0.2974 * (double)i);
    p[2 * i + 1] = sin(2.0 * PI * 0.2974 * (double)i);
  }
  st = classify(p, 100, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE,
     "100 points on a circle: CURVE (d = %g)", d);
  st = classify(p, 40, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL,
     "40 aperiodic points (< 64 for the dimension): EINVAL");
  st = classify(p, 1, 2, 1e-9, 0, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "1 point: EINVAL");
  st = classify(p, 100, 2, 1e-9, 51, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "npts < 2 max_period: EINVAL");
  st = classify(p, 100, 0, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "dim 0: EINVAL");
  st = classify(p, 100, 2, -1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "tol < 0: EINVAL");
  st = classify(p, 100, 2, NAN, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "tol NaN: EINVAL");
  st = whirl_section_classify(p, 100, 2, 1e-9, 5, NULL, &per, &d);
  ok(st == WHIRL_EINVAL, "kind NULL: EINVAL");
  st = whirl_section_classify(NULL, 100, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "pts NULL: EINVAL");
  st = whirl_section_classify(p, 100, 2, 1e-9, 5, &kind, NULL, NULL);
  ok(st == WHIRL_OK && kind == WHIRL_SECTION_CURVE,
     "period, dimension NULL: fine");
  p[77] = NAN;
  st = classify(p, 100, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "NaN coordinate: EINVAL");
  p[77] = -INFINITY;
  st = classify(p, 100, 2, 1e-9, 5, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "-Inf coordinate: EINVAL");
}

/* ------------------------------------------------------------------------
 * Steady states */

static int steady(const double *pts, size_t n, size_t dim, whirl_steady_kind *kind,
                  size_t *per, double *d) {
  *kind = (whirl_steady_kind)-1;
  *per = 999;
  *d = -1.0;
  return whirl_steady_classify(pts, n, dim, 1e-6, 16, kind, per, d);
}

/* n points r_k (cos k th, sin k th), r_k = r0 g^k, in the plane */
static void spiral(double *p, size_t n, double r0, double g, double th) {
  double r = r0;
  for (size_t k = 0; k < n; ++k, r *= g) {
    p[2 * k] = r * cos(th * (double)k);
    p[2 * k + 1] = r * sin(th * (double)k);
  }
}

static void test_steady(void) {
  enum { N = 400 };
  double *p = malloc(4 * N * sizeof *p);
  whirl_steady_kind kind;
  size_t per;
  double d;
  int st;

  for (size_t i = 0; i < 4 * N; ++i) p[i] = (i % 4 == 0 ? 0.6 : 0.1) + tap_urand(-1e-12, 1e-12);
  st = steady(p, N, 4, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_FIXED && per == 1 && d == 0.0,
     "a fixed point (+ 1e-12 noise) in 4-d: FIXED, period 1 (got %s, %zu)",
     whirl_steady_kind_name(kind), per);

  const double cyc[3][2] = {{0.7, 0.1}, {-0.3, 0.5}, {-0.2, -0.6}};
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = cyc[i % 3][0];
    p[2 * i + 1] = cyc[i % 3][1];
  }
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_PERIODIC && per == 3,
     "a period-3 sequence: PERIODIC, period 3 (got %s, %zu)", whirl_steady_kind_name(kind), per);

  spiral(p, N, 1.0, 1.0, 2.0 * PI * 3.0 / 29.0);
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_PERIODIC && per == 0,
     "a 29-cycle (longer than 16): PERIODIC, period 0 (got %s, %zu)",
     whirl_steady_kind_name(kind), per);

  /* the golden rotation on a circle: never repeats, fills the circle */
  spiral(p, N, 1.0, 1.0, PI * (3.0 - sqrt(5.0)));
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_QUASIPERIODIC && per == 0 && fabs(d - 1.0) < 0.2,
     "a quasiperiodic circle: QUASIPERIODIC, dimension %g ~ 1 (got %s)", d,
     whirl_steady_kind_name(kind));

  for (size_t i = 0; i < 2 * N; ++i) p[i] = tap_urand(-1.0, 1.0);
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_IRREGULAR && d > 1.5,
     "points filling a square: IRREGULAR, dimension %g (got %s)", d, whirl_steady_kind_name(kind));

  /* converging: the steps shrink by 0.95^360 ~ 1e-8 over the record, too
   * slowly for the points to be one point within the tolerance */
  spiral(p, N, 1.0, 0.95, 2.0 * PI * 0.2974);
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_TRANSIENT && isfinite(d),
     "a converging spiral: TRANSIENT, not a curve (got %s, dimension %g)",
     whirl_steady_kind_name(kind), d);
  /* the same converging slowly (the steps shrink 100-fold): classified by
   * the shape of the set, not taken for a transient */
  spiral(p, N, 1.0, pow(0.01, 1.0 / 360.0), 2.0 * PI * 0.2974);
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && (kind == WHIRL_STEADY_QUASIPERIODIC || kind == WHIRL_STEADY_IRREGULAR),
     "a spiral converging 100-fold: not TRANSIENT (got %s)", whirl_steady_kind_name(kind));

  /* diverging: r_k = 1e-9 1.05^k, to 3e-1 */
  spiral(p, N, 1e-9, 1.05, 2.0 * PI * 0.2974);
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_DIVERGENT,
     "a diverging spiral: DIVERGENT (got %s)", whirl_steady_kind_name(kind));
  /* diverging on a line, x_k = 1.1^k (to 5e16) */
  for (size_t i = 0; i < N; ++i) {
    p[2 * i] = pow(1.1, (double)i);
    p[2 * i + 1] = 0.0;
  }
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_DIVERGENT,
     "x_k = 1.1^k: DIVERGENT (got %s)", whirl_steady_kind_name(kind));
  p[2 * 300] = INFINITY;
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_DIVERGENT && per == 0 && isnan(d),
     "an infinite point: DIVERGENT, dimension NaN (got %s)", whirl_steady_kind_name(kind));
  p[2 * 300] = NAN;
  st = steady(p, N, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_DIVERGENT, "a NaN point: DIVERGENT");

  spiral(p, N, 1.0, 1.0, PI * (3.0 - sqrt(5.0)));
  st = steady(p, WHIRL_STEADY_MIN_POINTS - 1, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_TRANSIENT && per == 0 && isnan(d),
     "63 points: TRANSIENT (too few to tell), dimension NaN");
  st = steady(p, WHIRL_STEADY_MIN_POINTS, 2, &kind, &per, &d);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_QUASIPERIODIC, "64 points of the circle: QUASIPERIODIC");

  st = whirl_steady_classify(NULL, N, 2, 1e-6, 16, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "pts NULL: EINVAL");
  st = whirl_steady_classify(p, N, 2, 1e-6, 16, NULL, &per, &d);
  ok(st == WHIRL_EINVAL, "kind NULL: EINVAL");
  st = whirl_steady_classify(p, N, 0, 1e-6, 16, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "dim 0: EINVAL");
  st = whirl_steady_classify(p, N, 2, -1.0, 16, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "tol < 0: EINVAL");
  st = whirl_steady_classify(p, 100, 2, 1e-6, 51, &kind, &per, &d);
  ok(st == WHIRL_EINVAL, "max_period > npts / 2: EINVAL");
  st = whirl_steady_classify(p, N, 2, 1e-6, 16, &kind, NULL, NULL);
  ok(st == WHIRL_OK && kind == WHIRL_STEADY_QUASIPERIODIC, "period, dimension NULL: fine");

  ok(!strcmp(whirl_steady_kind_name(WHIRL_STEADY_FIXED), "fixed") &&
         !strcmp(whirl_steady_kind_name(WHIRL_STEADY_QUASIPERIODIC), "quasiperiodic") &&
         !strcmp(whirl_steady_kind_name(WHIRL_STEADY_DIVERGENT), "divergent") &&
         !strcmp(whirl_steady_kind_name((whirl_steady_kind)42), "?"),
     "kind names");
  free(p);
}

int main(void) {
  test_bins();
  test_single_tone();
  test_two_tones();
  test_offset_noise();
  test_spectrum_errors();
  test_fixed_periodic();
  test_curves();
  test_irregular();
  test_section_errors();
  test_steady();
  return done_testing();
}
