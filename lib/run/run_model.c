/* lib/run/run_model.c — `whirl run`: load the run file's model (a built-in
 * by name, or a plug-in shared object exporting whirl_model_def, checked for
 * its ABI before anything else is read) and resolve the names the run file
 * uses for parameters and state components.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* dladdr1: the symbol's ELF type and size */
#endif
#include <dlfcn.h>
#include <errno.h>
#include <stdalign.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "run_impl.h"

#ifdef __GLIBC__
#include <link.h>
#endif

/* What is wrong with the plug-in's whirl_model_def symbol, or NULL: it must
 * be a data object (`const whirl_model whirl_model_def = {...}`) of the
 * struct's size and alignment.  A function of that name (`whirl_model
 * whirl_model_def(void)`) was read as the struct, an unaligned read of
 * machine code. */
static const char *symbol_problem(const void *sym) {
#ifdef __GLIBC__
  Dl_info info;
  const ElfW(Sym) *es = NULL;
  if (dladdr1(sym, &info, (void **)&es, RTLD_DL_SYMENT) && es) {
#if __ELF_NATIVE_CLASS == 64
    const int type = ELF64_ST_TYPE(es->st_info);
#else
    const int type = ELF32_ST_TYPE(es->st_info);
#endif
    if (type == STT_FUNC || type == STT_GNU_IFUNC)
      return "is a function, not the struct";
    if (type != STT_OBJECT)
      return "is not a data object";
    if (es->st_size < sizeof(whirl_model))
      return "is smaller than a whirl_model";
  }
#endif
  if ((uintptr_t)sym % alignof(whirl_model) != 0)
    return "is not aligned as a whirl_model (a function, not the struct?)";
  return NULL;
}

static int is_plugin_path(const char *m) {
  size_t n = strlen(m);
  return strchr(m, '/') != NULL || (n > 3 && !strcmp(m + n - 3, ".so"));
}

/* The model NAME from the registry the caller gave (the command fills it
 * from the rotor module: sfd, sfd-rotating, jeffcott); NULL, said. */
static const whirl_model *registered_model(run_ctx *R, const char *name) {
  const whirl_model *model = whirl_model_registry_find(R->registry, name);
  if (model) return model;
  char list[256] = "";
  for (size_t i = 0; i < whirl_model_registry_count(R->registry); i++) {
    if (list[0]) strcat(list, ", ");
    strncat(list, whirl_model_registry_name(R->registry, i), sizeof list - strlen(list) - 3);
  }
  run_fail(R, WHIRL_RK_MODEL,
           "model: '%s' is neither a built-in model (%s) nor a plug-in "
           "(a path to a .so file)", name, list);
  return NULL;
}

int run_load_model(run_ctx *R) {
  const char *m = R->s->model;
  if (!is_plugin_path(m)) {
    R->model = registered_model(R, m);
    if (!R->model) return -1;
  } else {
    char path[8192], rel[8100];
    if (run_path(R, WHIRL_RK_MODEL, m, rel, sizeof rel)) {
      run_fail(R, WHIRL_RK_MODEL, "model: the path is too long");
      return -1;
    }
    /* dlopen searches the library path for a name without a '/' */
    snprintf(path, sizeof path, "%s%s", strchr(rel, '/') ? "" : "./", rel);
    FILE *probe = fopen(path, "rb");
    if (!probe) {
      run_fail(R, WHIRL_RK_MODEL, "model: cannot open plug-in '%s': %s", path,
               strerror(errno));
      return -1;
    }
    fclose(probe);
    dlerror();
    R->dl = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!R->dl) {
      const char *e = dlerror();
      run_fail(R, WHIRL_RK_MODEL, "model: cannot load plug-in '%s': %s", path,
               e ? e : "unknown error");
      return -1;
    }
    dlerror();
    const void *sym = dlsym(R->dl, WHIRL_MODEL_SYMBOL);
    if (!sym) {
      run_fail(R, WHIRL_RK_MODEL,
               "model: plug-in '%s' does not export the symbol '%s' (define "
               "`const whirl_model %s = {...}`, see doc/user-models.md)",
               path, WHIRL_MODEL_SYMBOL, WHIRL_MODEL_SYMBOL);
      return -1;
    }
    const char *bad = symbol_problem(sym);
    if (bad) {
      run_fail(R, WHIRL_RK_MODEL,
               "model: plug-in '%s': the symbol '%s' %s (define `const "
               "whirl_model %s = {...}`, see doc/user-models.md)",
               path, WHIRL_MODEL_SYMBOL, bad, WHIRL_MODEL_SYMBOL);
      return -1;
    }
    /* the ABI number is the first member: check it before the rest */
    int abi = *(const int *)sym;
    if (abi != WHIRL_MODEL_ABI) {
      run_fail(R, WHIRL_RK_MODEL,
               "model: plug-in '%s' was built for model ABI %d, this whirl "
               "(%s) needs ABI %d: rebuild it against the installed headers",
               path, abi, whirl_version(), WHIRL_MODEL_ABI);
      return -1;
    }
    R->model = sym;
  }
  char msg[512];
  if (whirl_model_check(R->model, msg, sizeof msg) != WHIRL_OK) {
    run_fail(R, WHIRL_RK_MODEL, "model '%s': %s", m, msg);
    return -1;
  }
  R->prob = R->model->problem;
  R->n = R->prob.n;
  R->npar = R->prob.npar;
  if (!R->prob.name) R->prob.name = m;
  if (R->s->jac == 0) R->prob.jac_x = R->prob.jac_p = NULL;
  return 0;
}

