/* lib/run/auto_runfile.c — an AUTO-07p constants file as the whirl run file
 * that runs it (whirl_auto_constants_runfile, whirl/auto_constants.h):
 * the constants whirl shares with AUTO copied with AUTO's meaning
 * (doc/run-files.md has whirl's), names resolved through parnames and
 * unames, AUTO's conventions made explicit (PAR(11) of orbits is the
 * period; a negative UZR index is a stop), and what whirl cannot do refused
 * at the constant's line.  AUTO-07p manual, ch. 10 (AUTO-constants).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "auto_impl.h"

/* ---- a growing text ---------------------------------------------------- */

typedef struct text {
  char *s;
  size_t n, cap;
  int oom;
} text;

static void put(text *t, const char *fmt, ...) WHIRL_PRINTF_LIKE(2, 3);
static void put(text *t, const char *fmt, ...) {
  va_list ap;
  for (;;) {
    va_start(ap, fmt);
    int k = t->oom ? -1 : vsnprintf(t->s ? t->s + t->n : NULL, t->s ? t->cap - t->n : 0, fmt, ap);
    va_end(ap);
    if (k < 0) {
      t->oom = 1;
      return;
    }
    if (t->s && t->n + (size_t)k < t->cap) {
      t->n += (size_t)k;
      return;
    }
    size_t cap = 2 * (t->cap + (size_t)k) + 256;
    char *s = realloc(t->s, cap);
    if (!s) {
      t->oom = 1;
      return;
    }
    t->s = s, t->cap = cap;
  }
}

/* x with the fewest digits that read back as x (15 to 17). */
static const char *num(double x, char *buf, size_t len) {
  for (int p = 15; p <= 17; p++) {
    snprintf(buf, len, "%.*g", p, x);
    if (strtod(buf, NULL) == x) break;
  }
  return buf;
}

/* ---- names and indices ------------------------------------------------- */

typedef struct ctx {
  whirl_auto_constants *ac;
  const whirl_auto_runfile_opts *o;
  int ips;
  text *t;
} ctx;

/* The index NAME has in parnames or unames, 0 if none. */
static int named(const whirl_auto_constants *ac, const char *names, const char *name) {
  whirl_auto_item it;
  for (size_t i = 0; i < whirl_auto_constants_count(ac, names); i++)
    if (whirl_auto_constants_item(ac, names, i, &it) == WHIRL_OK && !strcmp(it.text, name))
      return it.index;
  return 0;
}

/* A parameter of KEY's item as whirl names it: "k" (1 <= k <= npar) or
 * "PERIOD" (PAR(11) of a periodic problem), into buf.  1: fine; 0: beyond
 * NPAR (a PVLS quantity, a HomCont parameter); -1: an error (set). */
static int par_ref(ctx *c, const char *key, const whirl_auto_item *it, char *buf, size_t len) {
  int k = it->index;
  if (it->name && !(k = named(c->ac, "parnames", it->name))) {
    if (strcasecmp(it->name, "PERIOD"))
      return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, key),
                                       "%s: '%s' is neither in parnames nor PERIOD", key,
                                       it->name), -1;
    k = 11;
  }
  if (k == 11 && c->ips == 2) { /* AUTO: PAR(11) of orbits is the period */
    snprintf(buf, len, "PERIOD");
    return 1;
  }
  if (k < 1 || (size_t)k > c->o->npar) return 0;
  snprintf(buf, len, "%d", k);
  return 1;
}

/* A state component by index or unames: k, or 0 (with the error). */
static int state_ref(ctx *c, const char *key, const whirl_auto_item *it, int ndim) {
  const int line = whirl_auto_constants_line(c->ac, key);
  int k = it->name ? named(c->ac, "unames", it->name) : it->index;
  if (it->name && !k)
    return whirl_auto_constants_fail(c->ac, line, "%s: '%s' is not in unames", key, it->name), 0;
  if (k < 1 || k > ndim)
    return whirl_auto_constants_fail(c->ac, line, "%s: U(%d) beyond NDIM = %d", key, k, ndim), 0;
  return k;
}

