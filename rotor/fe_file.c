/* rotor/fe_file.c — the rotor file (doc/rotor-file.md): one statement a
 * line, `KEYWORD [NAME] key=value ...`, `#` comments, SI units.  Every key
 * is typed and range-checked from a per-keyword table; every error is one
 * message "FILE:LINE: what is wrong" (WHIRL_EINVAL).  Numbers are read by
 * whirl_run_number (the run files' syntax).  Checks that need the whole
 * file (nodes on the shaft, a continuous shaft, mass, pedestal names) run
 * after the last line, each blamed on the line that named the thing.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/runfile.h>

#include "fe_impl.h"

/* ---- nonlinear kinds ---------------------------------------------------- */

static const char *const kind_names[] = {"sfd-short-pi", "sfd-short-2pi", "sfd-long",
                                         "sfd-inertia",  "journal-short", "rub",
                                         "cubic"};
#define NKIND ((int)(sizeof kind_names / sizeof kind_names[0]))

const char *whirl_fe_nl_kind_name(whirl_fe_nl_kind kind) {
  return (int)kind >= 0 && (int)kind < NKIND ? kind_names[kind] : "unknown";
}

int whirl_fe_nl_kind_from_name(const char *name) {
  for (int k = 0; name && k < NKIND; ++k)
    if (!strcmp(name, kind_names[k])) return k;
  return -1;
}

/* ---- errors ------------------------------------------------------------- */

typedef struct ctx {
  fe_desc *d;
  int line;
  char *msg;
  size_t len;
  int *elline;  /* elline[n]: the line of the shaft element from node n, 0 */
  int nelline;  /* its length (the largest node so far + 1) */
} ctx;

static int fail_at(ctx *c, int line, const char *fmt, ...) WHIRL_PRINTF_LIKE(3, 4);
static int fail_at(ctx *c, int line, const char *fmt, ...) {
  char where[600];
  snprintf(where, sizeof where, "%s:%d", c->d->file, line);
  va_list ap;
  va_start(ap, fmt);
  whirl_errmsg_vat(c->msg, c->len, WHIRL_EINVAL, where, fmt, ap);
  va_end(ap);
  return WHIRL_EINVAL;
}
#define FAIL(c, ...) fail_at((c), (c)->line, __VA_ARGS__)

/* ---- key tables ----------------------------------------------------------- */

enum { K_REQ = 1, K_POS = 2, K_NONNEG = 4, K_NODE = 8, K_STR = 16 };

typedef struct kv {
  const char *key;
  int flags;
  double *num; /* numbers (K_NODE: an integer >= 0 stored as double) */
  char *str;   /* K_STR: a FE_NAME buffer */
  int seen;
} kv;

static int set_key(ctx *c, const char *kw, kv *t, size_t nt, const char *k, const char *v) {
  kv *e = NULL;
  for (size_t m = 0; m < nt && !e; ++m)
    if (!strcmp(t[m].key, k)) e = &t[m];
  if (!e) {
    char keys[300] = "";
    for (size_t m = 0; m < nt; ++m)
      snprintf(keys + strlen(keys), sizeof keys - strlen(keys), "%s%s", m ? ", " : "", t[m].key);
    return FAIL(c, "unknown key '%s' for %s (keys: %s)", k, kw, keys);
  }
  if (e->seen) return FAIL(c, "%s: key '%s' given twice", kw, k);
  e->seen = 1;
  if (e->flags & K_STR) {
    if (!*v || strlen(v) >= FE_NAME) return FAIL(c, "%s: bad %s '%s'", kw, k, v);
    strcpy(e->str, v);
    return 0;
  }
  double x;
  if (whirl_run_number(v, &x) != WHIRL_OK) return FAIL(c, "%s: %s: '%s' is not a number", kw, k, v);
  if ((e->flags & K_NODE) && (x < 0 || x != floor(x) || x > 1e6))
    return FAIL(c, "%s: %s must be a node number >= 0 (got '%s')", kw, k, v);
  if ((e->flags & K_POS) && !(x > 0)) return FAIL(c, "%s: %s must be > 0 (got %s)", kw, k, v);
  if ((e->flags & K_NONNEG) && x < 0) return FAIL(c, "%s: %s must be >= 0 (got %s)", kw, k, v);
  *e->num = x;
  return 0;
}

