/* lib/run/model.c — model descriptions for `whirl run` (whirl/model.h): the
 * built-in models by name and the checks a plug-in's description must pass
 * before anything calls into it.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <whirl/model.h>
#include <whirl/sfd.h>

static double sfd_par0[WHIRL_SFD_NPAR];
static const double sfd_u0[4] = {0.0, 0.0, 0.0, 0.0};

static int sfd_stpnt(double tau, double *u, double *par, void *data) {
  (void)tau;
  (void)par;
  (void)data;
  memset(u, 0, 4 * sizeof *u); /* at rest in the centre */
  return 0;
}

/* The problems are static; the tables are filled on first use (the
 * parameter defaults come from whirl_sfd_default_params, Table 1). */
static whirl_model sfd_models[2];

static void init_builtins(void) {
  if (sfd_models[0].abi) return;
  whirl_sfd_default_params(sfd_par0);
  sfd_models[0] = (whirl_model){
      .abi = WHIRL_MODEL_ABI, .problem = *whirl_sfd_fixed(), .par0 = sfd_par0,
      .u0 = sfd_u0, .stpnt = sfd_stpnt, .forcing_param = WHIRL_SFD_OMEGA,
      .description = "rigid rotor on two short squeeze-film dampers, fixed "
                     "frame (unbalance forcing at Omega)"};
  sfd_models[1] = (whirl_model){
      .abi = WHIRL_MODEL_ABI, .problem = *whirl_sfd_rotating(),
      .par0 = sfd_par0, .u0 = sfd_u0, .stpnt = sfd_stpnt, .forcing_param = -1,
      .description = "rigid rotor on two short squeeze-film dampers, rotating "
                     "frame (circular orbits are equilibria)"};
}

static const char *const builtin_names[] = {"sfd", "sfd-rotating", NULL};

const char *const *whirl_model_builtin_names(void) { return builtin_names; }

const whirl_model *whirl_model_builtin(const char *name) {
  if (!name) return NULL;
  init_builtins();
  for (size_t i = 0; builtin_names[i]; i++)
    if (!strcmp(name, builtin_names[i])) return &sfd_models[i];
  return NULL;
}

int whirl_model_check_params(const whirl_model *m, const double *p,
                             char *msg, size_t len) {
  char dummy[8];
  if (!msg || !len) msg = dummy, len = sizeof dummy;
  msg[0] = '\0';
  if (!m || !p) {
    snprintf(msg, len, "no model or no parameters");
    return WHIRL_EINVAL;
  }
  init_builtins();
  if (m == &sfd_models[0] || m == &sfd_models[1])
    return whirl_sfd_check_params(p, msg, len);
  return WHIRL_OK;
}

static int name_ok(const char *s) {
  if (!s || !*s || strlen(s) >= 64 || isdigit((unsigned char)s[0])) return 0;
  for (; *s; s++) {
    unsigned char c = (unsigned char)*s;
    if (!(isalnum(c) || c == '_' || c == '.' || c == '(' || c == ')' ||
          c == '-' || c == '+' || c == '^' || c == '/'))
      return 0;
  }
  return 1;
}

static int names_ok(const char *const *names, size_t n, const char *what,
                    char *msg, size_t len) {
  if (!names) return 1;
  for (size_t i = 0; i < n; i++) {
    if (!name_ok(names[i])) {
      snprintf(msg, len, "%s name %zu is not usable in run files (letters, "
               "digits, _ . ( ) - + ^ /, not starting with a digit)", what, i + 1);
      return 0;
    }
    for (size_t j = 0; j < i; j++)
      if (!strcmp(names[i], names[j])) {
        snprintf(msg, len, "%s name '%s' appears twice", what, names[i]);
        return 0;
      }
  }
  return 1;
}

int whirl_model_check(const whirl_model *m, char *msg, size_t len) {
  char dummy[8];
  if (!msg || !len) msg = dummy, len = sizeof dummy;
  if (!m) {
    snprintf(msg, len, "no model description");
    return WHIRL_EINVAL;
  }
  if (m->abi != WHIRL_MODEL_ABI) {
    snprintf(msg, len, "built for model ABI %d, this whirl needs %d: rebuild "
             "the plug-in against the installed whirl headers", m->abi,
             WHIRL_MODEL_ABI);
    return WHIRL_EINVAL;
  }
  const whirl_problem *p = &m->problem;
  if (p->n == 0 || p->n > 100000) {
    snprintf(msg, len, "state dimension n = %zu is not in [1, 100000]", p->n);
    return WHIRL_EINVAL;
  }
  if (p->npar == 0 || p->npar > 1000) {
    snprintf(msg, len, "number of parameters npar = %zu is not in [1, 1000]",
             p->npar);
    return WHIRL_EINVAL;
  }
  if (!p->rhs) {
    snprintf(msg, len, "the right-hand side callback (problem.rhs) is NULL");
    return WHIRL_EINVAL;
  }
  if (!m->par0) {
    snprintf(msg, len, "no default parameter values (par0 is NULL)");
    return WHIRL_EINVAL;
  }
  for (size_t k = 0; k < p->npar; k++)
    if (!isfinite(m->par0[k])) {
      snprintf(msg, len, "default parameter %zu is not finite", k + 1);
      return WHIRL_EINVAL;
    }
  if (m->u0)
    for (size_t i = 0; i < p->n; i++)
      if (!isfinite(m->u0[i])) {
        snprintf(msg, len, "default start state component %zu is not finite",
                 i + 1);
        return WHIRL_EINVAL;
      }
  if (m->forcing_param >= (int)p->npar || m->forcing_param < -1) {
    snprintf(msg, len, "forcing_param = %d is not a parameter index (0..%zu) "
             "or -1", m->forcing_param, p->npar - 1);
    return WHIRL_EINVAL;
  }
  if (m->forcing_param >= 0 && p->autonomous) {
    snprintf(msg, len, "an autonomous model cannot have a forcing parameter");
    return WHIRL_EINVAL;
  }
  if (m->forcing_param < 0 && !p->autonomous) {
    snprintf(msg, len, "a non-autonomous model needs forcing_param (the "
             "index of its forcing frequency)");
    return WHIRL_EINVAL;
  }
  if (!(m->period0 >= 0.0) || !isfinite(m->period0)) {
    snprintf(msg, len, "period0 = %g must be finite and >= 0", m->period0);
    return WHIRL_EINVAL;
  }
  if (!names_ok(p->x_names, p->n, "state", msg, len)) return WHIRL_EINVAL;
  if (!names_ok(p->p_names, p->npar, "parameter", msg, len)) return WHIRL_EINVAL;
  msg[0] = '\0';
  return WHIRL_OK;
}
