/* lib/run/model.c — model descriptions for `whirl run` (whirl/model.h): the
 * checks a description must pass before anything calls into it, and the
 * registry of models by name that modules fill (the rotor module's
 * whirl_rotor_register_models) and run files name.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/model.h>

struct whirl_model_registry {
  char **names;
  whirl_model *models;
  size_t n, cap;
};

whirl_model_registry *whirl_model_registry_alloc(void) {
  return calloc(1, sizeof(whirl_model_registry));
}

void whirl_model_registry_free(whirl_model_registry *reg) {
  if (!reg) return;
  for (size_t i = 0; i < reg->n; i++) free(reg->names[i]);
  free(reg->names);
  free(reg->models);
  free(reg);
}

static int registry_name_ok(const char *s) {
  if (!s || !*s || strlen(s) >= 64) return 0;
  for (; *s; s++)
    if (!(isalnum((unsigned char)*s) || *s == '_' || *s == '-' || *s == '.')) return 0;
  return 1;
}

static int registry_grow(whirl_model_registry *reg) {
  if (reg->n < reg->cap) return 0;
  const size_t cap = reg->cap ? 2 * reg->cap : 8;
  char **names = realloc(reg->names, cap * sizeof *names);
  if (!names) return -1;
  reg->names = names;
  whirl_model *models = realloc(reg->models, cap * sizeof *models);
  if (!models) return -1;
  reg->models = models;
  reg->cap = cap;
  return 0;
}

int whirl_model_registry_add(whirl_model_registry *reg, const char *name,
                             const whirl_model *m, char *msg, size_t len) {
  char dummy[8];
  if (!msg || !len) msg = dummy, len = sizeof dummy;
  if (!reg || !registry_name_ok(name)) {
    snprintf(msg, len, "model name '%s' is not usable (letters, digits, _ - .)",
             name ? name : "(null)");
    return WHIRL_EINVAL;
  }
  if (whirl_model_registry_find(reg, name)) {
    snprintf(msg, len, "a model named '%s' is registered already", name);
    return WHIRL_EINVAL;
  }
  if (whirl_model_check(m, msg, len) != WHIRL_OK) return WHIRL_EINVAL;
  if (registry_grow(reg) || !(reg->names[reg->n] = malloc(strlen(name) + 1))) {
    snprintf(msg, len, "out of memory");
    return WHIRL_ENOMEM;
  }
  strcpy(reg->names[reg->n], name);
  reg->models[reg->n++] = *m;
  return WHIRL_OK;
}

const whirl_model *whirl_model_registry_find(const whirl_model_registry *reg,
                                             const char *name) {
  for (size_t i = 0; reg && name && i < reg->n; i++)
    if (!strcmp(reg->names[i], name)) return &reg->models[i];
  return NULL;
}

size_t whirl_model_registry_count(const whirl_model_registry *reg) {
  return reg ? reg->n : 0;
}

const char *whirl_model_registry_name(const whirl_model_registry *reg, size_t i) {
  return reg && i < reg->n ? reg->names[i] : NULL;
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
  if (m->check_params && m->check_params(p, msg, len) != 0) {
    if (!msg[0]) snprintf(msg, len, "the parameters are outside the model's domain");
    return WHIRL_EINVAL;
  }
  msg[0] = '\0';
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
  for (size_t i = 0; m->scale && i < p->n; i++)
    if (!(m->scale[i] > 0) || !isfinite(m->scale[i])) {
      snprintf(msg, len, "scale[%zu] = %g: the state's scales must be positive "
               "and finite", i, m->scale[i]);
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