/* Fill the table from the tokens key=value; the required keys must be there. */
static int parse_keys(ctx *c, const char *kw, char **tok, int ntok, kv *t, size_t nt) {
  for (int k = 0; k < ntok; ++k) {
    char *eq = strchr(tok[k], '=');
    if (!eq || eq == tok[k]) return FAIL(c, "%s: '%s' is not key=value", kw, tok[k]);
    *eq = '\0';
    int rc = set_key(c, kw, t, nt, tok[k], eq + 1);
    if (rc) return rc;
  }
  for (size_t m = 0; m < nt; ++m)
    if ((t[m].flags & K_REQ) && !t[m].seen) return FAIL(c, "%s needs %s=", kw, t[m].key);
  return 0;
}

#define NT(t) (sizeof(t) / sizeof((t)[0]))

/* Append to a growing array: 0 or WHIRL_ENOMEM. */
#define PUSH(arr, n, cap)                                                     \
  (((n) < (cap)) ? 0                                                           \
                 : grow_array((void **)&(arr), &(cap), sizeof *(arr)))
static int grow_array(void **a, size_t *cap, size_t size) {
  size_t nc = *cap ? 2 * *cap : 8;
  void *p = realloc(*a, nc * size);
  if (!p) return WHIRL_ENOMEM;
  *a = p;
  *cap = nc;
  return 0;
}

static int find_material(const fe_desc *d, const char *name) {
  for (size_t k = 0; k < d->nmat; ++k)
    if (!strcmp(d->mat[k].name, name)) return (int)k;
  return -1;
}

static int check_diameters(ctx *c, const char *kw, double od, double id) {
  if (id >= od)
    return FAIL(c, "%s: inner diameter id=%g must be smaller than the outer diameter od=%g", kw, id, od);
  return 0;
}

/* ---- statements ------------------------------------------------------------ */

static int st_material(ctx *c, char *name, char **tok, int ntok) {
  fe_desc *d = c->d;
  if (!name) return FAIL(c, "material needs a name: material NAME E=.. G=.. rho=..");
  if (strlen(name) >= FE_NAME) return FAIL(c, "material: name too long");
  int k = find_material(d, name);
  if (k >= 0) return FAIL(c, "material '%s' defined twice (first at line %d)", name, d->mat[k].line);
  fe_material m = {.line = c->line};
  strcpy(m.name, name);
  kv t[] = {{"E", K_REQ | K_POS, &m.E, NULL, 0},
            {"G", K_REQ | K_POS, &m.G, NULL, 0},
            {"rho", K_REQ | K_NONNEG, &m.rho, NULL, 0}};
  int rc = parse_keys(c, "material", tok, ntok, t, NT(t));
  if (rc) return rc;
  /* Cowper's shear coefficient needs Poisson's ratio ν = E/(2G) − 1 of an
   * isotropic solid, −1 < ν ≤ 1/2: G > 10 E (ν → −1) makes it vanish,
   * the shear deformation grow without bound */
  const double nu = m.E / (2 * m.G) - 1;
  if (!(nu > -0.95 && nu <= 0.5))
    return FAIL(c, "material '%s': E = %g and G = %g give Poisson's ratio %g, outside "
                "(-0.95, 0.5] (for a rigid shaft scale both: G = E/2.6)",
                name, m.E, m.G, nu);
  if (PUSH(d->mat, d->nmat, d->cmat)) return WHIRL_ENOMEM;
  d->mat[d->nmat++] = m;
  return 0;
}

