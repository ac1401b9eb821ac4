/* drivers/run_solution.c — labelled solutions of `whirl run`, the
 * counterpart of AUTO's s-files: OUT/solutions holds one block per label
 * with all digits (%.17g), enough to restart exactly (IRS):
 *
 *   # whirl solutions: model ab, npar 3
 *   LAB 3 TY HB BR 1 PT 27 KIND eq ICP 1 ICP2 0 NX 2 STAB 0
 *   PAR 0.165 14 3
 *   X 0.4059 1.4208
 *   TAN ...            (optional: the branch's unit tangent, NX + 1)
 *   MESH ...           (collocation: NTST + 1 mesh points; NTST, NCOL on LAB)
 *   END
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run.h"

static const char *kind_name[] = {"eq", "colloc", "hbm"};

void run_solution_free(run_solution *s) {
  if (!s) return;
  free(s->par);
  free(s->x);
  free(s->tan);
  free(s->mesh);
  memset(s, 0, sizeof *s);
}

static void put_vec(FILE *f, const char *tag, const double *v, size_t n) {
  fputs(tag, f);
  for (size_t i = 0; i < n; i++) fprintf(f, " %.17g", v[i]);
  fputc('\n', f);
}

int run_solution_write(FILE *f, const run_solution *s) {
  fprintf(f, "LAB %d TY %s BR %d PT %d KIND %s ICP %d ICP2 %d NX %zu STAB %d",
          s->label, s->ty, s->br, s->pt, kind_name[s->kind], s->icp + 1,
          s->icp2 + 1, s->nx, s->stable);
  if (s->kind == RUN_COLLOC) fprintf(f, " NTST %d NCOL %d", s->ntst, s->ncol);
  if (s->kind == RUN_HBM) fprintf(f, " NHB %d", s->nhb);
  fputc('\n', f);
  put_vec(f, "PAR", s->par, s->npar);
  put_vec(f, "X", s->x, s->nx);
  if (s->tan) put_vec(f, "TAN", s->tan, s->nx + 1);
  if (s->kind == RUN_COLLOC && s->mesh) put_vec(f, "MESH", s->mesh, (size_t)s->ntst + 1);
  fputs("END\n", f);
  return ferror(f) ? -1 : 0;
}

/* ---- reading ------------------------------------------------------------ */

typedef struct reader {
  FILE *f;
  const char *path;
  int line;
  char *buf;
  size_t cap;
  char *msg;
  size_t len;
} reader;

static int rd_line(reader *r) {
  ssize_t got = getline(&r->buf, &r->cap, r->f);
  if (got < 0) return -1;
  r->line++;
  return 0;
}

static int bad(reader *r, const char *what) {
  snprintf(r->msg, r->len, "%s:%d: %s", r->path, r->line, what);
  return -1;
}

/* "TAG v1 v2 ... vn" into v[n] (allocated). */
static int rd_vec(reader *r, const char *tag, size_t n, double **v) {
  if (rd_line(r)) return bad(r, "unexpected end of file");
  size_t tl = strlen(tag);
  if (strncmp(r->buf, tag, tl) || (r->buf[tl] != ' ' && r->buf[tl] != '\n'))
    return bad(r, "malformed solution block (a line is missing)");
  *v = malloc((n ? n : 1) * sizeof **v);
  if (!*v) return bad(r, "out of memory");
  char *p = r->buf + tl, *end;
  for (size_t i = 0; i < n; i++) {
    errno = 0;
    (*v)[i] = strtod(p, &end);
    if (end == p || !isfinite((*v)[i])) return bad(r, "a value is missing or not finite");
    p = end;
  }
  while (*p == ' ' || *p == '\n' || *p == '\r') p++;
  if (*p) return bad(r, "too many values");
  return 0;
}

