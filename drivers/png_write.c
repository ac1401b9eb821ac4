/* drivers/png_write.c — PNG encoder for rendered pictures (see png_write.h).
 *
 * A first pass splits the rows into runs of equal pixels (16 pixels
 * compared at a time) and counts the colours, one hash probe a run, until
 * a 257th rules out a palette.  It keeps the runs (4 bytes each) while
 * they take at most an eighth of the picture's own memory; the coding pass
 * splits the other rows itself, so the pixels of a typical picture are
 * read once.  Then the choice: an 8-bit palette image (colour type 3) for
 * <= 256 colours, else 8-bit RGB (type 2); and the rows (filter 0, None)
 * are coded into one fixed-Huffman DEFLATE block (RFC 1951, BTYPE = 01):
 * the first pixel of a run as literals, the rest as copies at distance 1
 * (palette: a byte a pixel) or 3 (RGB) in pieces of 3..258 bytes.  That
 * is the whole match search, which suits long background runs with thin
 * lines on them.  The zlib stream's Adler-32 is summed a run at a time in
 * closed form, so the uncompressed bytes are never formed.  Bits go into
 * a byte buffer written out as an IDAT chunk once it holds 64 KiB (at the
 * end of a row, so a chunk holds up to 64 KiB and a row).
 * SPDX-License-Identifier: BSD-3-Clause */
#include "png_write.h"

#include <errno.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SSE2__) && defined(__GNUC__)
#include <emmintrin.h>
#define PNG_SSE2 1
#endif

#define RGB_MASK 0xFFFFFFu     /* the colour bits of a pixel */
#define HASH_BITS 11           /* colour hash: 2048 slots for <= 256 colours */
#define HASH_N (1u << HASH_BITS)
#define HASH_EMPTY 0xFFFFFFFFu /* no colour: the top byte is never set */
#define IDAT_CAP 65536         /* bytes of zlib stream per IDAT chunk */
#define RUNS_MAX (1u << 22)    /* at most 16 MiB of kept runs */
#define ADLER_MOD 65521u

/* A code for the LSB-first bit stream: the bits << 5 | how many (<= 27). */
#define PACK(bits, n) ((uint32_t)(bits) << 5 | (uint32_t)(n))

/* The bit writer: ACC holds N <= 7 bits not yet complete at P. */
typedef struct bitw {
  uint64_t acc;
  unsigned n;
  uint8_t *p;
} bitw;

typedef struct png_enc {
  FILE *f;
  uint32_t crc[16][256]; /* [k][b]: CRC-32 of byte b and k zero bytes */
  uint32_t lit[257];     /* fixed codes of literals 0..255 and end of block */
  uint32_t match[259];   /* [k]: a copy of k = 3..258 bytes at our distance */
  uint32_t lits[256][3]; /* [v][k]: k literals v (nothing, one, two) */
  uint32_t key[HASH_N];  /* colour hash: the colour, or HASH_EMPTY */
  uint8_t idx[HASH_N];   /* its palette index */
  uint32_t pal[256];     /* the palette, in order of first appearance */
  unsigned ncol;         /* colours so far; 257: too many */
  uint32_t *runs;        /* each row's runs (RUN) */
  size_t nruns, cap;     /* runs kept (of whole rows), room for them */
  size_t rows_kept;      /* the rows whose runs are kept */
  uint64_t s1, s2;       /* Adler-32 sums, reduced at each row's end */
  uint8_t *buf;          /* IDAT chunk: 8 bytes length and type, data, CRC */
} png_enc;

static void put32be(uint8_t *p, uint32_t v) {
  p[0] = (uint8_t)(v >> 24);
  p[1] = (uint8_t)(v >> 16);
  p[2] = (uint8_t)(v >> 8);
  p[3] = (uint8_t)v;
}

/* (The compiler makes each of these one load or store where it can.) */
static inline void put64le(uint8_t *p, uint64_t v) {
  p[0] = (uint8_t)v;
  p[1] = (uint8_t)(v >> 8);
  p[2] = (uint8_t)(v >> 16);
  p[3] = (uint8_t)(v >> 24);
  p[4] = (uint8_t)(v >> 32);
  p[5] = (uint8_t)(v >> 40);
  p[6] = (uint8_t)(v >> 48);
  p[7] = (uint8_t)(v >> 56);
}