static int st_shaft(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double from = 0, to = 0, nel = 0, length = 0, od = 0, id = 0;
  char mat[FE_NAME] = "";
  kv t[] = {{"from", K_REQ | K_NODE, &from, NULL, 0},   {"to", K_REQ | K_NODE, &to, NULL, 0},
            {"elements", K_POS, &nel, NULL, 0},         {"length", K_REQ | K_POS, &length, NULL, 0},
            {"od", K_REQ | K_POS, &od, NULL, 0},        {"id", K_NONNEG, &id, NULL, 0},
            {"material", K_REQ | K_STR, NULL, mat, 0}};
  int rc = parse_keys(c, "shaft", tok, ntok, t, NT(t));
  if (rc || (rc = check_diameters(c, "shaft", od, id))) return rc;
  if (!(to > from)) return FAIL(c, "shaft: to=%g must be greater than from=%g", to, from);
  if (t[2].seen && nel != to - from)
    return FAIL(c, "shaft: elements=%g but from=%g to=%g makes %g elements", nel, from, to, to - from);
  int mk = find_material(d, mat);
  if (mk < 0) return FAIL(c, "shaft: unknown material '%s' (define it before its first use)", mat);
  if ((int)to > c->nelline) { /* a line per node: the check below is O(1) */
    int *e = realloc(c->elline, (size_t)to * sizeof *e);
    if (!e) return WHIRL_ENOMEM;
    memset(e + c->nelline, 0, ((size_t)to - (size_t)c->nelline) * sizeof *e);
    c->elline = e;
    c->nelline = (int)to;
  }
  for (int n = (int)from; n < (int)to; ++n) {
    if (c->elline[n])
      return FAIL(c, "shaft: the element between nodes %d and %d is defined twice (first at line %d)",
                  n, n + 1, c->elline[n]);
    c->elline[n] = c->line;
    if (PUSH(d->el, d->nel, d->cel)) return WHIRL_ENOMEM;
    d->el[d->nel++] = (fe_element){n, length / (to - from), od, id, mk, c->line};
  }
  return 0;
}

/* disk node=N mass= ip= it=, or disk node=N width= od= id= material= */
static int st_disk(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double node = 0, m = 0, ip = 0, it = 0, w = 0, od = 0, id = 0;
  char mat[FE_NAME] = "";
  kv t[] = {{"node", K_REQ | K_NODE, &node, NULL, 0}, {"mass", K_NONNEG, &m, NULL, 0},
            {"ip", K_NONNEG, &ip, NULL, 0},           {"it", K_NONNEG, &it, NULL, 0},
            {"width", K_POS, &w, NULL, 0},            {"od", K_POS, &od, NULL, 0},
            {"id", K_NONNEG, &id, NULL, 0},           {"material", K_STR, NULL, mat, 0}};
  int rc = parse_keys(c, "disk", tok, ntok, t, NT(t));
  if (rc) return rc;
  int by_mass = t[1].seen || t[2].seen || t[3].seen;
  int by_geom = t[4].seen || t[5].seen || t[6].seen || t[7].seen;
  if (by_mass == by_geom || (by_mass && !t[1].seen) || (by_geom && !(t[4].seen && t[5].seen && t[7].seen)))
    return FAIL(c, "disk: give either mass= [ip= it=] or width= od= [id=] material=");
  if (by_geom) {
    if ((rc = check_diameters(c, "disk", od, id))) return rc;
    int mk = find_material(d, mat);
    if (mk < 0) return FAIL(c, "disk: unknown material '%s' (define it before its first use)", mat);
    /* a uniform annulus of width w: m, Ip = m(od²+id²)/8, It = Ip/2 + m w²/12 */
    m = d->mat[mk].rho * WHIRL_PI * w * (od * od - id * id) / 4;
    ip = m * (od * od + id * id) / 8;
    it = ip / 2 + m * w * w / 12;
  }
  for (size_t k = 0; k < d->ndisk; ++k)
    if (d->disk[k].node == (int)node)
      return FAIL(c, "disk: a disk at node %g is already defined (line %d)", node, d->disk[k].line);
  if (PUSH(d->disk, d->ndisk, d->cdisk)) return WHIRL_ENOMEM;
  d->disk[d->ndisk++] = (fe_disk){(int)node, m, ip, it, c->line};
  return 0;
}

/* the 8 coefficients kyy kyz kzy kzz cyy cyz czy czz, in k[4], c[4] */
#define KC_KEYS(k, cc)                                                          \
  {"kyy", 0, &(k)[0], NULL, 0}, {"kyz", 0, &(k)[1], NULL, 0},                    \
  {"kzy", 0, &(k)[2], NULL, 0}, {"kzz", 0, &(k)[3], NULL, 0},                    \
  {"cyy", 0, &(cc)[0], NULL, 0}, {"cyz", 0, &(cc)[1], NULL, 0},                  \
  {"czy", 0, &(cc)[2], NULL, 0}, {"czz", 0, &(cc)[3], NULL, 0}