void run_unload_model(run_ctx *R) {
  if (R->pnames)
    for (size_t k = 0; k < R->npar; k++) free(R->pnames[k]);
  if (R->xnames)
    for (size_t k = 0; k < R->n; k++) free(R->xnames[k]);
  free(R->pnames);
  free(R->xnames);
  free(R->par);
  free(R->u);
  if (R->dl) dlclose(R->dl);
  R->dl = NULL;
}

static int find_name(char **names, size_t n, const whirl_run_ref *r) {
  if (r->index > 0) return (size_t)r->index <= n ? r->index - 1 : -1;
  for (size_t k = 0; k < n; k++)
    if (!strcmp(names[k], r->name)) return (int)k;
  /* PAR(3) / U(2) spelled out */
  for (size_t k = 0; k < n; k++)
    if (!strcasecmp(names[k], r->name)) return (int)k;
  return -1;
}

int run_par_index(run_ctx *R, const whirl_run_ref *r) {
  int k = find_name(R->pnames, R->npar, r);
  if (k < 0 && !r->index) {
    char alt[80];
    for (size_t j = 0; j < R->npar; j++) {
      snprintf(alt, sizeof alt, "PAR(%zu)", j + 1);
      if (!strcasecmp(alt, r->name)) return (int)j;
    }
  }
  return k;
}

int run_state_index(run_ctx *R, const whirl_run_ref *r) {
  int k = find_name(R->xnames, R->n, r);
  if (k < 0 && !r->index) {
    char alt[80];
    for (size_t j = 0; j < R->n; j++) {
      snprintf(alt, sizeof alt, "U(%zu)", j + 1);
      if (!strcasecmp(alt, r->name)) return (int)j;
    }
  }
  return k;
}

static void list_names(char **names, size_t n, char *buf, size_t len) {
  buf[0] = '\0';
  for (size_t k = 0; k < n && strlen(buf) + 8 < len; k++) {
    if (k) strncat(buf, ", ", len - strlen(buf) - 1);
    strncat(buf, names[k], len - strlen(buf) - 1);
  }
}

static const char *ref_text(const whirl_run_ref *r, char *buf, size_t len) {
  if (r->index > 0)
    snprintf(buf, len, "%d", r->index);
  else
    snprintf(buf, len, "%s", r->name);
  return buf;
}

/* PLOT: a parameter, PERIOD (orbits), L2-NORM, a state component or "MAX
 * component", into R->plot_kind and R->plot_index; 0 or -1 (message). */
static int resolve_plot(run_ctx *R) {
  const char *p = R->s->plot;
  R->plot_kind = RUN_PLOT_DEFAULT;
  if (!p[0]) return 0;
  if (!strcasecmp(p, "L2-NORM")) {
    R->plot_kind = RUN_PLOT_L2;
    return 0;
  }
  if (!strcasecmp(p, "PERIOD")) {
    if (R->s->ips != WHIRL_IPS_PERIODIC) {
      run_fail(R, WHIRL_RK_PLOT, "PLOT = %s: only periodic orbits (IPS = 2) "
               "have a period", p);
      return -1;
    }
    R->plot_kind = RUN_PLOT_PERIOD;
    return 0;
  }
  const int max = !strncasecmp(p, "MAX ", 4);
  whirl_run_ref r;
  memset(&r, 0, sizeof r);
  snprintf(r.name, sizeof r.name, "%s", max ? p + 4 + strspn(p + 4, " ") : p);
  int k = max ? -1 : run_par_index(R, &r);
  if (k >= 0) {
    R->plot_kind = RUN_PLOT_PAR;
  } else if ((k = run_state_index(R, &r)) >= 0) {
    R->plot_kind = RUN_PLOT_STATE;
  } else {
    char pl[512], xl[512];
    list_names(R->pnames, R->npar, pl, sizeof pl);
    list_names(R->xnames, R->n, xl, sizeof xl);
    run_fail(R, WHIRL_RK_PLOT, "PLOT: '%s' is neither a parameter (%s), "
             "PERIOD, L2-NORM, a state component nor MAX of one (%s) of model "
             "'%s'", p, pl, xl, R->prob.name);
    return -1;
  }
  R->plot_index = k;
  return 0;
}

