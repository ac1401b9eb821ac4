/* lib/run/solution.c — labelled solutions (whirl/solution.h): writing a
 * block, and reading one back with every count and number checked.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* getline */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/solution.h>
#include "util/fmt_num.h"

static const char *kind_name[] = {"eq", "colloc", "hbm", "bvp"};

void whirl_solution_free(whirl_solution *s) {
  if (!s) return;
  free(s->par);
  free(s->x);
  free(s->tan);
  free(s->mesh);
  memset(s, 0, sizeof *s);
}

/* " %.17g" each, by fmt_g (util/fmt_num.h: the same bytes, a fifth of
 * printf's time; a stored orbit is thousands of numbers a label) */
static void put_vec(FILE *f, const char *tag, const double *v, size_t n) {
  char b[FMT_NUM_SIZE + 1];
  fputs(tag, f);
  for (size_t i = 0; i < n; i++) {
    b[0] = ' ';
    const int k = fmt_g(b + 1, sizeof b - 1, v[i], 17);
    fwrite(b, 1, (size_t)k + 1, f);
  }
  fputc('\n', f);
}

int whirl_solution_write(FILE *f, const whirl_solution *s) {
  fprintf(f, "LAB %d TY %s BR %d PT %d KIND %s ICP %d ICP2 %d NX %zu STAB %d",
          s->label, s->ty, s->br, s->pt, kind_name[s->kind], s->icp + 1,
          s->icp2 + 1, s->nx, s->stable);
  if (s->kind == WHIRL_SOL_COLLOC) fprintf(f, " NTST %d NCOL %d", s->ntst, s->ncol);
  if (s->kind == WHIRL_SOL_BVP) {
    fprintf(f, " NTST %d NCOL %d NFREE %d", s->ntst, s->ncol, s->nfree);
    for (int j = 0; j < s->nfree && j < WHIRL_SOL_MAXFREE; j++) fprintf(f, " FREE %d", s->free_par[j] + 1);
  }
  if (s->kind == WHIRL_SOL_HBM) fprintf(f, " NHB %d", s->nhb);
  if (s->kind == WHIRL_SOL_EQ && s->iterate > 1) fprintf(f, " ITER %d", s->iterate);
  if (s->icp2 >= 0 && s->locus[0]) fprintf(f, " LOCUS %s", s->locus);
  fputc('\n', f);
  put_vec(f, "PAR", s->par, s->npar);
  put_vec(f, "X", s->x, s->nx);
  if (s->tan) put_vec(f, "TAN", s->tan, s->nx + 1);
  if ((s->kind == WHIRL_SOL_COLLOC || s->kind == WHIRL_SOL_BVP) && s->mesh)
    put_vec(f, "MESH", s->mesh, (size_t)s->ntst + 1);
  fputs("END\n", f);
  return ferror(f) ? -1 : 0;
}

/* ---- reading ------------------------------------------------------------ */

/* The file is read line by line and every block is checked for its own
 * consistency before it is compared with the label asked for: the header's
 * fields and their ranges, a known KIND and point type, NX against NTST and
 * NCOL (or NHB), the number of values on PAR, X, TAN and MESH lines, finite
 * numbers, an increasing mesh, END.  A caller may then index every vector
 * by the sizes in the whirl_solution. */
typedef struct reader {
  FILE *f;
  const char *path;
  int line;
  char *buf;
  size_t cap;
  char *msg;
  size_t len;
} reader;