/* ---- the keys ---------------------------------------------------------- */

/* Keys copied as they are: AUTO's and whirl's meaning agree (doc/run-files.md),
 * or whirl accepts them and says in run.log that it ignores them. */
static const char *const same_int[] = {"NDIM", "ILP", "ISP", "NTST", "NCOL", "IAD", "NMX",
                                       "NPR", "ITNW", "ITMX", "NWTN", "IID", "IPLT", "NBC",
                                       "NINT", "MXBF", "IADS", "NPAR", "IIS", "IBR", "LAB",
                                       "NUNSTAB", "NSTAB"};
static const char *const same_real[] = {"DS", "DSMIN", "DSMAX", "RL0", "RL1", "A0", "A1",
                                        "EPSL", "EPSU", "EPSS"};

/* AUTO-07p's defaults (its main.f90, INIT) for the keys a constants file
 * leaves out where whirl's run files default otherwise: the Newton and
 * localisation limits (ITNW 5, not 8: pp2's equilibria took three
 * iterations a step, and the step grew x1.1 where AUTO's stays), DS's
 * bounds, the tests and the switches */
static void auto_defaults(ctx *c) {
  static const struct { const char *key; int v; } di[] = {
      {"ILP", 1}, {"ISP", 2}, {"NTST", 20}, {"NCOL", 4}, {"IAD", 3},
      {"MXBF", 10}, {"ITMX", 9}, {"ITNW", 5}, {"NWTN", 3}};
  static const struct { const char *key; double v; } dr[] = {
      {"DS", 0.01}, {"DSMIN", 0.005}, {"DSMAX", 0.1}};
  char nb[40];
  int v;
  double x;
  for (size_t i = 0; i < sizeof di / sizeof *di; i++)
    if (whirl_auto_constants_int(c->ac, di[i].key, &v) != WHIRL_OK)
      put(c->t, "%-6s = %d  # AUTO's default\n", di[i].key, di[i].v);
  for (size_t i = 0; i < sizeof dr / sizeof *dr; i++)
    if (whirl_auto_constants_real(c->ac, dr[i].key, &x) != WHIRL_OK)
      put(c->t, "%-6s = %s  # AUTO's default\n", dr[i].key, num(dr[i].v, nb, sizeof nb));
}

static void copy_same(ctx *c) {
  char nb[40];
  int v;
  double x;
  for (size_t i = 0; i < sizeof same_int / sizeof *same_int; i++) {
    if (whirl_auto_constants_int(c->ac, same_int[i], &v) != WHIRL_OK) continue;
    /* equilibria do not use the mesh; AUTO accepts any NTST, NCOL there */
    if (c->ips != 2 && c->ips != 4 && (!strcmp(same_int[i], "NTST") || !strcmp(same_int[i], "NCOL")) &&
        v < 2)
      put(c->t, "# note: %s = %d (no mesh for equilibria)\n", same_int[i], v);
    else put(c->t, "%-6s = %d\n", same_int[i], v);
  }
  for (size_t i = 0; i < sizeof same_real / sizeof *same_real; i++)
    if (whirl_auto_constants_real(c->ac, same_real[i], &x) == WHIRL_OK)
      put(c->t, "%-6s = %s\n", same_real[i], num(x, nb, sizeof nb));
}