static int st_bearing(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  fe_bearing b = {.line = c->line, .pedestal = -1};
  double node = 0;
  kv t[] = {{"node", K_REQ | K_NODE, &node, NULL, 0}, KC_KEYS(b.k, b.c),
            {"pedestal", K_STR, NULL, b.pedestal_name, 0}};
  int rc = parse_keys(c, "bearing", tok, ntok, t, NT(t));
  if (rc) return rc;
  b.node = (int)node;
  for (size_t k = 0; k < d->nbrg; ++k)
    if (d->brg[k].node == b.node && !strcmp(d->brg[k].pedestal_name, b.pedestal_name))
      return FAIL(c, "bearing: a bearing at node %d is already defined (line %d)", b.node, d->brg[k].line);
  if (PUSH(d->brg, d->nbrg, d->cbrg)) return WHIRL_ENOMEM;
  d->brg[d->nbrg++] = b;
  return 0;
}

static int st_pedestal(ctx *c, char *name, char **tok, int ntok) {
  fe_desc *d = c->d;
  if (!name) return FAIL(c, "pedestal needs a name: pedestal NAME mass=.. kyy=.. ...");
  if (strlen(name) >= FE_NAME) return FAIL(c, "pedestal: name too long");
  for (size_t k = 0; k < d->nped; ++k)
    if (!strcmp(d->ped[k].name, name))
      return FAIL(c, "pedestal '%s' defined twice (first at line %d)", name, d->ped[k].line);
  fe_pedestal p = {.line = c->line};
  strcpy(p.name, name);
  kv t[] = {{"mass", K_REQ | K_POS, &p.mass, NULL, 0}, KC_KEYS(p.k, p.c)};
  int rc = parse_keys(c, "pedestal", tok, ntok, t, NT(t));
  if (rc) return rc;
  if (PUSH(d->ped, d->nped, d->cped)) return WHIRL_ENOMEM;
  d->ped[d->nped++] = p;
  return 0;
}

/* A nonlinear element: the common keys, then those of its kind. */
static int st_nonlinear(ctx *c, int kind, char **tok, int ntok) {
  fe_desc *d = c->d;
  whirl_fe_nl e = {.kind = (whirl_fe_nl_kind)kind, .pedestal = -1, .line = c->line};
  whirl_fe_nl_params *q = &e.par;
  char ped[FE_NAME] = "";
  double node = 0;
  const int film = kind != WHIRL_FE_RUB && kind != WHIRL_FE_CUBIC;
  const int F = film ? K_REQ | K_POS : 0;
  kv t[] = {{"node", K_REQ | K_NODE, &node, NULL, 0},
            {"pedestal", K_STR, NULL, ped, 0},
            {"offset-y", 0, &e.offset[0], NULL, 0},
            {"offset-z", 0, &e.offset[1], NULL, 0},
            {"clearance", film ? F : K_REQ | K_NONNEG, &q->clearance, NULL, 0},
            {"radius", F, &q->radius, NULL, 0},
            {"length", F, &q->length, NULL, 0},
            {"viscosity", F, &q->viscosity, NULL, 0},
            {"density", K_REQ | K_POS, &q->density, NULL, 0},
            {"k-contact", K_REQ | K_POS, &q->k_contact, NULL, 0},
            {"friction", K_NONNEG, &q->friction, NULL, 0},
            {"k1", K_REQ, &q->k1, NULL, 0},
            {"k3", K_REQ, &q->k3, NULL, 0}};
  /* the kind's own keys: the common four, then its parameters */
  size_t hi = 8;
  if (kind == WHIRL_FE_SFD_INERTIA) hi = 9;
  if (kind == WHIRL_FE_RUB) {
    kv rub[] = {t[0], t[1], t[2], t[3], t[4], t[9], t[10]};
    memcpy(t, rub, sizeof rub);
    hi = 7;
  } else if (kind == WHIRL_FE_CUBIC) {
    kv cub[] = {t[0], t[1], t[2], t[3], t[11], t[12]};
    memcpy(t, cub, sizeof cub);
    hi = 6;
  }
  int rc = parse_keys(c, kind_names[kind], tok, ntok, t, hi);
  if (rc) return rc;
  if (kind == WHIRL_FE_CUBIC && !(isfinite(q->k1) && isfinite(q->k3)))
    return FAIL(c, "cubic: k1 and k3 must be finite");
  e.node = (int)node;
  for (size_t k = 0; k < d->nnl; ++k)
    if (d->nl[k].node == e.node && d->nl[k].kind == e.kind)
      return FAIL(c, "%s at node %d is already defined (line %d)", kind_names[kind], e.node, d->nl[k].line);
  if (PUSH(d->nl, d->nnl, d->cnl)) return WHIRL_ENOMEM;
  size_t cap = d->cnl;
  char(*np)[FE_NAME] = realloc(d->nl_ped, cap * sizeof *np);
  if (!np) return WHIRL_ENOMEM;
  d->nl_ped = np;
  strcpy(d->nl_ped[d->nnl], ped);
  d->nl[d->nnl++] = e;
  return 0;
}

