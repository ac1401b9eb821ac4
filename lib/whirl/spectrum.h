/* whirl/spectrum.h — signal analysis of time histories: amplitude spectra by
 * a windowed DFT with peak interpolation.  The character of a Poincaré
 * section (fixed point, period-k, invariant curve, irregular) is in
 * whirl/section.h, included here for the code that found it here.
 *
 * Spectrum: the (window-weighted) mean is removed, a Hann window applied, the record zero-
 * padded to 4 times the next power of two ≥ m (radix-2 FFT), and each peak's
 * frequency refined by fitting a parabola to the logarithms of the three
 * largest bins (Gaussian interpolation).  With the 4× padding the bins are at
 * most 1/4 of the resolution 1/(m dt) apart and the interpolation bias for a
 * Hann window is at most 2e-4 resolution bins in frequency and 1e-4 relative
 * in amplitude (1.5e-2 and 3e-2 without padding); other tones, and the
 * negative-frequency image of the tone itself, ν resolution bins away add
 * leakage of order 1/(π ν³) of their amplitude.  Peak amplitudes are those
 * of the sinusoid (window gain corrected).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_SPECTRUM_H
#define WHIRL_SPECTRUM_H

#include <stddef.h>
#include <whirl/status.h>
#include <whirl/section.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct whirl_peak {
  double freq; /* cycles per unit time (1/dt units) */
  double amp;  /* amplitude of the sinusoid */
} whirl_peak;

/* One-sided amplitude spectrum of x[m] sampled every dt: *nfreq (≤ nmax)
 * bins, freq[k] = k / (N dt) with N the padded length, amp[k] the window-
 * corrected amplitude.  Pass freq = amp = NULL to get the needed *nfreq
 * (N/2 + 1, about 2m).  With nmax below that, the lowest nmax bins are
 * returned.  WHIRL_EINVAL as for whirl_spectrum_peaks, or when only one of
 * freq, amp is NULL. */
WHIRL_API int whirl_spectrum(const double *x, size_t m, double dt,
                             double *freq, double *amp, size_t nmax,
                             size_t *nfreq);

/* The largest spectral peaks of x[m]: local maxima of the amplitude spectrum
 * at least rel_threshold times the largest, interpolated, at most maxpeaks,
 * sorted by decreasing amplitude.  Window side lobes are dropped: peaks
 * closer than 3 resolution bins 1/(m dt) to a larger one, and peaks below
 * twice the Hann leakage envelope 1/(π ν (ν² − 1)) of a larger peak ν
 * resolution bins away (or of its images at −f and 1/dt − f).  So a tone is
 * resolved next to a larger one of amplitude A only if it is more than 3
 * bins away and above 2 A/(π ν (ν² − 1)) (≈ 1e-2 A at 4 bins, 1e-3 A at 9
 * bins).  Peaks below 3 resolution bins (fewer than 3 cycles in the record,
 * inside the lobe of the removed mean) are not reported.  *npeaks = 0 when
 * the spectrum is at the rounding level (largest amplitude below
 * 1e3 DBL_EPSILON max|x|, e.g. a constant record).  WHIRL_EINVAL for m < 16,
 * dt <= 0, non-finite data, rel_threshold < 0, npeaks NULL, or peaks NULL
 * with maxpeaks > 0. */
WHIRL_API int whirl_spectrum_peaks(const double *x, size_t m, double dt,
                                   double rel_threshold, whirl_peak *peaks,
                                   size_t maxpeaks, size_t *npeaks);

#ifdef __cplusplus
}
#endif
#endif