/* IPS, ISW, JAC: the values whirl has; others refused at their line. */
static int problem(ctx *c) {
  int ips = 1, isw = 1, jac = 0;
  whirl_auto_constants_int(c->ac, "IPS", &ips);
  whirl_auto_constants_int(c->ac, "ISW", &isw);
  if (ips != 1 && ips != 2 && ips != 4 && ips != -1)
    return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, "IPS"),
                                     "IPS = %d: whirl runs AUTO's equilibria (1), periodic "
                                     "orbits (2), boundary-value problems (4) and fixed "
                                     "points of maps (-1) only", ips);
  if (isw != 1 && isw != -1 && isw != 2 && isw != 3)
    return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, "ISW"),
                                     "ISW = %d: whirl has ISW = 1, -1, 2 and 3 only", isw);
  c->ips = ips;
  put(c->t, "IPS    = %d\nISW    = %d\n", ips, isw);
  /* AUTO's meshes of orbits (EQDF), and its MAX U(i) of an orbit, the
   * largest value at the mesh nodes */
  put(c->t, "MESH_RULE = jumps\nORBIT_MAX = nodes\nEQ_STEP = sphere\n");
  /* AUTO's phase condition of orbits (ICPS at the nodes, UPOLD the
   * model's f there) */
  put(c->t, "PHASE = nodes\n");
  /* AUTO's difference quotients of BVPs (FUNI, ICNI with JAC = 0) */
  put(c->t, "DIFFERENCES = auto\n");
  /* AUTO's ICND gets its direction vector as UDOT */
  put(c->t, "UDOT = direction\n");
  /* a new point's tangent as AUTO's direction vector, unrefined */
  put(c->t, "TANGENT = iterate\n");
  /* the branch goes on from the special point located to convergence, as
   * AUTO's at EPSS -> 0 (LOCATE = auto, from where AUTO's own localisation
   * to EPSS ends, follows AUTO's step sequence at the file's EPSS but
   * agreed with fewer of AUTO's printed points: doc/auto-reference.md) */
  put(c->t, "LOCATE = converged\n");
  /* a Newton failure at DSMIN ends the branch in AUTO's MX label */
  put(c->t, "MX = label\n");
  /* AUTO's default JAC is 0 (finite differences), whirl's 1: always said */
  whirl_auto_constants_int(c->ac, "JAC", &jac);
  put(c->t, "JAC    = %d%s\n", jac != 0, jac == -1 ? "  # AUTO: JAC = -1 (DFDU only)" : "");
  return WHIRL_OK;
}

/* ICP: indices; PAR(11) of orbits is PERIOD. */
static int icp(ctx *c) {
  const size_t n = whirl_auto_constants_count(c->ac, "ICP");
  if (!n)
    return whirl_auto_constants_fail(c->ac, 1, "ICP (the continuation parameters) missing");
  put(c->t, "ICP    = [");
  for (size_t i = 0; i < n; i++) {
    whirl_auto_item it;
    char ref[32];
    whirl_auto_constants_item(c->ac, "ICP", i, &it);
    int r = par_ref(c, "ICP", &it, ref, sizeof ref);
    if (r < 0) return WHIRL_EINVAL;
    if (r == 0)
      return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, "ICP"),
                                       "ICP: PAR(%d) beyond NPAR = %zu", it.index, c->o->npar);
    put(c->t, "%s%s", i ? ", " : "", ref);
  }
  put(c->t, "]\n");
  return WHIRL_OK;
}

/* IRS (or the caller's label), with S. */
static int restart(ctx *c) {
  char lab[64] = "";
  int irs = 0;
  const char *t = whirl_auto_constants_text(c->ac, "IRS");
  if (c->o->label) snprintf(lab, sizeof lab, "%s", c->o->label);
  else if (t) snprintf(lab, sizeof lab, "%s", t);
  else if (whirl_auto_constants_int(c->ac, "IRS", &irs) == WHIRL_OK && irs != 0)
    snprintf(lab, sizeof lab, "%d", irs);
  if (!lab[0]) return WHIRL_OK;
  if (!c->o->restart)
    return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, "IRS"),
                                     "IRS = %s: no earlier run to restart from", lab);
  put(c->t, "S      = '%s'\nIRS    = %s\n", c->o->restart, lab);
  return WHIRL_OK;
}