/* Two entries of PAR (or U) that name the same parameter (component), as
 * {B: 1, 2: 3} or {B: 1, PAR(2): 3} do; 0 or -1 (message). */
static int same_twice(run_ctx *R, whirl_run_key key, const whirl_run_value *v,
                      size_t n, int (*index)(run_ctx *, const whirl_run_ref *)) {
  char a[80], b[80];
  for (size_t i = 1; i < n; i++)
    for (size_t j = 0; j < i; j++)
      if (index(R, &v[i].ref) >= 0 && index(R, &v[i].ref) == index(R, &v[j].ref)) {
        run_fail(R, key, "%s: '%s' and '%s' are the same %s", whirl_run_key_name(key),
                 ref_text(&v[j].ref, a, sizeof a), ref_text(&v[i].ref, b, sizeof b),
                 key == WHIRL_RK_PAR ? "parameter" : "state component");
        return -1;
      }
  return 0;
}

int run_resolve(run_ctx *R) {
  const whirl_run_settings *s = R->s;
  const whirl_model *m = R->model;
  char list[1024], t[80];
  R->pnames = calloc(R->npar, sizeof *R->pnames);
  R->xnames = calloc(R->n, sizeof *R->xnames);
  R->par = calloc(R->npar, sizeof *R->par);
  R->u = calloc(R->n, sizeof *R->u);
  if (!R->pnames || !R->xnames || !R->par || !R->u) {
    run_say(R, "out of memory");
    return -1;
  }
  for (size_t k = 0; k < R->npar; k++) {
    char b[80];
    if (R->prob.p_names)
      snprintf(b, sizeof b, "%s", R->prob.p_names[k]);
    else
      snprintf(b, sizeof b, "PAR(%zu)", k + 1);
    R->pnames[k] = strdup(b);
    if (!R->pnames[k]) return -1;
  }
  for (size_t k = 0; k < R->n; k++) {
    char b[80];
    if (R->prob.x_names)
      snprintf(b, sizeof b, "%s", R->prob.x_names[k]);
    else
      snprintf(b, sizeof b, "U(%zu)", k + 1);
    R->xnames[k] = strdup(b);
    if (!R->xnames[k]) return -1;
  }
  if (s->ndim && (size_t)s->ndim != R->n) {
    run_fail(R, WHIRL_RK_NDIM, "NDIM = %d, but model '%s' has %zu state "
             "components", s->ndim, R->prob.name, R->n);
    return -1;
  }
  if (s->method == WHIRL_METHOD_COLLOC && s->ips == WHIRL_IPS_PERIODIC &&
      !R->prob.autonomous && R->model->forcing_param < 0) {
    run_fail(R, WHIRL_RK_IPS, "IPS = 2: model '%s' is neither autonomous nor "
             "forced at a known frequency", R->prob.name);
    return -1;
  }
  list_names(R->pnames, R->npar, list, sizeof list);
  R->nicp = 0;
  for (size_t i = 0; i < s->nicp; i++) {
    const whirl_run_ref *r = &s->icp[i];
    int k = run_par_index(R, r);
    if (k < 0 && s->ips == WHIRL_IPS_PERIODIC &&
        ((r->index == 11 && R->npar < 11) || !strcasecmp(r->name, "PERIOD")))
    {
      R->period_free = 1;
      continue; /* AUTO's PAR(11): the period is free for autonomous orbits */
    }
    if (k < 0) {
      run_fail(R, WHIRL_RK_ICP, "ICP: '%s' is not a parameter of model '%s' "
               "(%s)", ref_text(r, t, sizeof t), R->prob.name, list);
      return -1;
    }
    for (size_t j = 0; j < R->nicp; j++)
      if (R->icp[j] == k) {
        run_fail(R, WHIRL_RK_ICP, "ICP: parameter '%s' listed twice",
                 R->pnames[k]);
        return -1;
      }
    if (k == m->forcing_param && s->ips == WHIRL_IPS_EQUILIBRIA) {
      /* allowed: an equilibrium of a forced model is unusual but legal */
    }
    R->icp[R->nicp++] = k;
  }
  if (m->set_icp) { /* AUTO's numbers, in the run file's order */
    int auto_icp[WHIRL_RUN_MAXITEMS];
    size_t na = 0;
    for (size_t i = 0; i < s->nicp && na < WHIRL_RUN_MAXITEMS; i++) {
      const int k = run_par_index(R, &s->icp[i]);
      auto_icp[na++] = k >= 0 ? k + 1 : 11;
    }
    const int counts[4] = {s->ntst, s->ncol, s->nbc, s->nint};
    m->set_icp(auto_icp, na, counts, R->prob.data);
  }
  if (s->ips != WHIRL_IPS_BASINS && R->nicp == 0) {
    run_fail(R, WHIRL_RK_ICP, "ICP: no continuation parameter left (only the "
             "period)");
    return -1;
  }
  /* start values: model defaults, STPNT, then the run file's PAR and U */
  memcpy(R->par, m->par0, R->npar * sizeof *R->par);
  if (m->u0) memcpy(R->u, m->u0, R->n * sizeof *R->u);
  if (m->stpnt && m->stpnt(0.0, R->u, R->par, R->prob.data) != 0) {
    run_fail(R, WHIRL_RK_MODEL, "model '%s': its start function (stpnt) "
             "failed", R->prob.name);
    return -1;
  }
  for (size_t i = 0; i < s->npar; i++) {
    int k = run_par_index(R, &s->par[i].ref);
    if (k < 0) {
      run_fail(R, WHIRL_RK_PAR, "PAR: '%s' is not a parameter of model '%s' "
               "(%s)", ref_text(&s->par[i].ref, t, sizeof t), R->prob.name, list);
      return -1;
    }
    R->par[k] = s->par[i].value;
  }
  if (same_twice(R, WHIRL_RK_PAR, s->par, s->npar, run_par_index)) return -1;
  list_names(R->xnames, R->n, list, sizeof list);
  for (size_t i = 0; i < s->nu; i++) {
    int k = run_state_index(R, &s->u[i].ref);
    if (k < 0) {
      run_fail(R, WHIRL_RK_U, "U: '%s' is not a state component of model '%s' "
               "(%s)", ref_text(&s->u[i].ref, t, sizeof t), R->prob.name, list);
      return -1;
    }
    R->u[k] = s->u[i].value;
  }
  if (same_twice(R, WHIRL_RK_U, s->u, s->nu, run_state_index)) return -1;
  char why[256];
  if (whirl_model_check_params(m, R->par, why, sizeof why) != WHIRL_OK) {
    run_fail(R, WHIRL_RK_PAR, "PAR: model '%s': %s", R->prob.name, why);
    return -1;
  }
  if (m->forcing_param >= 0 && !(R->par[m->forcing_param] > 0)) {
    run_fail(R, WHIRL_RK_PAR, "PAR: the forcing frequency '%s' of model '%s' "
             "must be > 0 (got %g)", R->pnames[m->forcing_param], R->prob.name,
             R->par[m->forcing_param]);
    return -1;
  }
  for (size_t i = 0; i < s->naxes; i++)
    if (run_state_index(R, &s->axes[i].ref) < 0) {
      run_fail(R, WHIRL_RK_BASIN_AXES, "BASIN_AXES: '%s' is not a state "
               "component of model '%s' (%s)",
               ref_text(&s->axes[i].ref, t, sizeof t), R->prob.name, list);
      return -1;
    }
  return resolve_plot(R);
}

int run_solution_find(const run_ctx *R, const char *dir, int label,
                      const char *ty, whirl_solution *out, char *msg, size_t len) {
  /* a boundary-value problem may extend a solution of fewer components
   * (AUTO pads a restart with a larger NDIM with zeros: demo pcl) */
  const whirl_solution_shape want = {R->prob.name, R->n, R->npar,
                                     R->model->forcing_param >= 0,
                                     R->s->ips == WHIRL_IPS_BVP};
  return whirl_solution_find(dir, &want, label, ty, out, msg, len);
}