static int st_unbalance(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double node = 0, me = 0, ph = 0;
  kv t[] = {{"node", K_REQ | K_NODE, &node, NULL, 0},
            {"me", K_REQ | K_NONNEG, &me, NULL, 0},
            {"phase-deg", 0, &ph, NULL, 0}};
  int rc = parse_keys(c, "unbalance", tok, ntok, t, NT(t));
  if (rc) return rc;
  for (size_t k = 0; k < d->nunb; ++k)
    if (d->unb[k].node == (int)node)
      return FAIL(c, "unbalance at node %g is already defined (line %d)", node, d->unb[k].line);
  if (PUSH(d->unb, d->nunb, d->cunb)) return WHIRL_ENOMEM;
  d->unb[d->nunb++] = (fe_unbalance){(int)node, me, ph * WHIRL_PI / 180, c->line};
  return 0;
}

static int st_load(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  fe_load l = {.line = c->line};
  double node = 0;
  kv t[] = {{"node", K_REQ | K_NODE, &node, NULL, 0}, {"fy", 0, &l.f[0], NULL, 0},
            {"fz", 0, &l.f[1], NULL, 0},              {"my", 0, &l.f[2], NULL, 0},
            {"mz", 0, &l.f[3], NULL, 0}};
  int rc = parse_keys(c, "load", tok, ntok, t, NT(t));
  if (rc) return rc;
  l.node = (int)node;
  for (size_t k = 0; k < d->nload; ++k)
    if (d->load[k].node == l.node)
      return FAIL(c, "load at node %d is already defined (line %d)", l.node, d->load[k].line);
  if (PUSH(d->load, d->nload, d->cload)) return WHIRL_ENOMEM;
  d->load[d->nload++] = l;
  return 0;
}

static int once(ctx *c, const char *kw, int *line) {
  if (*line) return FAIL(c, "%s given twice (first at line %d)", kw, *line);
  *line = c->line;
  return 0;
}

static int st_gravity(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double g = 0;
  char dir[FE_NAME] = "";
  kv t[] = {{"g", K_REQ | K_NONNEG, &g, NULL, 0}, {"direction", K_REQ | K_STR, NULL, dir, 0}};
  int rc = once(c, "gravity", &d->gravity_line);
  if (rc || (rc = parse_keys(c, "gravity", tok, ntok, t, NT(t)))) return rc;
  const char *names[] = {"+y", "-y", "+z", "-z", "y", "z"};
  const int axis[] = {0, 0, 1, 1, 0, 1};
  const double sign[] = {1, -1, 1, -1, 1, 1};
  for (int k = 0; k < 6; ++k)
    if (!strcmp(dir, names[k])) {
      d->gravity[axis[k]] = sign[k] * g;
      return 0;
    }
  return FAIL(c, "gravity: direction must be +y, -y, +z or -z (got '%s')", dir);
}

/* a speed unit's factor to rad/s: rpm, rad/s, hz */
static int unit_factor(ctx *c, const char *kw, const char *u, double *f) {
  if (!*u || !strcmp(u, "rad/s")) *f = 1;
  else if (!strcmp(u, "rpm")) *f = WHIRL_PI / 30;
  else if (!strcmp(u, "hz") || !strcmp(u, "Hz")) *f = 2 * WHIRL_PI;
  else return FAIL(c, "%s: unit must be rpm, rad/s or hz (got '%s')", kw, u);
  return 0;
}

static int st_speed(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double from = 0, to = 0, f = 1;
  char unit[FE_NAME] = "";
  kv t[] = {{"from", K_REQ | K_NONNEG, &from, NULL, 0},
            {"to", K_REQ | K_POS, &to, NULL, 0},
            {"unit", K_STR, NULL, unit, 0}};
  int rc = once(c, "speed", &d->speed_line);
  if (rc || (rc = parse_keys(c, "speed", tok, ntok, t, NT(t))) || (rc = unit_factor(c, "speed", unit, &f)))
    return rc;
  if (!(to > from)) return FAIL(c, "speed: to=%g must be greater than from=%g", to, from);
  d->speed_min = from * f;
  d->speed_max = to * f;
  return 0;
}