/* PAR = {k: v}, U = {k: v}. */
static int values(ctx *c) {
  int ndim = 0;
  whirl_auto_constants_int(c->ac, "NDIM", &ndim);
  static const char *const keys[] = {"PAR", "U"};
  for (int k = 0; k < 2; k++) {
    const size_t n = whirl_auto_constants_count(c->ac, keys[k]);
    if (!n) continue;
    put(c->t, "%-6s = {", keys[k]);
    for (size_t i = 0; i < n; i++) {
      whirl_auto_item it;
      char ref[32];
      whirl_auto_constants_item(c->ac, keys[k], i, &it);
      if (it.nvalues != 1)
        return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, keys[k]),
                                         "%s: one value an index", keys[k]);
      int r = k ? state_ref(c, "U", &it, ndim) : par_ref(c, "PAR", &it, ref, sizeof ref);
      if (r <= 0 || (!k && !strcmp(ref, "PERIOD")))
        return r < 0 || k ? WHIRL_EINVAL
                          : whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, "PAR"),
                                                      "PAR: PAR(%d) is not a parameter of the "
                                                      "model (NPAR = %zu)", it.index, c->o->npar);
      if (k) snprintf(ref, sizeof ref, "%d", r);
      char nb[40];
      put(c->t, "%s%s: %s", i ? ", " : "", ref, num(it.values[0], nb, sizeof nb));
    }
    put(c->t, "}\n");
  }
  return WHIRL_OK;
}

/* UZR and UZSTOP: a dictionary each, one entry a parameter; a negative
 * UZR index is a stop (AUTO-07p manual, UZR).  Indices beyond NPAR are
 * noted. */
typedef struct uz {
  char ref[32];
  int stop;
  const double *v;
  size_t n;
} uz;

static void put_uz(ctx *c, const uz *u, size_t n, int stop) {
  int first = 1;
  for (size_t i = 0; i < n; i++) {
    if (u[i].stop != stop) continue;
    int seen = 0; /* an earlier entry of this parameter wrote it */
    for (size_t j = 0; j < i; j++) seen |= u[j].stop == stop && !strcmp(u[j].ref, u[i].ref);
    if (seen) continue;
    put(c->t, "%s%s: [", first ? (stop ? "UZSTOP = {" : "UZR    = {") : ", ", u[i].ref);
    int k = 0;
    for (size_t j = i; j < n; j++)
      if (u[j].stop == stop && !strcmp(u[j].ref, u[i].ref))
        for (size_t m = 0; m < u[j].n; m++) {
          char nb[40];
          put(c->t, "%s%s", k++ ? ", " : "", num(u[j].v[m], nb, sizeof nb));
        }
    put(c->t, "]");
    first = 0;
  }
  if (!first) put(c->t, "}\n");
}

static int user_points(ctx *c) {
  static const char *const keys[] = {"UZR", "UZSTOP"};
  const size_t cap = whirl_auto_constants_count(c->ac, "UZR") +
                     whirl_auto_constants_count(c->ac, "UZSTOP");
  uz *u = calloc(cap + 1, sizeof *u);
  size_t n = 0;
  if (!u) return WHIRL_ENOMEM;
  for (int k = 0; k < 2; k++)
    for (size_t i = 0; i < whirl_auto_constants_count(c->ac, keys[k]); i++) {
      whirl_auto_item it;
      whirl_auto_constants_item(c->ac, keys[k], i, &it);
      const int neg = !it.name && it.index < 0;
      if (neg) it.index = -it.index;
      int r = par_ref(c, keys[k], &it, u[n].ref, sizeof u[n].ref);
      if (r < 0) {
        free(u);
        return WHIRL_EINVAL;
      }
      if (r == 0) {
        put(c->t, "# note: %s on PAR(%d): not a parameter of the model (a PVLS quantity?), "
                  "ignored\n", keys[k], it.index);
        continue;
      }
      u[n].stop = k == 1 || neg, u[n].v = it.values, u[n].n = it.nvalues;
      n++;
    }
  put_uz(c, u, n, 0);
  put_uz(c, u, n, 1);
  free(u);
  return WHIRL_OK;
}