static inline uint32_t get32le(const uint8_t *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* ---- CRC-32 (PNG's: reflected polynomial 0xEDB88320), 16 bytes a step */

/* T[0]: the CRC of each byte, the eight single-bit bytes by the bitwise
 * rule and the rest by linearity; T[k]: the same followed by k zero bytes. */
static void crc_init(uint32_t t[16][256]) {
  t[0][0] = 0;
  for (unsigned b = 1; b < 256; b <<= 1) {
    uint32_t c = b;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[0][b] = c;
  }
  for (unsigned i = 1; i < 256; ++i) t[0][i] = t[0][i & (i - 1)] ^ t[0][i & (0u - i)];
  for (int k = 1; k < 16; ++k)
    for (unsigned i = 0; i < 256; ++i) t[k][i] = (t[k - 1][i] >> 8) ^ t[0][t[k - 1][i] & 0xFF];
}

/* The CRC of 4 bytes W (little-endian) followed by K zero bytes. */
static inline uint32_t crc_word(const uint32_t t[16][256], uint32_t w, int k) {
  return t[k + 3][w & 0xFF] ^ t[k + 2][(w >> 8) & 0xFF] ^ t[k + 1][(w >> 16) & 0xFF] ^
         t[k][w >> 24];
}

/* The CRC of N bytes at P: 16 bytes at a time, each passing through the
 * bytes after it in the step (its own table); then byte by byte. */
static uint32_t crc32_of(const uint32_t t[16][256], const uint8_t *p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (; n >= 16; n -= 16, p += 16)
    c = crc_word(t, c ^ get32le(p), 12) ^ crc_word(t, get32le(p + 4), 8) ^
        crc_word(t, get32le(p + 8), 4) ^ crc_word(t, get32le(p + 12), 0);
  for (; n; --n, ++p) c = t[0][(c ^ *p) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

/* ---- fixed Huffman codes */

/* The low N bits of V in reverse order (Huffman codes go MSB first). */
static uint32_t bit_reverse(uint32_t v, unsigned n) {
  uint32_t r = 0;
  for (unsigned k = 0; k < n; ++k, v >>= 1) r = r << 1 | (v & 1);
  return r;
}

/* The fixed literal/length code of symbol S (RFC 1951, 3.2.6). */
static uint32_t fixed_code(unsigned s) {
  if (s < 144) return PACK(bit_reverse(0x30 + s, 8), 8);
  if (s < 256) return PACK(bit_reverse(0x190 + s - 144, 9), 9);
  if (s < 280) return PACK(bit_reverse(s - 256, 7), 7);
  return PACK(bit_reverse(0xC0 + s - 280, 8), 8);
}

/* M[k], k = 3..258: length symbol, its extra bits and the distance code
 * DSYM (5 bits, no extra bits), one code.  Symbols 257..284 have 0 extra
 * bits for the first 8, then 1..5 for four symbols each (RFC 1951,
 * 3.2.5); 284 stops at 257, since 258 has a symbol of its own, 285. */
static void match_init(uint32_t m[259], unsigned dsym) {
  const uint32_t d = bit_reverse(dsym, 5);
  unsigned len = 3;
  for (unsigned i = 0; i < 28; ++i) {
    const unsigned extra = i < 8 ? 0 : (i - 4) / 4;
    const uint32_t c = fixed_code(257 + i), n = c & 31;
    for (uint32_t x = 0; x < (1u << extra) && len < 258; ++x, ++len)
      m[len] = PACK((c >> 5) | x << n | d << (n + extra), n + extra + 5);
  }
  const uint32_t c = fixed_code(285), n = c & 31;
  m[258] = PACK((c >> 5) | d << n, n + 5);
}

/* ---- runs and colours */

/* A run as kept: its length (<= 65535) << 8 | its palette index. */
#define RUN(n, v) ((uint32_t)(n) << 8 | (uint32_t)(v))

/* The lowest set bit of M != 0. */
static inline unsigned low_bit(unsigned m) {
#ifdef __GNUC__
  return (unsigned)__builtin_ctz(m);
#else
  unsigned i = 0;
  for (; !(m & 1); m >>= 1) ++i;
  return i;
#endif
}

#ifdef PNG_SSE2
/* Pixels P[0..3], any alignment. */
static inline __m128i load4(const uint32_t *p) {
  return _mm_loadu_si128((const __m128i *)(const void *)p);
}
#endif

/* Bit i set where ROW[x + i] differs from ROW[x + i - 1], i < 16: where
 * runs begin.  Pixels that differ only in the ignored top byte may begin a
 * run too: two runs of one colour are coded correctly, only longer. */
static inline unsigned breaks16(const uint32_t *row, size_t x) {
#ifdef PNG_SSE2
  /* first, cheaply, whether all 16 continue the run of ROW[x - 1] */
  const __m128i c = _mm_set1_epi32((int)row[x - 1]);
  const uint32_t *q = row + x;
  const __m128i a0 = load4(q), a1 = load4(q + 4), a2 = load4(q + 8), a3 = load4(q + 12);
  const __m128i all = _mm_and_si128(_mm_and_si128(_mm_cmpeq_epi32(a0, c), _mm_cmpeq_epi32(a1, c)),
                                    _mm_and_si128(_mm_cmpeq_epi32(a2, c), _mm_cmpeq_epi32(a3, c)));
  if (_mm_movemask_epi8(all) == 0xFFFF) return 0;
  const __m128i e0 = _mm_cmpeq_epi32(a0, load4(q - 1)), e1 = _mm_cmpeq_epi32(a1, load4(q + 3));
  const __m128i e2 = _mm_cmpeq_epi32(a2, load4(q + 7)), e3 = _mm_cmpeq_epi32(a3, load4(q + 11));
  const __m128i eq = _mm_packs_epi16(_mm_packs_epi32(e0, e1), _mm_packs_epi32(e2, e3));
  return ~(unsigned)_mm_movemask_epi8(eq) & 0xFFFF;
#else
  unsigned m = 0;
  for (unsigned i = 0; i < 16; ++i) m |= (unsigned)(row[x + i] != row[x + i - 1]) << i;
  return m;
#endif
}

/* The palette index of colour C, added if new; 0 once there are more than
 * 256 colours (E->ncol 257). */
static inline unsigned colour_index(png_enc *e, uint32_t c) {
  unsigned s = (c * 0x9E3779B1u) >> (32 - HASH_BITS);
  while (e->key[s] != c && e->key[s] != HASH_EMPTY) s = (s + 1) & (HASH_N - 1);
  if (e->key[s] == c) return e->idx[s];
  if (e->ncol == 256) {
    e->ncol = 257;
    return 0;
  }
  e->key[s] = c; /* at most 256 of 2048 slots taken: an empty one was found */
  e->idx[s] = (uint8_t)e->ncol;
  e->pal[e->ncol] = c;
  return e->ncol++;
}

/* RUNS[(*K)++]: N pixels of colour *P (counted while a palette may do). */
static inline void add_run(png_enc *e, const uint32_t *p, size_t n, uint32_t *runs, size_t *k) {
  const unsigned v = e->ncol <= 256 ? colour_index(e, *p & RGB_MASK) : 0;
  runs[(*k)++] = RUN(n, v);
}

/* Split ROW (W pixels) into RUNS; returns how many.  The places where runs
 * begin come 16 at a time as a bit mask, so that a branch is mispredicted
 * about once per group of short runs, not once per run. */
static size_t split_row(png_enc *e, const uint32_t *row, size_t w, uint32_t *runs) {
  size_t k = 0, start = 0, x = 1;
  for (; x + 16 <= w; x += 16)
    for (unsigned m = breaks16(row, x); m; m &= m - 1) {
      const size_t s = x + low_bit(m);
      add_run(e, row + start, s - start, runs, &k);
      start = s;
    }
  for (; x < w; ++x)
    if (row[x] != row[x - 1]) {
      add_run(e, row + start, x - start, runs, &k);
      start = x;
    }
  add_run(e, row + start, w - start, runs, &k);
  return k;
}

/* The pass that decides: all pixels' colours, until a 257th rules out a
 * palette, and the runs of as many rows as fit (always leaving room for
 * one more row's).  An RGB image's rows after the 257th colour's are split
 * only when they are coded, so its runs need not be kept. */
static void split_all(png_enc *e, const uint32_t *pix, size_t w, size_t h) {
  memset(e->key, 0xFF, sizeof e->key);
  e->ncol = 0;
  e->nruns = 0;
  e->rows_kept = 0;
  for (size_t y = 0; y < h && e->ncol <= 256; ++y) {
    const size_t k = split_row(e, pix + y * w, w, e->runs + e->nruns);
    if (e->rows_kept == y && e->nruns + k + w <= e->cap) {
      e->nruns += k;
      e->rows_kept++;
    }
  }
}

/* Split the palette row ROW (W indices) into RUNS; returns how many.  The
 * run goes on 8 indices at a time while they all equal its own. */
static size_t split_row8(const uint8_t *row, size_t w, uint32_t *runs) {
  size_t k = 0, start = 0, x = 1;
  uint8_t v = row[0];
  while (x < w) {
    const uint64_t all = 0x0101010101010101u * v;
    uint64_t q;
    while (x + 8 <= w && (memcpy(&q, row + x, 8), q == all)) x += 8;
    while (x < w && row[x] == v) ++x;
    if (x == w) break;
    runs[k++] = RUN(x - start, v);
    start = x;
    v = row[x++];
  }
  runs[k++] = RUN(w - start, v);
  return k;
}

/* ---- output */

/* 0 (errno back to SAVED) if a stdio call, made with errno 0, went OK;
 * else -1 with errno set (EIO if stdio left it 0, as a memory stream may). */
static int io_status(int went_ok, int saved) {
  if (went_ok) {
    errno = saved;
    return 0;
  }
  if (!errno) errno = EIO;
  return -1;
}

/* fwrite all N bytes; 0 or -1 with errno set. */
static int put_bytes(FILE *f, const void *p, size_t n) {
  const int saved = errno;
  errno = 0;
  return io_status(fwrite(p, 1, n, f) == n, saved);
}

/* fflush F; 0 or -1 with errno set. */
static int put_flush(FILE *f) {
  const int saved = errno;
  errno = 0;
  return io_status(fflush(f) == 0, saved);
}

/* Write a chunk of type TYPE with N <= 768 bytes of DATA. */
static int put_chunk(const png_enc *e, const char *type, const uint8_t *data, size_t n) {
  uint8_t c[12 + 768];
  put32be(c, (uint32_t)n);
  memcpy(c + 4, type, 4);
  if (n) memcpy(c + 8, data, n);
  put32be(c + 8 + n, crc32_of(e->crc, c + 4, n + 4));
  return put_bytes(e->f, c, n + 12);
}

/* Write the zlib bytes from E->buf + 8 up to END as an IDAT chunk. */
static int idat_flush(const png_enc *e, uint8_t *end) {
  const size_t n = (size_t)(end - (e->buf + 8));
  put32be(e->buf, (uint32_t)n);
  memcpy(e->buf + 4, "IDAT", 4);
  put32be(end, crc32_of(e->crc, e->buf + 4, n + 4));
  return put_bytes(e->f, e->buf, n + 12);
}

/* Signature, IHDR and (palette images) PLTE. */
static int put_head(const png_enc *e, int w, int h, int palette) {
  static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  uint8_t ihdr[13] = {0}, plte[768];
  put32be(ihdr, (uint32_t)w);
  put32be(ihdr + 4, (uint32_t)h);
  ihdr[8] = 8;               /* bit depth */
  ihdr[9] = palette ? 3 : 2; /* colour type; compression, filter, interlace 0 */
  for (unsigned i = 0; palette && i < e->ncol; ++i) {
    plte[3 * i] = (uint8_t)(e->pal[i] >> 16);
    plte[3 * i + 1] = (uint8_t)(e->pal[i] >> 8);
    plte[3 * i + 2] = (uint8_t)e->pal[i];
  }
  if (put_bytes(e->f, sig, 8) || put_chunk(e, "IHDR", ihdr, 13)) return -1;
  return palette ? put_chunk(e, "PLTE", plte, 3 * (size_t)e->ncol) : 0;
}

/* ---- DEFLATE */

/* Append the LEN <= 56 bits CODE to the bit stream, without a branch:
 * store all 8 bytes of the accumulator, step over the complete ones. */
static inline void put_bits(bitw *b, uint64_t code, unsigned len) {
  b->acc |= code << b->n;
  b->n += len;
  put64le(b->p, b->acc);
  b->p += b->n >> 3;
  b->acc >>= b->n & ~7u;
  b->n &= 7;
}

/* Append code V (PACK). */
static inline void put(bitw *b, uint32_t v) { put_bits(b, v >> 5, v & 31); }

/* A run: the literals of its first bytes, HEAD (HN <= 27 bits), then the
 * rest, M bytes, as copies of 3..258 bytes (259 and 260 as 256 or 257 and
 * 3) or, M < 3, as SHORT[M] (nothing, one or two literals).  For M <= 258
 * (nearly always) head and rest go in one write. */
static inline void put_run(bitw *b, uint64_t head, unsigned hn, const uint32_t *match,
                           const uint32_t *shrt, size_t m) {
  if (m > 258) {
    put_bits(b, head, hn);
    head = hn = 0;
    do {
      const size_t k = m - 258 >= 3 ? 258 : m - 3;
      put(b, match[k]);
      m -= k;
    } while (m > 258);
  }
  const uint32_t t = (m < 3 ? shrt : match)[m];
  put_bits(b, head | (uint64_t)(t >> 5) << hn, hn + (t & 31));
}

/* Code one palette row of W pixels from its RUNS, filter byte first, and
 * add its bytes to the Adler-32 sums: a run of n bytes v after sums
 * (s1, s2) gives s1 + u, u = n v, and s2 + n s1 + u (n + 1) / 2.  In a row
 * s1 < 2^26 and s2 < 2^44, so 64 bits and one reduction a row do.
 * Returns the number of runs. */
static inline size_t row_palette(png_enc *e, bitw *b, const uint32_t *runs, size_t w) {
  uint64_t s1 = e->s1, s2 = e->s2 + s1;
  size_t i = 0;
  put(b, e->lit[0]);
  for (size_t x = 0; x < w; ++i) {
    const uint64_t n = runs[i] >> 8, v = runs[i] & 0xFF, u = n * v;
    put_run(b, e->lit[v] >> 5, e->lit[v] & 31, e->match, e->lits[v], (size_t)n - 1);
    x += n;
    s2 += n * s1 + (u * (n + 1) >> 1);
    s1 += u;
  }
  e->s1 = s1 % ADLER_MOD;
  e->s2 = s2 % ADLER_MOD;
  return i;
}

/* Code one RGB row the same way, a run's colour from its first pixel in
 * ROW.  A run of n pixels (r, g, b) is 3n bytes; byte j (1-based) adds
 * s1_old + (its prefix sum) to s2, so s2 gains
 * 3n s1_old + 3 t n (n + 1) / 2 - n (g + 2 b), t = r + g + b, and s1
 * gains u = n t: computed as n (3 s1_old - g - 2 b) + 3 u (n + 1) / 2,
 * the first term wrapping modulo 2^64 at times but never the sum. */
static inline size_t row_rgb(png_enc *e, bitw *b, const uint32_t *runs, const uint32_t *row,
                             size_t w) {
  static const uint32_t none[3] = {0, 0, 0};
  uint64_t s1 = e->s1, s2 = e->s2 + s1;
  size_t i = 0;
  put(b, e->lit[0]);
  for (size_t x = 0; x < w; ++i) {
    const uint64_t n = runs[i] >> 8, r = (row[x] >> 16) & 0xFF, g = (row[x] >> 8) & 0xFF,
                   bl = row[x] & 0xFF, u = n * (r + g + bl);
    const uint32_t lr = e->lit[r], lg = e->lit[g], lb = e->lit[bl], nr = lr & 31, ng = lg & 31;
    put_run(b, (lr >> 5) | (lg >> 5) << nr | (uint64_t)(lb >> 5) << (nr + ng), nr + ng + (lb & 31),
            e->match, none, 3 * ((size_t)n - 1));
    x += n;
    s2 += n * (3 * s1 - g - 2 * bl) + 3 * (u * (n + 1) >> 1);
    s1 += u;
  }
  e->s1 = s1 % ADLER_MOD;
  e->s2 = s2 % ADLER_MOD;
  return i;
}

/* The zlib stream of all rows, as IDAT chunks; then IEND.  The rows whose
 * runs were not kept are split here, into the room after the kept ones;
 * palette indices IDX (pix NULL) are split row by row. */
static int put_image(png_enc *e, const uint32_t *pix, const uint8_t *idx, size_t w,
                     size_t h, int palette) {
  uint8_t *const data = e->buf + 8;
  bitw b = {0, 0, data};
  size_t at = 0; /* the next kept run */
  data[0] = 0x78; /* deflate, 32 KiB window; FLEVEL 0, no dictionary */
  data[1] = 0x01; /* so that 0x7801 % 31 == 0 */
  b.p += 2;
  put(&b, PACK(3, 3)); /* BFINAL = 1, BTYPE = 01 (fixed Huffman) */
  e->s1 = 1;
  e->s2 = 0;
  for (size_t y = 0; y < h; ++y) {
    if (b.p - data >= IDAT_CAP) {
      if (idat_flush(e, b.p)) return -1;
      b.p = data;
    }
    const uint32_t *row = pix ? pix + y * w : NULL, *runs = e->runs + at;
    if (idx) {
      runs = e->runs;
      split_row8(idx + y * w, w, e->runs);
    } else if (y >= e->rows_kept) {
      runs = e->runs + e->nruns;
      split_row(e, row, w, e->runs + e->nruns);
    }
    const size_t used = palette ? row_palette(e, &b, runs, w) : row_rgb(e, &b, runs, row, w);
    if (y < e->rows_kept) at += used;
  }
  put(&b, e->lit[256]);
  b.p += b.n > 0; /* the last, incomplete byte (already stored) */
  put32be(b.p, (uint32_t)(e->s2 << 16 | e->s1));
  if (idat_flush(e, b.p + 4)) return -1;
  return put_chunk(e, "IEND", NULL, 0);
}

/* Room for the runs of the first rows: w h / 8 runs, an eighth of the
 * picture's own memory (at most RUNS_MAX), and always one more row's. */
static size_t runs_room(size_t w, size_t h) {
  const size_t eighth = w * h / 8;
  return (eighth < RUNS_MAX ? eighth : RUNS_MAX) + w;
}

/* The CRC and code tables; copies at distance 1 (palette) or 3 (RGB). */
static void tables_init(png_enc *e, int palette) {
  crc_init(e->crc);
  for (unsigned s = 0; s < 257; ++s) e->lit[s] = fixed_code(s);
  for (unsigned v = 0; v < 256; ++v) {
    const uint32_t c = e->lit[v] >> 5, n = e->lit[v] & 31;
    e->lits[v][0] = 0;
    e->lits[v][1] = e->lit[v];
    e->lits[v][2] = PACK(c | c << n, 2 * n);
  }
  match_init(e->match, palette ? 0 : 2);
}

/* Split, choose, write. */
static int encode(png_enc *e, const uint32_t *pix, int w, int h) {
  split_all(e, pix, (size_t)w, (size_t)h);
  const int palette = e->ncol <= 256;
  tables_init(e, palette);
  /* <= 9 bits a byte of a row (a copy: <= 18 bits for >= 3 bytes) */
  const size_t row = 1 + (size_t)w * (palette ? 1 : 3);
  e->buf = malloc(8 + IDAT_CAP + row * 9 / 8 + 32);
  if (!e->buf) {
    errno = ENOMEM;
    return -1;
  }
  if (put_head(e, w, h, palette) || put_image(e, pix, NULL, (size_t)w, (size_t)h, palette))
    return -1;
  return put_flush(e->f);
}

/* An encoder writing to F with room for CAP runs; NULL (errno ENOMEM). */
static png_enc *enc_new(FILE *f, size_t cap) {
  png_enc *e = malloc(sizeof *e);
  if (!e) {
    errno = ENOMEM;
    return NULL;
  }
  e->f = f;
  e->cap = cap;
  e->runs = malloc(cap * sizeof *e->runs);
  e->buf = NULL;
  if (!e->runs) {
    free(e);
    errno = ENOMEM;
    return NULL;
  }
  return e;
}

static void enc_free(png_enc *e) {
  free(e->buf);
  free(e->runs);
  free(e);
}

static int size_ok(int w, int h) { return w >= 1 && w <= 65535 && h >= 1 && h <= 65535; }

int png_write_rgb(FILE *f, const uint32_t *pix, int w, int h) {
  if (!f || !pix || !size_ok(w, h)) {
    errno = EINVAL;
    return -1;
  }
  png_enc *e = enc_new(f, runs_room((size_t)w, (size_t)h));
  if (!e) return -1;
  const int r = encode(e, pix, w, h);
  enc_free(e);
  return r;
}

/* ---- palette images coded row by row, the palette given at the end */

struct png_rows {
  png_enc *e;
  bitw b;     /* the DEFLATE block's bits, in z */
  uint8_t *z; /* the zlib stream so far */
  size_t cap; /* bytes of z */
  int w, h, y; /* size; rows coded */
};

/* the most bytes one row's code takes, with the bit writer's 8 of slack */
static size_t row_room(size_t w) { return (1 + w) * 9 / 8 + 32; }

png_rows *png_rows_new(int w, int h) {
  if (!size_ok(w, h)) {
    errno = EINVAL;
    return NULL;
  }
  png_rows *s = calloc(1, sizeof *s);
  png_enc *e = s ? enc_new(NULL, (size_t)w + 1) : NULL; /* one row's runs at a time */
  if (!e) {
    free(s);
    errno = ENOMEM;
    return NULL;
  }
  s->e = e;
  s->w = w;
  s->h = h;
  s->cap = 4096 + 2 * row_room((size_t)w);
  s->z = malloc(s->cap);
  if (!s->z) {
    png_rows_free(s);
    errno = ENOMEM;
    return NULL;
  }
  tables_init(e, 1);
  e->rows_kept = e->nruns = 0;
  e->s1 = 1;
  e->s2 = 0;
  s->z[0] = 0x78; /* deflate, 32 KiB window; FLEVEL 0, no dictionary */
  s->z[1] = 0x01; /* so that 0x7801 % 31 == 0 */
  s->b.p = s->z + 2;
  put(&s->b, PACK(3, 3)); /* BFINAL = 1, BTYPE = 01 (fixed Huffman) */
  return s;
}

void png_rows_free(png_rows *s) {
  if (!s) return;
  if (s->e) enc_free(s->e);
  free(s->z);
  free(s);
}

/* room in z for one more row's code (and the stream's end) */
static int rows_room(png_rows *s) {
  const size_t used = (size_t)(s->b.p - s->z), need = row_room((size_t)s->w);
  if (used + need <= s->cap) return 0;
  size_t cap = 2 * s->cap;
  while (cap < used + need) cap *= 2;
  uint8_t *z = realloc(s->z, cap);
  if (!z) {
    errno = ENOMEM;
    return -1;
  }
  s->z = z;
  s->b.p = z + used;
  s->cap = cap;
  return 0;
}

int png_rows_add(png_rows *s, const uint8_t *idx, int n) {
  if (!s || !idx || n < 0 || n > s->h - s->y) {
    errno = EINVAL;
    return -1;
  }
  for (int j = 0; j < n; ++j) {
    if (rows_room(s)) return -1;
    split_row8(idx + (size_t)j * (size_t)s->w, (size_t)s->w, s->e->runs);
    row_palette(s->e, &s->b, s->e->runs, (size_t)s->w);
  }
  s->y += n;
  return 0;
}

int png_rows_write(png_rows *s, FILE *f, const uint32_t *pal, int npal) {
  if (!s || !f || !pal || npal < 1 || npal > 256 || s->y != s->h) {
    errno = EINVAL;
    return -1;
  }
  png_enc *e = s->e;
  e->f = f;
  e->ncol = (unsigned)npal;
  for (int i = 0; i < npal; ++i) e->pal[i] = pal[i] & RGB_MASK;
  /* the end of the block and the Adler-32 (row_room left space for them) */
  bitw b = s->b;
  put(&b, e->lit[256]);
  b.p += b.n > 0; /* the last, incomplete byte (already stored) */
  put32be(b.p, (uint32_t)(e->s2 << 16 | e->s1));
  const size_t len = (size_t)(b.p + 4 - s->z);
  if (!e->buf && !(e->buf = malloc(8 + IDAT_CAP + 4))) {
    errno = ENOMEM;
    return -1;
  }
  if (put_head(e, s->w, s->h, 1)) return -1;
  for (size_t at = 0; at < len; at += IDAT_CAP) {
    const size_t n = len - at < IDAT_CAP ? len - at : IDAT_CAP;
    memcpy(e->buf + 8, s->z + at, n);
    if (idat_flush(e, e->buf + 8 + n)) return -1;
  }
  if (put_chunk(e, "IEND", NULL, 0)) return -1;
  return put_flush(f);
}

int png_write_indexed(FILE *f, const uint8_t *idx, int w, int h, const uint32_t *pal,
                      int npal) {
  if (!f || !idx || !pal || !size_ok(w, h) || npal < 1 || npal > 256) {
    errno = EINVAL;
    return -1;
  }
  png_rows *s = png_rows_new(w, h);
  if (!s) return -1;
  const int r = png_rows_add(s, idx, h) || png_rows_write(s, f, pal, npal) ? -1 : 0;
  png_rows_free(s);
  return r;
}