/* damping alpha=A beta=B: proportional (Rayleigh) damping of the shaft
 * elements, C_e = α M_e + β K_e, non-rotating. */
static int st_damping(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  kv t[] = {{"alpha", K_NONNEG, &d->damp_alpha, NULL, 0},
            {"beta", K_NONNEG, &d->damp_beta, NULL, 0}};
  int rc = once(c, "damping", &d->damping_line);
  if (rc || (rc = parse_keys(c, "damping", tok, ntok, t, NT(t)))) return rc;
  if (!(d->damp_alpha > 0) && !(d->damp_beta > 0))
    return FAIL(c, "damping: give alpha= (1/s) or beta= (s), or both");
  return 0;
}

/* nodes count=N: the nodes of a rotor whose linear part comes from
 * matrices (no shaft line needed). */
static int st_nodes(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double n = 0;
  kv t[] = {{"count", K_REQ | K_NODE, &n, NULL, 0}};
  int rc = once(c, "nodes", &d->nodes_line);
  if (rc || (rc = parse_keys(c, "nodes", tok, ntok, t, NT(t)))) return rc;
  if (n < 1 || n > 1e6) return FAIL(c, "nodes: count=%g must be between 1 and 1000000", n);
  d->nodes_count = (int)n;
  return 0;
}

/* matrices M=FILE C=FILE G=FILE K=FILE: Matrix Market files added to the
 * assembled matrices (fe_matrix.c), paths relative to the rotor file. */
static int st_matrices(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  static const char names[] = "MCGK";
  int rc = once(c, "matrices", &d->mtx_line);
  for (int k = 0; !rc && k < ntok; k++) {
    const char *eq = strchr(tok[k], '=');
    const char *w = eq && eq - tok[k] == 1 ? strchr(names, tok[k][0]) : NULL;
    if (!w || !eq[1]) return FAIL(c, "matrices: '%s' is not M=FILE, C=FILE, G=FILE or K=FILE", tok[k]);
    char *dst = d->mtx[w - names];
    if (dst[0]) return FAIL(c, "matrices: %c given twice", tok[k][0]);
    char dir[sizeof d->file];
    const char *slash = strrchr(d->file, '/');
    const int dirlen = eq[1] == '/' || !slash ? 0 : (int)(slash - d->file + 1);
    snprintf(dir, sizeof dir, "%.*s", dirlen, d->file);
    if (snprintf(dst, sizeof d->mtx[0], "%s%s", dir, eq + 1) >= (int)sizeof d->mtx[0])
      return FAIL(c, "matrices: the path of %c is too long", tok[k][0]);
  }
  if (!rc && !d->mtx[0][0] && !d->mtx[3][0]) return FAIL(c, "matrices: give at least M= or K=");
  return rc;
}

static int st_reference(ctx *c, char **tok, int ntok) {
  fe_desc *d = c->d;
  double om = 0, f = 1;
  char unit[FE_NAME] = "";
  kv t[] = {{"omega", K_REQ | K_POS, &om, NULL, 0}, {"unit", K_STR, NULL, unit, 0}};
  int rc = once(c, "reference", &d->reference_line);
  if (rc || (rc = parse_keys(c, "reference", tok, ntok, t, NT(t))) ||
      (rc = unit_factor(c, "reference", unit, &f)))
    return rc;
  d->omega_ref = om * f;
  return 0;
}

/* ---- lines --------------------------------------------------------------------- */

#define MAXTOK 64

