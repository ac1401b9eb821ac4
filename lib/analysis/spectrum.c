/* lib/analysis/spectrum.c — one-sided amplitude spectra of sampled time
 * histories and their dominant peaks (whirl/spectrum.h).  The window-
 * weighted mean is removed, a periodic ("DFT-even") Hann window applied,
 * the record zero-padded to SPEC_PAD times the next power of two and
 * transformed by an iterative radix-2 FFT; amplitudes are divided by half
 * the window sum (one-sided, coherent gain 0.5), so a sinusoid
 * A cos(2π f t) on a bin reads A.  Peak frequency and amplitude
 * are refined by a parabola through the logarithms of the three bins around a
 * local maximum (Gaussian interpolation); side lobes of larger peaks are
 * rejected by distance and by the Hann leakage envelope.
 *
 * References: J. W. Cooley, J. W. Tukey, Math. Comp. 19 (1965) 297–301
 * (radix-2 FFT); F. J. Harris, Proc. IEEE 66 (1978) 51–83 (Hann window, its
 * kernel and coherent gain); M. Gasior, J. L. Gonzalez, "Improving FFT
 * frequency measurement resolution by parabolic and Gaussian spectrum
 * interpolation", AIP Conf. Proc. 732 (2004) 276–285.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include <whirl/problem.h>
#include <whirl/spectrum.h>

/* Zero padding beyond the next power of two: the FFT bin spacing is at most
 * 1/SPEC_PAD of the resolution 1/(m dt), which makes the Gaussian interpolation
 * of a Hann-windowed peak accurate to 2e-4 of a resolution bin in frequency
 * and 1e-4 relative in amplitude (1.5e-2 and 3e-2 without padding, 1.5e-3
 * and 1.4e-3 with 2× padding). */
#define SPEC_PAD 4

/* Peaks closer than this many resolution bins 1/(m dt) to a larger one, or
 * to 0, are dropped (the Hann main lobe spans ±2 bins, its first side lobe
 * sits near 2.4 bins). */
#define SPEC_MIN_SEP 3.0

/* A peak farther away is still dropped when its amplitude is below this
 * multiple of the Hann leakage envelope of a larger peak. */
#define SPEC_LOBE_SAFETY 2.0

/* A spectrum whose largest amplitude is below SPEC_ROUNDING·DBL_EPSILON·
 * max|x| is rounding noise (the record is constant): no peaks. */
#define SPEC_ROUNDING 1000.0

/* ------------------------------------------------------------------------
 * FFT */

/* In-place forward DFT X_k = Σ x_n exp(−2πi nk/n) of z[2n] (interleaved
 * re, im), n a power of two ≥ 2: bit-reversal permutation followed by
 * log2(n) butterfly stages.  tw[2*(n/2)] holds exp(−2πi j/n), j < n/2. */
static void fft_radix2(double *z, size_t n, const double *tw) {
  for (size_t i = 1, j = 0; i < n; ++i) {
    size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j |= bit;
    if (i < j) {
      double t = z[2 * i];
      z[2 * i] = z[2 * j];
      z[2 * j] = t;
      t = z[2 * i + 1];
      z[2 * i + 1] = z[2 * j + 1];
      z[2 * j + 1] = t;
    }
  }
  for (size_t len = 2; len <= n; len <<= 1) {
    const size_t half = len >> 1, step = n / len;
    for (size_t s = 0; s < n; s += len) {
      for (size_t j = 0; j < half; ++j) {
        const double wr = tw[2 * j * step], wi = tw[2 * j * step + 1];
        double *a = z + 2 * (s + j), *b = z + 2 * (s + j + half);
        const double tr = wr * b[0] - wi * b[1];
        const double ti = wr * b[1] + wi * b[0];
        b[0] = a[0] - tr;
        b[1] = a[1] - ti;
        a[0] += tr;
        a[1] += ti;
      }
    }
  }
}

/* exp(−2πi j/n) for j < n/2, each from one cos/sin call (no recurrence, so
 * the twiddles carry no accumulated rounding error). */
static void fft_twiddles(double *tw, size_t n) {
  for (size_t j = 0; j < n / 2; ++j) {
    const double ang = 2.0 * WHIRL_PI * (double)j / (double)n;
    tw[2 * j] = cos(ang);
    tw[2 * j + 1] = -sin(ang);
  }
}