/* THL = {k: w} (parameters, PERIOD) and THU = {k: w} (state components):
 * the weights of the arclength norm, copied where they name what the model
 * has (an empty THL too); THL of a parameter beyond NPAR (e.g. PAR(11) of
 * equilibria) is noted and left out. */
static int arclength_weights(ctx *c) {
  int ndim = 0;
  whirl_auto_constants_int(c->ac, "NDIM", &ndim);
  static const char *const keys[] = {"THL", "THU"};
  for (int k = 0; k < 2; k++) {
    const size_t n = whirl_auto_constants_count(c->ac, keys[k]);
    char dict[1024] = "", left[256] = "";
    size_t used = 0, nleft = 0;
    for (size_t i = 0; i < n; i++) {
      whirl_auto_item it;
      char ref[32], nb[40];
      whirl_auto_constants_item(c->ac, keys[k], i, &it);
      if (it.nvalues != 1)
        return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, keys[k]),
                                         "%s: one weight an index", keys[k]);
      int r = k ? state_ref(c, keys[k], &it, ndim) : par_ref(c, keys[k], &it, ref, sizeof ref);
      if (r < 0 || (k && r == 0)) return WHIRL_EINVAL;
      if (r == 0) { /* THL of a parameter the model does not have */
        nleft += (size_t)snprintf(left + nleft, nleft < sizeof left ? sizeof left - nleft : 0,
                                  "%s%d", nleft ? ", " : "", it.index);
        continue;
      }
      if (k) snprintf(ref, sizeof ref, "%d", r);
      used += (size_t)snprintf(dict + used, used < sizeof dict ? sizeof dict - used : 0,
                               "%s%s: %s", used ? ", " : "", ref, num(it.values[0], nb, sizeof nb));
    }
    if (used >= sizeof dict || nleft >= sizeof left)
      return whirl_auto_constants_fail(c->ac, whirl_auto_constants_line(c->ac, keys[k]),
                                       "%s: too many weights", keys[k]);
    /* THL = {} given is kept: AUTO's default for orbits without a THL
     * line is THL = {11: 0}, with an empty one the period is weighted 1 */
    if (used || (!k && !nleft && whirl_auto_constants_line(c->ac, keys[k]) > 0))
      put(c->t, "%s    = {%s}\n", keys[k], dict);
    if (nleft) put(c->t, "# note: %s on PAR(%s): not a parameter of the model, ignored\n",
                   keys[k], left);
  }
  return WHIRL_OK;
}

/* dat = 'NAME': DAT, the file NAME, else NAME.dat, in opts->dir (AUTO-07p
 * opens them in that order, toolboxbv.f90 STPNUB); a start of orbits
 * (IPS = 2) or of a boundary-value problem (IPS = 4). */
static int dat(ctx *c) {
  const char *d = whirl_auto_constants_text(c->ac, "dat");
  const int line = whirl_auto_constants_line(c->ac, "dat");
  if (!d || !d[0]) return WHIRL_OK;
  if (c->ips != 2 && c->ips != 4)
    return whirl_auto_constants_fail(c->ac, line, "dat = '%s': a data file starts periodic "
                                     "orbits (IPS = 2) or a boundary-value problem (IPS = 4), "
                                     "not IPS = %d", d, c->ips);
  char path[2][4200];
  for (int k = 0; k < 2; k++) {
    snprintf(path[k], sizeof path[k], "%s%s%s%s", c->o->dir && d[0] != '/' ? c->o->dir : "",
             c->o->dir && d[0] != '/' ? "/" : "", d, k ? ".dat" : "");
    FILE *f = fopen(path[k], "r");
    if (f) {
      fclose(f);
      if (strchr(path[k], '\'') || strchr(path[k], '\n'))
        return whirl_auto_constants_fail(c->ac, line, "dat: %s: a quote or newline in the path",
                                         path[k]);
      put(c->t, "DAT    = '%s'\n", path[k]);
      return WHIRL_OK;
    }
  }
  return whirl_auto_constants_fail(c->ac, line, "dat = '%s': no data file %s or %s", d, path[0],
                                   path[1]);
}