static int statement(ctx *c, char *s) {
  char *hash = strchr(s, '#');
  if (hash) *hash = '\0';
  char *tok[MAXTOK];
  int ntok = 0;
  for (char *p = strtok(s, " \t\r\n"); p; p = strtok(NULL, " \t\r\n")) {
    if (ntok == MAXTOK) return FAIL(c, "too many items on the line");
    tok[ntok++] = p;
  }
  if (ntok == 0) return 0;
  const char *kw = tok[0];
  char *name = ntok > 1 && !strchr(tok[1], '=') ? tok[1] : NULL;
  int k = whirl_fe_nl_kind_from_name(kw);
  if (k >= 0) return st_nonlinear(c, k, tok + 1, ntok - 1);
  if (!strcmp(kw, "material")) return st_material(c, name, tok + 1 + !!name, ntok - 1 - !!name);
  if (!strcmp(kw, "pedestal")) return st_pedestal(c, name, tok + 1 + !!name, ntok - 1 - !!name);
  if (!strcmp(kw, "shaft")) return st_shaft(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "disk")) return st_disk(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "bearing")) return st_bearing(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "unbalance")) return st_unbalance(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "load")) return st_load(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "gravity")) return st_gravity(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "speed")) return st_speed(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "reference")) return st_reference(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "nodes")) return st_nodes(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "damping")) return st_damping(c, tok + 1, ntok - 1);
  if (!strcmp(kw, "matrices")) return st_matrices(c, tok + 1, ntok - 1);
  return FAIL(c, "unknown keyword '%s'", kw);
}

/* title: the rest of the line, verbatim (no comment) */
static int title(ctx *c, const char *s) {
  int rc = once(c, "title", &c->d->title_line);
  if (rc) return rc;
  s += strspn(s, " \t");
  snprintf(c->d->title, sizeof c->d->title, "%s", s);
  char *t = c->d->title;
  size_t n = strlen(t);
  while (n && (t[n - 1] == '\n' || t[n - 1] == '\r' || t[n - 1] == ' ' || t[n - 1] == '\t')) t[--n] = '\0';
  return 0;
}

static int read_lines(ctx *c, FILE *f) {
  char buf[4096];
  while (fgets(buf, sizeof buf, f)) {
    c->line++;
    size_t n = strlen(buf);
    if (n == sizeof buf - 1 && buf[n - 1] != '\n') return FAIL(c, "line too long (over 4094 characters)");
    const char *s = buf + strspn(buf, " \t");
    int rc = !strncmp(s, "title", 5) && (s[5] == ' ' || s[5] == '\t' || s[5] == '\n' || !s[5])
                 ? title(c, s + 5)
                 : statement(c, buf);
    if (rc) return rc;
  }
  if (ferror(f)) return FAIL(c, "read error");
  c->d->nlines = c->line;
  return 0;
}

/* ---- whole-file checks ----------------------------------------------------------- */

static int on_shaft(ctx *c, int node, int line, const char *what) {
  if (node < c->d->nnode) return 0;
  return fail_at(c, line, "%s: node %d is not on the shaft (nodes 0..%d)", what, node, c->d->nnode - 1);
}

static int find_pedestal(ctx *c, const char *name, int line, const char *what, int *idx) {
  *idx = -1;
  if (!*name) return 0;
  for (size_t k = 0; k < c->d->nped; ++k)
    if (!strcmp(c->d->ped[k].name, name)) {
      *idx = (int)k;
      return 0;
    }
  return fail_at(c, line, "%s: unknown pedestal '%s'", what, name);
}

static int check_nodes(ctx *c) {
  fe_desc *d = c->d;
  int rc = 0;
  for (size_t k = 0; k < d->ndisk && !rc; ++k) rc = on_shaft(c, d->disk[k].node, d->disk[k].line, "disk");
  for (size_t k = 0; k < d->nbrg && !rc; ++k) {
    fe_bearing *b = &d->brg[k];
    rc = on_shaft(c, b->node, b->line, "bearing");
    if (!rc) rc = find_pedestal(c, b->pedestal_name, b->line, "bearing", &b->pedestal);
  }
  for (size_t k = 0; k < d->nnl && !rc; ++k) {
    whirl_fe_nl *e = &d->nl[k];
    rc = on_shaft(c, e->node, e->line, kind_names[e->kind]);
    if (!rc) rc = find_pedestal(c, d->nl_ped[k], e->line, kind_names[e->kind], &e->pedestal);
  }
  for (size_t k = 0; k < d->nunb && !rc; ++k) rc = on_shaft(c, d->unb[k].node, d->unb[k].line, "unbalance");
  for (size_t k = 0; k < d->nload && !rc; ++k) rc = on_shaft(c, d->load[k].node, d->load[k].line, "load");
  return rc;
}

/* The matrices of the `matrices` line into d->imp, 4 nnode square each;
 * *mass gets M's trace over the translations (the rotor has mass). */