static int bad(reader *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int bad(reader *r, const char *fmt, ...) {
  char where[4200];
  if (r->line > 0)
    snprintf(where, sizeof where, "%s:%d", r->path, r->line);
  else /* nothing read: no line to blame */
    snprintf(where, sizeof where, "%s", r->path);
  va_list ap;
  va_start(ap, fmt);
  whirl_errmsg_vat(r->msg, r->len, -1, where, fmt, ap);
  va_end(ap);
  return -1;
}

/* Untrusted text for a message: at most 60 bytes, unprintable ones as '?'. */
static const char *shown(const char *s, char buf[72]) {
  size_t j = 0;
  for (; s[j] && j < 60; j++)
    buf[j] = s[j] >= 32 && s[j] < 127 ? s[j] : '?';
  if (s[j]) memcpy(buf + j, "...", 3), j += 3;
  buf[j] = '\0';
  return buf;
}

/* The next line, without its '\n': 0, 1 at the end of the file, -1 with
 * the message set for a read error or a NUL byte. */
static int rd_line(reader *r) {
  ssize_t got = getline(&r->buf, &r->cap, r->f);
  if (got < 0 && ferror(r->f)) return bad(r, "cannot read: %s", strerror(errno));
  if (got < 0) return 1;
  r->line++;
  if (got > 0 && r->buf[got - 1] == '\n') r->buf[--got] = '\0';
  if ((size_t)got != strlen(r->buf))
    return bad(r, "NUL byte in the line (not a whirl solutions file?)");
  return 0;
}

/* " KEY value" at *p: an integer in [lo, hi]; *p moves past it. */
static int lab_int(reader *r, char **p, const char *key, long lo, long hi,
                   long *v) {
  size_t kl = strlen(key);
  char *q = *p + (**p == ' '), *end;
  if (strncmp(q, key, kl) || q[kl] != ' ')
    return bad(r, "malformed LAB line: %s expected", key);
  errno = 0;
  *v = strtol(q + kl + 1, &end, 10);
  if (end == q + kl + 1 || (*end && *end != ' ') || errno || *v < lo || *v > hi)
    return bad(r, "LAB line: %s must be an integer in [%ld, %ld]", key, lo, hi);
  *p = end;
  return 0;
}

/* " KEY word" at *p into w[cap]. */
static int lab_word(reader *r, char **p, const char *key, char *w, size_t cap) {
  size_t kl = strlen(key), n;
  char *q = *p + (**p == ' '), b[72];
  if (strncmp(q, key, kl) || q[kl] != ' ')
    return bad(r, "malformed LAB line: %s expected", key);
  q += kl + 1;
  n = strcspn(q, " ");
  if (n == 0 || n >= cap) {
    q[n] = '\0';
    return bad(r, "LAB line: %s '%s' is too long or empty", key, shown(q, b));
  }
  memcpy(w, q, n);
  w[n] = '\0';
  *p = q + n;
  return 0;
}

/* NX of a periodic orbit is (M x n) state values, plus the period for an
 * autonomous model, with M = NTST x NCOL + 1 nodes (colloc) or 2 NHB + 1
 * coefficients (hbm): the state count and the period from NX. */
static int orbit_size(reader *r, whirl_solution *s) {
  if (s->kind == WHIRL_SOL_BVP) { /* (NTST NCOL + 1) n node values + NFREE */
    const size_t m = (size_t)s->ntst * (size_t)s->ncol + 1, nf = (size_t)s->nfree;
    if (s->nx <= nf || (s->nx - nf) % m)
      return bad(r, "label %d: NX %zu does not fit NTST %d, NCOL %d, NFREE %d (a "
                 "boundary-value solution has (NTST x NCOL + 1) x n values, + NFREE)",
                 s->label, s->nx, s->ntst, s->ncol, s->nfree);
    s->nstate = (s->nx - nf) / m;
    s->aut = 0;
    return 0;
  }
  const size_t m = s->kind == WHIRL_SOL_COLLOC ? (size_t)s->ntst * (size_t)s->ncol + 1
                                         : 2 * (size_t)s->nhb + 1;
  if (s->nx < m || s->nx % m > 1) {
    if (s->kind == WHIRL_SOL_COLLOC)
      return bad(r, "label %d: NX %zu does not fit NTST %d, NCOL %d (a "
                 "collocation orbit has (NTST x NCOL + 1) x n values, + 1 "
                 "for the period)", s->label, s->nx, s->ntst, s->ncol);
    return bad(r, "label %d: NX %zu does not fit NHB %d (a harmonic-balance "
               "orbit has (2 x NHB + 1) x n values, + 1 for the period)",
               s->label, s->nx, s->nhb);
  }
  s->nstate = s->nx / m;
  s->aut = (int)(s->nx % m);
  return 0;
}

/* The LAB line of a block, into s (vectors not read yet). */
static int rd_lab(reader *r, size_t npar, whirl_solution *s) {
  char *p = r->buf, ty[8], kind[16], b[72];
  long lab, br, pt, icp, icp2, nx, stab, v1, v2;
  if (strncmp(p, "LAB ", 4)) return bad(r, "'%s' is not a LAB line", shown(p, b));
  if (lab_int(r, &p, "LAB", 1, INT_MAX, &lab) ||
      lab_word(r, &p, "TY", ty, sizeof ty) ||
      lab_int(r, &p, "BR", 1, INT_MAX, &br) ||
      lab_int(r, &p, "PT", 0, INT_MAX, &pt) ||
      lab_word(r, &p, "KIND", kind, sizeof kind) ||
      lab_int(r, &p, "ICP", 1, (long)npar, &icp) ||
      lab_int(r, &p, "ICP2", 0, (long)npar, &icp2) ||
      lab_int(r, &p, "NX", 1, 100000000, &nx) ||
      lab_int(r, &p, "STAB", -1, 1, &stab))
    return -1;
  s->label = (int)lab, s->br = (int)br, s->pt = (int)pt;
  s->icp = (int)icp - 1, s->icp2 = (int)icp2 - 1;
  s->nx = (size_t)nx, s->stable = (int)stab, s->npar = npar;
  /* two characters: AUTO's names (HB, LP, ...), or "??" for a type the
   * writer did not know */
  if (strlen(ty) != 2 || !isgraph((unsigned char)ty[0]) ||
      !isgraph((unsigned char)ty[1]))
    return bad(r, "label %d: TY '%s' is not a point type (two characters, "
               "such as HB)", s->label, shown(ty, b));
  memcpy(s->ty, ty, 3);
  if (icp2 == icp) return bad(r, "label %d: ICP2 equals ICP", s->label);
  if (!strcmp(kind, "eq")) {
    s->kind = WHIRL_SOL_EQ;
    s->nstate = s->nx;
  } else if (!strcmp(kind, "colloc")) {
    s->kind = WHIRL_SOL_COLLOC;
    if (lab_int(r, &p, "NTST", 2, 100000, &v1) || lab_int(r, &p, "NCOL", 2, 7, &v2))
      return -1;
    s->ntst = (int)v1, s->ncol = (int)v2;
  } else if (!strcmp(kind, "bvp")) {
    long v3;
    s->kind = WHIRL_SOL_BVP;
    if (lab_int(r, &p, "NTST", 1, 100000, &v1) || lab_int(r, &p, "NCOL", 2, 7, &v2) ||
        lab_int(r, &p, "NFREE", 0, WHIRL_SOL_MAXFREE, &v3))
      return -1;
    s->ntst = (int)v1, s->ncol = (int)v2, s->nfree = (int)v3;
    for (int j = 0; j < s->nfree; j++) {
      if (lab_int(r, &p, "FREE", 1, (long)npar, &v1)) return -1;
      s->free_par[j] = (int)v1 - 1;
    }
  } else if (!strcmp(kind, "hbm")) {
    s->kind = WHIRL_SOL_HBM;
    if (lab_int(r, &p, "NHB", 1, 1000, &v1)) return -1;
    s->nhb = (int)v1;
  } else {
    return bad(r, "label %d: unknown KIND '%s' (eq, colloc, hbm or bvp)", s->label,
               shown(kind, b));
  }
  s->iterate = 1;
  if (s->kind == WHIRL_SOL_EQ && !strncmp(p, " ITER ", 6)) { /* a map's period */
    if (lab_int(r, &p, "ITER", 1, 1 << 20, &v1)) return -1;
    s->iterate = (int)v1;
  }
  if (!strncmp(p, " LOCUS ", 7)) { /* loci (optional: older files lack it) */
    char loc[8];
    if (lab_word(r, &p, "LOCUS", loc, sizeof loc)) return -1;
    if (s->icp2 < 0 ||
        (strcmp(loc, "LP") && strcmp(loc, "PD") && strcmp(loc, "HB") && strcmp(loc, "TR") &&
         strcmp(loc, "BP")))
      return bad(r, "label %d: LOCUS '%s' (LP, PD, HB, TR or BP, on a locus: ICP2 > 0)",
                 s->label, shown(loc, b));
    memcpy(s->locus, loc, 3);
  }
  if (*p) return bad(r, "label %d: unexpected '%s' at the end of the LAB line",
                     s->label, shown(p + 1, b));
  return s->kind == WHIRL_SOL_EQ ? 0 : orbit_size(r, s);
}

/* The numbers after a tag: exactly want of them, finite, into *v (one
 * strtod a number: the values go into *v as they are read, and the count
 * goes on past want only to say how many there were). */
static int rd_values(reader *r, const whirl_solution *s, const char *tag,
                     const char *text, size_t want, const char *expect,
                     double **v) {
  double *out = malloc((want ? want : 1) * sizeof *out);
  if (!out) return bad(r, "out of memory");
  size_t k = 0;
  char *end, b[72];
  for (const char *p = text;; p = end) {
    while (*p == ' ') p++;
    if (!*p) break;
    double x = strtod(p, &end);
    if (end == p || (*end && *end != ' ')) {
      free(out);
      return bad(r, "label %d: %s: '%s' is not a number", s->label, tag,
                 shown(p, b));
    }
    if (!isfinite(x)) {
      free(out);
      return bad(r, "label %d: %s: value %zu is not finite", s->label, tag, k + 1);
    }
    if (k < want) out[k] = x;
    k++;
  }
  if (k != want) {
    free(out);
    return bad(r, "label %d: %s has %zu values, %s = %zu expected", s->label,
               tag, k, expect, want);
  }
  *v = out;
  return 0;
}

/* The lines after LAB up to END: PAR, X, optional TAN, MESH (colloc). */
static int rd_body(reader *r, whirl_solution *s) {
  char b[72];
  for (;;) {
    int rc = rd_line(r);
    if (rc > 0)
      return bad(r, "end of file inside the block of label %d (END missing)",
                 s->label);
    if (rc) return -1;
    if (!strcmp(r->buf, "END")) break;
    const size_t tl = strcspn(r->buf, " ");
    const char *tags[] = {"PAR", "X", "TAN", "MESH"};
    const char *expect[] = {"npar", "NX", "NX + 1", "NTST + 1"};
    const size_t want[] = {s->npar, s->nx, s->nx + 1, (size_t)s->ntst + 1};
    double **dst[] = {&s->par, &s->x, &s->tan, &s->mesh};
    int t = 0;
    while (t < 4 && (strlen(tags[t]) != tl || strncmp(r->buf, tags[t], tl))) t++;
    if (t == 4 || (t == 3 && s->kind != WHIRL_SOL_COLLOC && s->kind != WHIRL_SOL_BVP))
      return bad(r, "label %d: unexpected line '%s' in the block", s->label,
                 shown(r->buf, b));
    if (*dst[t]) return bad(r, "label %d: a second %s line", s->label, tags[t]);
    if (rd_values(r, s, tags[t], r->buf + tl, want[t], expect[t], dst[t])) return -1;
  }
  if (!s->par || !s->x)
    return bad(r, "label %d: the block has no %s line", s->label,
               s->par ? "X" : "PAR");
  if ((s->kind == WHIRL_SOL_COLLOC || s->kind == WHIRL_SOL_BVP) && !s->mesh)
    return bad(r, "label %d: collocation solution without MESH", s->label);
  if (s->mesh) {
    int ok = s->mesh[0] == 0.0 && s->mesh[s->ntst] == 1.0;
    for (int i = 1; i <= s->ntst; i++) ok &= s->mesh[i] > s->mesh[i - 1];
    if (!ok) return bad(r, "label %d: MESH does not increase from 0 to 1", s->label);
  }
  return 0;
}

/* "# whirl solutions: model NAME, npar N": NAME into model, N into *npar. */
static int rd_header(reader *r, char *model, size_t cap, size_t *npar) {
  static const char head[] = "# whirl solutions: model ";
  const size_t hl = sizeof head - 1;
  int rc = rd_line(r);
  if (rc < 0) return -1;
  if (rc) return bad(r, "the file is empty (not a whirl solutions file)");
  if (strncmp(r->buf, head, hl)) return bad(r, "not a whirl solutions file");
  char *comma = NULL, *end;
  for (char *q = strstr(r->buf + hl, ", npar "); q; q = strstr(q + 1, ", npar "))
    comma = q;
  if (!comma) return bad(r, "not a whirl solutions file");
  errno = 0;
  long n = strtol(comma + 7, &end, 10);
  if (end == comma + 7 || *end || errno || n < 1 || n > 100000 ||
      (size_t)(comma - (r->buf + hl)) >= cap)
    return bad(r, "malformed header line");
  memcpy(model, r->buf + hl, (size_t)(comma - (r->buf + hl)));
  model[comma - (r->buf + hl)] = '\0';
  *npar = (size_t)n;
  return 0;
}

/* Does the solution fit the model of want?  0, or -1 with the message. */
static int fits(reader *r, const whirl_solution *s, const whirl_solution_shape *want) {
  if (!want->n) return 0;
  if (s->kind != WHIRL_SOL_EQ && s->kind != WHIRL_SOL_BVP && want->forced >= 0 &&
      s->aut == want->forced) {
    snprintf(r->msg, r->len, "label %d of %s is an orbit of %s NX %zu "
             "unknowns; model '%s' is %s", s->label, r->path,
             s->aut ? "an autonomous model: its period is the last of its"
                    : "a forced model: the period is none of its",
             s->nx, want->model ? want->model : "?",
             want->forced ? "forced" : "autonomous");
    return -1;
  }
  if (s->nstate == want->n) return 0;
  if (want->pad_state && s->nstate < want->n &&
      (s->kind == WHIRL_SOL_COLLOC || s->kind == WHIRL_SOL_BVP))
    return 0; /* pad_state adds the components */
  char how[128] = "";
  if (s->kind == WHIRL_SOL_COLLOC)
    snprintf(how, sizeof how, " = (NTST %d x NCOL %d + 1) x %zu%s", s->ntst,
             s->ncol, s->nstate, s->aut ? " + 1" : "");
  if (s->kind == WHIRL_SOL_HBM)
    snprintf(how, sizeof how, " = (2 x NHB %d + 1) x %zu%s", s->nhb, s->nstate,
             s->aut ? " + 1" : "");
  if (s->kind == WHIRL_SOL_BVP)
    snprintf(how, sizeof how, " = (NTST %d x NCOL %d + 1) x %zu + %d", s->ntst, s->ncol,
             s->nstate, s->nfree);
  snprintf(r->msg, r->len, "label %d of %s %s %zu states (NX %zu%s); model "
           "'%s' has %zu", s->label, r->path,
           s->kind == WHIRL_SOL_EQ ? "has" : "is an orbit of", s->nstate, s->nx, how,
           want->model ? want->model : "?", want->n);
  return -1;
}

/* A collocation solution with fewer state components than want->n (and
 * want->pad_state): every node's values followed by zeros, the unknowns
 * after the nodes (period, free parameters) kept; the tangent, of the
 * other dimension, dropped.  0, or -1 out of memory. */
static int pad_state(whirl_solution *s, const whirl_solution_shape *want) {
  if (!want->pad_state || !want->n || s->nstate >= want->n ||
      (s->kind != WHIRL_SOL_COLLOC && s->kind != WHIRL_SOL_BVP))
    return 0;
  const size_t m = (size_t)s->ntst * (size_t)s->ncol + 1, k = s->nstate, n = want->n;
  const size_t extra = s->nx - m * k, nx = m * n + extra;
  double *x = calloc(nx, sizeof *x);
  if (!x) return -1;
  for (size_t j = 0; j < m; j++) memcpy(x + n * j, s->x + k * j, k * sizeof *x);
  memcpy(x + m * n, s->x + m * k, extra * sizeof *x);
  free(s->x);
  free(s->tan);
  s->x = x, s->tan = NULL, s->nx = nx, s->nstate_stored = k, s->nstate = n;
  return 0;
}

/* s's parameters to npar (when more than it has), the new ones 0 and
 * npar_stored the file's count.  0, or -1 out of memory. */
static int pad_params(whirl_solution *s, size_t npar) {
  if (npar <= s->npar) return 0;
  double *p = realloc(s->par, npar * sizeof *p);
  if (!p) return -1;
  for (size_t k = s->npar; k < npar; k++) p[k] = 0.0;
  s->par = p;
  s->npar_stored = s->npar;
  s->npar = npar;
  return 0;
}

int whirl_solution_read(FILE *f, const char *path, const whirl_solution_shape *want,
                      int label, const char *ty, whirl_solution *out, char *msg,
                      size_t len) {
  memset(out, 0, sizeof *out);
  if (len) msg[0] = '\0';
  reader r = {f, path, 0, NULL, 0, msg, len};
  char model[256];
  size_t npar = 0;
  int rc = -1, count = 0;
  if (rd_header(&r, model, sizeof model, &npar)) goto done;
  if (want->model && strcmp(model, want->model)) {
    char b[72];
    bad(&r, "the solutions are of model '%s', this run's model is '%s'",
        shown(model, b), want->model);
    goto done;
  }
  /* fewer parameters than the model: a restart with a larger NPAR, as
   * AUTO's (main.f90: NPAR = MAX(NPARR, NPAR)); the others are the
   * model's own values for the run (pad_params: npar_stored) */
  if (want->npar && npar > want->npar) {
    bad(&r, "the solutions have %zu parameters (npar %zu); model '%s' has %zu",
        npar, npar, model, want->npar);
    goto done;
  }
  for (;;) {
    whirl_solution s;
    memset(&s, 0, sizeof s);
    int got = rd_line(&r);
    if (got < 0) goto done;
    if (got > 0) break;
    if (rd_lab(&r, npar, &s) || rd_body(&r, &s)) {
      whirl_solution_free(&s);
      goto done;
    }
    if (ty && ty[0] ? !strcmp(s.ty, ty) && ++count == label : s.label == label) {
      if (fits(&r, &s, want)) {
        whirl_solution_free(&s);
        goto done;
      }
      if (pad_params(&s, want->npar) || pad_state(&s, want)) {
        whirl_solution_free(&s);
        snprintf(msg, len, "%s: out of memory", path);
        goto done;
      }
      *out = s;
      rc = 0;
      goto done;
    }
    whirl_solution_free(&s);
  }
  if (ty && ty[0])
    snprintf(msg, len, "%s: there is no %s number %d (IRS = %s%d)", path, ty,
             label, ty, label);
  else
    snprintf(msg, len, "%s: there is no label %d", path, label);
done:
  free(r.buf);
  return rc;
}

int whirl_solution_each(FILE *f, const char *path,
                        int (*fn)(const whirl_solution *s, void *data), void *data,
                        char *msg, size_t len) {
  if (len) msg[0] = '\0';
  reader r = {f, path, 0, NULL, 0, msg, len};
  char model[256];
  size_t npar = 0;
  int rc = -1;
  if (rd_header(&r, model, sizeof model, &npar)) goto done;
  for (;;) {
    whirl_solution s;
    memset(&s, 0, sizeof s);
    const int got = rd_line(&r);
    if (got < 0) goto done;
    if (got > 0) break;
    if (rd_lab(&r, npar, &s) || rd_body(&r, &s)) {
      whirl_solution_free(&s);
      goto done;
    }
    const int stop = fn(&s, data);
    whirl_solution_free(&s);
    if (stop) {
      rc = stop;
      goto done;
    }
  }
  rc = 0;
done:
  free(r.buf);
  return rc;
}

int whirl_solution_find(const char *dir, const whirl_solution_shape *want,
                        int label, const char *ty, whirl_solution *out, char *msg,
                        size_t len) {
  char path[8192];
  snprintf(path, sizeof path, "%s/solutions", dir);
  memset(out, 0, sizeof *out);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, len, "cannot open %s: %s (S must name the output directory "
             "of an earlier whirl run)", path, strerror(errno));
    return -1;
  }
  int rc = whirl_solution_read(f, path, want, label, ty, out, msg, len);
  fclose(f);
  return rc;
}