/* STOP: AUTO's stopping points ['TR1', 'LP2'], as whirl's STOP (its types
 * checked by the run file's reader, at this file's line in its message). */
static int stops(ctx *c) {
  size_t n = whirl_auto_constants_count(c->ac, "STOP");
  for (size_t i = 0; i < n; i++) {
    whirl_auto_item it;
    if (whirl_auto_constants_item(c->ac, "STOP", i, &it) || !it.name) continue;
    put(c->t, "%s%s", i ? ", " : "STOP   = [", it.name);
  }
  if (n) put(c->t, "]\n");
  return WHIRL_OK;
}

/* TY = 'HBk' on a restart of orbits (IPS = 2) from an equilibrium label:
 * the label taken as a Hopf point whose orbits have the period PAR(k)
 * (AUTO's RSPTBV: ITP = 3, PAR(11) = PAR(k)): HB_PERIOD.  Any other TY
 * is noted as unused. */
static int type_override(ctx *c) {
  const char *ty = whirl_auto_constants_text(c->ac, "TY");
  const int line = whirl_auto_constants_line(c->ac, "TY");
  if (!ty || !ty[0]) return WHIRL_OK;
  if (c->ips == 2 && (ty[0] == 'H' || ty[0] == 'h') && (ty[1] == 'B' || ty[1] == 'b') && ty[2]) {
    char *end;
    const long k = strtol(ty + 2, &end, 10);
    if (*end || k < 1 || k > 100000)
      return whirl_auto_constants_fail(c->ac, line, "TY = '%s': HB and a parameter number "
                                       "(the period of the orbits, PAR(k)) expected", ty);
    put(c->t, "HB_PERIOD = PAR(%ld)\n", k);
    return WHIRL_OK;
  }
  put(c->t, "# note: TY (line %d) is not used by whirl\n", line);
  return WHIRL_OK;
}

/* Keys whirl has no use for yet: noted. */
static int unused(ctx *c) {
  static const char *const noted[] = {"SP", "IEQUIB", "ITWIST",
                                      "ISTART", "IREV", "IFIXED", "IPSI"};
  for (size_t i = 0; i < sizeof noted / sizeof *noted; i++)
    if (whirl_auto_constants_line(c->ac, noted[i]))
      put(c->t, "# note: %s (line %d) is not used by whirl\n", noted[i],
          whirl_auto_constants_line(c->ac, noted[i]));
  return WHIRL_OK;
}

int whirl_auto_constants_runfile(whirl_auto_constants *ac, const whirl_auto_runfile_opts *o,
                                 char **out) {
  if (!ac || !o || !o->model || !out) return WHIRL_EINVAL;
  *out = NULL;
  text t = {NULL, 0, 0, 0};
  ctx c = {ac, o, 1, &t};
  put(&t, "# whirl run file for the AUTO-07p constants %s\n", whirl_auto_constants_name(ac));
  put(&t, "model  = '%s'\n", o->model);
  if (o->out) put(&t, "OUT    = '%s'\n", o->out);
  int rc = problem(&c);
  if (!rc) rc = icp(&c);
  if (!rc) rc = restart(&c);
  if (!rc) copy_same(&c);
  if (!rc) auto_defaults(&c);
  if (!rc) rc = values(&c);
  if (!rc) rc = user_points(&c);
  if (!rc) rc = arclength_weights(&c);
  if (!rc) rc = dat(&c);
  if (!rc) rc = stops(&c);
  if (!rc) rc = type_override(&c);
  if (!rc) rc = unused(&c);
  if (!rc && t.oom) rc = WHIRL_ENOMEM;
  if (rc) {
    free(t.s);
    return rc;
  }
  *out = t.s;
  return WHIRL_OK;
}