/* ------------------------------------------------------------------------
 * Spectrum */

static int check_input(const double *x, size_t m, double dt) {
  if (x == NULL || m < 16 || !(dt > 0.0) || !isfinite(dt)) return WHIRL_EINVAL;
  for (size_t i = 0; i < m; ++i)
    if (!isfinite(x[i])) return WHIRL_EINVAL;
  return WHIRL_OK;
}

/* Padded FFT length for m samples, or 0 when it would overflow. */
static size_t padded_length(size_t m) {
  size_t n = 1;
  while (n < m) {
    if (n > SIZE_MAX / 2) return 0;
    n <<= 1;
  }
  if (n > SIZE_MAX / (4 * SPEC_PAD * sizeof(double))) return 0;
  return n * SPEC_PAD;
}

/* Window-corrected one-sided amplitudes amp[n/2 + 1] of x[m] (validated),
 * n = padded_length(m).  amp is allocated here; the caller frees it. */
static int amplitude_spectrum(const double *x, size_t m, size_t n,
                              double **amp_out) {
  const size_t nf = n / 2 + 1;
  double *z = malloc(2 * n * sizeof *z);
  double *tw = malloc(n * sizeof *tw);
  double *amp = malloc(nf * sizeof *amp);
  if (z == NULL || tw == NULL || amp == NULL) {
    free(z);
    free(tw);
    free(amp);
    return WHIRL_ENOMEM;
  }
  /* the window-weighted mean: unlike the plain mean it leaves no DC in the
   * windowed record (bin 0 is exactly 0), whose Hann lobe would otherwise
   * show as a spurious peak near f = 0 of relative size ~1/(2π f T) */
  double wsum = 0.0, mean = 0.0;
  for (size_t i = 0; i < m; ++i) {
    const double w = 0.5 - 0.5 * cos(2.0 * WHIRL_PI * (double)i / (double)m);
    wsum += w;
    mean += w * x[i];
    z[2 * i] = w;
  }
  mean /= wsum;
  for (size_t i = 0; i < m; ++i) {
    z[2 * i] *= x[i] - mean;
    z[2 * i + 1] = 0.0;
  }
  for (size_t i = 2 * m; i < 2 * n; ++i) z[i] = 0.0;
  fft_twiddles(tw, n);
  fft_radix2(z, n, tw);
  for (size_t k = 0; k < nf; ++k) {
    const double g = (k == 0 || k == n / 2) ? 1.0 : 2.0;
    amp[k] = g * hypot(z[2 * k], z[2 * k + 1]) / wsum;
  }
  free(z);
  free(tw);
  *amp_out = amp;
  return WHIRL_OK;
}

int whirl_spectrum(const double *x, size_t m, double dt, double *freq,
                   double *amp, size_t nmax, size_t *nfreq) {
  if (nfreq == NULL || (freq == NULL) != (amp == NULL)) return WHIRL_EINVAL;
  int st = check_input(x, m, dt);
  if (st != WHIRL_OK) return st;
  const size_t n = padded_length(m);
  if (n == 0) return WHIRL_ENOMEM;
  const size_t nf = n / 2 + 1;
  if (freq == NULL) {
    *nfreq = nf;
    return WHIRL_OK;
  }
  double *full = NULL;
  st = amplitude_spectrum(x, m, n, &full);
  if (st != WHIRL_OK) return st;
  const size_t nout = nmax < nf ? nmax : nf;
  const double df = 1.0 / ((double)n * dt);
  for (size_t k = 0; k < nout; ++k) {
    freq[k] = (double)k * df;
    amp[k] = full[k];
  }
  free(full);
  *nfreq = nout;
  return WHIRL_OK;
}

/* ------------------------------------------------------------------------
 * Peaks */

static int peak_by_amp_desc(const void *pa, const void *pb) {
  const whirl_peak *a = pa, *b = pb;
  if (a->amp > b->amp) return -1;
  if (a->amp < b->amp) return 1;
  return (a->freq > b->freq) - (a->freq < b->freq);
}

/* Hann leakage bound |W(ν)/W(0)| = |sin(πν)| / (π ν |1 − ν²|) ≤
 * 1 / (π ν (ν² − 1)) at ν resolution bins from a tone, ν > 1. */
static double hann_envelope(double nu) {
  return 1.0 / (WHIRL_PI * nu * (nu * nu - 1.0));
}