int run_solution_find(const char *dir, const char *model, size_t npar,
                      int label, const char *ty, run_solution *out, char *msg,
                      size_t len) {
  char path[8192];
  snprintf(path, sizeof path, "%s/solutions", dir);
  memset(out, 0, sizeof *out);
  reader r = {fopen(path, "r"), path, 0, NULL, 0, msg, len};
  if (!r.f) {
    snprintf(msg, len, "cannot open %s: %s (S must name the output directory "
             "of an earlier whirl run)", path, strerror(errno));
    return -1;
  }
  int rc = -1, count = 0, found = 0;
  char want_model[256];
  if (rd_line(&r) || sscanf(r.buf, "# whirl solutions: model %255[^,], npar", want_model) != 1) {
    bad(&r, "not a whirl solutions file");
    goto done;
  }
  if (strcmp(want_model, model)) {
    char m[600];
    snprintf(m, sizeof m, "the solutions are of model '%s', this run's model "
             "is '%s'", want_model, model);
    bad(&r, m);
    goto done;
  }
  while (!found && rd_line(&r) == 0) {
    run_solution s;
    memset(&s, 0, sizeof s);
    char tyb[8], kb[16];
    int icp = 0, icp2 = 0, nconv = 0;
    size_t nx = 0;
    nconv = sscanf(r.buf, "LAB %d TY %7s BR %d PT %d KIND %15s ICP %d ICP2 %d NX %zu STAB %d",
                   &s.label, tyb, &s.br, &s.pt, kb, &icp, &icp2, &nx, &s.stable);
    if (nconv != 9) {
      bad(&r, "malformed solution header (LAB ... line)");
      goto done;
    }
    snprintf(s.ty, sizeof s.ty, "%.2s", tyb);
    s.kind = !strcmp(kb, "colloc") ? RUN_COLLOC : !strcmp(kb, "hbm") ? RUN_HBM : RUN_EQ;
    if (strcmp(kb, "eq") && s.kind == RUN_EQ) {
      bad(&r, "unknown solution KIND");
      goto done;
    }
    if (icp < 1 || (size_t)icp > npar || icp2 < 0 || (size_t)icp2 > npar ||
        nx == 0 || nx > 100000000) {
      bad(&r, "solution header out of range");
      goto done;
    }
    s.icp = icp - 1;
    s.icp2 = icp2 - 1;
    s.nx = nx;
    s.npar = npar;
    if (s.kind == RUN_COLLOC) {
      char *q = strstr(r.buf, "NTST");
      if (!q || sscanf(q, "NTST %d NCOL %d", &s.ntst, &s.ncol) != 2 ||
          s.ntst < 2 || s.ncol < 2 || s.ncol > 7) {
        bad(&r, "collocation solution without a valid NTST/NCOL");
        goto done;
      }
    }
    if (s.kind == RUN_HBM) {
      char *q = strstr(r.buf, "NHB");
      if (!q || sscanf(q, "NHB %d", &s.nhb) != 1 || s.nhb < 1) {
        bad(&r, "harmonic-balance solution without NHB");
        goto done;
      }
    }
    int match = ty && ty[0] ? !strcmp(s.ty, ty) && ++count == label
                            : s.label == label;
    if (rd_vec(&r, "PAR", npar, &s.par) || rd_vec(&r, "X", nx, &s.x)) {
      run_solution_free(&s);
      goto done;
    }
    /* optional TAN and MESH, then END */
    for (;;) {
      if (rd_line(&r)) {
        bad(&r, "unexpected end of file (END missing)");
        run_solution_free(&s);
        goto done;
      }
      if (!strncmp(r.buf, "END", 3)) break;
      if (!strncmp(r.buf, "TAN ", 4) || !strncmp(r.buf, "MESH ", 5)) {
        int is_tan = r.buf[0] == 'T';
        size_t m = is_tan ? nx + 1 : (size_t)s.ntst + 1;
        double **dst = is_tan ? &s.tan : &s.mesh;
        if (*dst || (!is_tan && s.kind != RUN_COLLOC)) {
          bad(&r, "unexpected line in a solution block");
          run_solution_free(&s);
          goto done;
        }
        *dst = malloc(m * sizeof **dst);
        if (!*dst) {
          bad(&r, "out of memory");
          run_solution_free(&s);
          goto done;
        }
        char *p = r.buf + (is_tan ? 3 : 4), *end;
        for (size_t i = 0; i < m; i++) {
          (*dst)[i] = strtod(p, &end);
          if (end == p || !isfinite((*dst)[i])) {
            bad(&r, "a value is missing or not finite");
            run_solution_free(&s);
            goto done;
          }
          p = end;
        }
        continue;
      }
      bad(&r, "unexpected line in a solution block");
      run_solution_free(&s);
      goto done;
    }
    if (s.kind == RUN_COLLOC && !s.mesh) {
      bad(&r, "collocation solution without MESH");
      run_solution_free(&s);
      goto done;
    }
    if (match) {
      *out = s;
      found = 1;
    } else {
      run_solution_free(&s);
    }
  }
  if (!found) {
    if (ty && ty[0])
      snprintf(msg, len, "%s: there is no %s number %d (IRS = %s%d)", path, ty,
               label, ty, label);
    else
      snprintf(msg, len, "%s: there is no label %d", path, label);
    goto done;
  }
  rc = 0;
done:
  free(r.buf);
  fclose(r.f);
  return rc;
}