static int read_matrices(ctx *c, double *mass) {
  fe_desc *d = c->d;
  d->imp = calloc(4, sizeof *d->imp);
  if (!d->imp) return WHIRL_ENOMEM;
  for (int k = 0; k < 4; k++) {
    fe_trip_init(&d->imp[k], 4 * d->nnode);
    char why[1200];
    if (d->mtx[k][0] && fe_matrix_read(d->mtx[k], 4 * d->nnode, &d->imp[k], why, sizeof why))
      return fail_at(c, d->mtx_line, "matrices: %c: %s", "MCGK"[k], why);
  }
  for (size_t t = 0; t < d->imp[0].nt; t++)
    if (d->imp[0].i[t] == d->imp[0].j[t] && d->imp[0].i[t] % 4 < 2) *mass += d->imp[0].x[t] / 2;
  return 0;
}

static int check_whole(ctx *c) {
  fe_desc *d = c->d;
  const int end = d->nlines > 0 ? d->nlines : 1;
  if (d->nel == 0 && !d->nodes_count)
    return fail_at(c, end, "no shaft: a rotor needs at least one shaft line (or nodes and matrices)");
  if (d->nodes_count && !d->mtx_line)
    return fail_at(c, d->nodes_line, "nodes: the matrices line is missing");
  if (d->mtx_line && !d->nodes_count && d->nel == 0)
    return fail_at(c, d->mtx_line, "matrices: give the number of nodes (nodes count=N)");
  d->nnode = 0;
  for (size_t k = 0; k < d->nel; ++k)
    if (d->el[k].node + 2 > d->nnode) d->nnode = d->el[k].node + 2;
  if (d->nodes_count && d->nel && d->nodes_count != d->nnode)
    return fail_at(c, d->nodes_line, "nodes: count=%d, but the shaft has %d nodes",
                   d->nodes_count, d->nnode);
  if (d->nodes_count) d->nnode = d->nodes_count;
  if (d->nel && (size_t)d->nnode - 1 != d->nel) {
    for (int n = 0; n + 1 < d->nnode; ++n) {
      size_t k = 0;
      while (k < d->nel && d->el[k].node != n) ++k;
      if (k == d->nel) return fail_at(c, end, "no shaft element between nodes %d and %d", n, n + 1);
    }
  }
  int rc = check_nodes(c);
  if (rc) return rc;
  double mass = 0;
  for (size_t k = 0; k < d->nel; ++k) {
    const fe_element *e = &d->el[k];
    mass += d->mat[e->material].rho * WHIRL_PI * (e->od * e->od - e->id * e->id) / 4 * e->length;
  }
  for (size_t k = 0; k < d->ndisk; ++k) mass += d->disk[k].m;
  for (size_t k = 0; k < d->nped; ++k) mass += d->ped[k].mass;
  if (d->mtx_line && (rc = read_matrices(c, &mass))) return rc;
  if (!(mass > 0)) return fail_at(c, end, "the rotor has no mass (every density, disk mass and imported M is 0)");
  return 0;
}

int fe_parse(const char *path, fe_desc *d, char *msg, size_t len) {
  memset(d, 0, sizeof *d);
  snprintf(d->file, sizeof d->file, "%s", path);
  ctx c = {d, 0, msg, len, NULL, 0};
  FILE *f = fopen(path, "r");
  if (!f) {
    if (msg && len) snprintf(msg, len, "%s: cannot open: %s", path, strerror(errno));
    return WHIRL_EIO;
  }
  int rc = read_lines(&c, f);
  fclose(f);
  free(c.elline);
  if (rc == WHIRL_ENOMEM && msg && len) snprintf(msg, len, "%s:%d: out of memory", path, c.line);
  if (!rc) rc = check_whole(&c);
  if (rc) fe_desc_free(d);
  return rc;
}

void fe_desc_free(fe_desc *d) {
  for (int k = 0; d->imp && k < 4; k++) {
    free(d->imp[k].i);
    free(d->imp[k].j);
    free(d->imp[k].x);
  }
  free(d->imp);
  d->imp = NULL;
  free(d->mat);
  free(d->el);
  free(d->disk);
  free(d->brg);
  free(d->ped);
  free(d->nl);
  free(d->nl_ped);
  free(d->unb);
  free(d->load);
  d->mat = NULL;
  d->el = NULL;
  d->disk = NULL;
  d->brg = NULL;
  d->ped = NULL;
  d->nl = NULL;
  d->nl_ped = NULL;
  d->unb = NULL;
  d->load = NULL;
}