/* Is a peak at fb with amplitude a explained as leakage of the larger
 * accepted peak at pb with amplitude pamp, or of its images at −pb and
 * fs − pb (fs = 1/dt)?  Frequencies in resolution bins (f·T, T = m dt), so
 * fs is at m. */
static int is_side_lobe(double fb, double a, double pb, double pamp, double m) {
  const double nu[3] = {fabs(fb - pb), fb + pb, fabs(m - pb - fb)};
  if (nu[0] < SPEC_MIN_SEP) return 1;
  for (int i = 0; i < 3; ++i)
    if (nu[i] >= SPEC_MIN_SEP &&
        a <= SPEC_LOBE_SAFETY * pamp * hann_envelope(nu[i]))
      return 1;
  return 0;
}

int whirl_spectrum_peaks(const double *x, size_t m, double dt,
                         double rel_threshold, whirl_peak *peaks,
                         size_t maxpeaks, size_t *npeaks) {
  if (npeaks == NULL || (peaks == NULL && maxpeaks > 0)) return WHIRL_EINVAL;
  if (!(rel_threshold >= 0.0) || !isfinite(rel_threshold)) return WHIRL_EINVAL;
  int st = check_input(x, m, dt);
  if (st != WHIRL_OK) return st;
  *npeaks = 0;
  const size_t n = padded_length(m);
  if (n == 0) return WHIRL_ENOMEM;
  const size_t nf = n / 2 + 1;
  double *amp = NULL;
  st = amplitude_spectrum(x, m, n, &amp);
  if (st != WHIRL_OK) return st;

  /* a spectrum at the rounding level of the data (a constant record) has
   * no peaks */
  double amax = 0.0, xmax = 0.0;
  for (size_t k = 1; k < nf; ++k) amax = fmax(amax, amp[k]);
  for (size_t i = 0; i < m; ++i) xmax = fmax(xmax, fabs(x[i]));
  if (!(amax > SPEC_ROUNDING * DBL_EPSILON * xmax) || maxpeaks == 0) {
    free(amp);
    return WHIRL_OK;
  }
  const double thr = rel_threshold * amax;
  const double df = 1.0 / ((double)n * dt); /* FFT bin */
  const double T = (double)m * dt;          /* 1 / resolution bin */

  size_t ncand = 0;
  for (size_t k = 1; k + 1 < nf; ++k)
    if (amp[k] > amp[k - 1] && amp[k] >= amp[k + 1] && amp[k] >= thr) ++ncand;
  whirl_peak *cand = malloc((ncand > 0 ? ncand : 1) * sizeof *cand);
  if (cand == NULL) {
    free(amp);
    return WHIRL_ENOMEM;
  }
  size_t c = 0;
  for (size_t k = 1; k + 1 < nf; ++k) {
    if (!(amp[k] > amp[k - 1] && amp[k] >= amp[k + 1] && amp[k] >= thr))
      continue;
    /* Gaussian interpolation: parabola through (−1, a), (0, b), (1, c) */
    const double la = log(fmax(amp[k - 1], DBL_MIN)), lb = log(amp[k]),
                 lc = log(fmax(amp[k + 1], DBL_MIN));
    const double den = la - 2.0 * lb + lc;
    double d = den < 0.0 ? 0.5 * (la - lc) / den : 0.0;
    if (d > 0.5) d = 0.5;
    if (d < -0.5) d = -0.5;
    cand[c].freq = ((double)k + d) * df;
    cand[c].amp = exp(lb - 0.25 * (la - lc) * d);
    ++c;
  }
  free(amp);
  qsort(cand, ncand, sizeof *cand, peak_by_amp_desc);

  size_t np = 0;
  for (size_t i = 0; i < ncand && np < maxpeaks; ++i) {
    /* below SPEC_MIN_SEP cycles in the record: the main lobe of the
     * removed mean, not a measurable tone */
    if (cand[i].amp < thr || cand[i].freq * T < SPEC_MIN_SEP) continue;
    int lobe = 0;
    for (size_t j = 0; j < np && !lobe; ++j)
      lobe = is_side_lobe(cand[i].freq * T, cand[i].amp, peaks[j].freq * T,
                          peaks[j].amp, (double)m);
    if (!lobe) peaks[np++] = cand[i];
  }
  free(cand);
  *npeaks = np;
  return WHIRL_OK;
}
