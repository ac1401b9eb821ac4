/* test/unit/t_runfile.c — the run file's public accessors (whirl/runfile.h):
 * every value comes back as the text below wrote it, defaults as
 * doc/run-files.md states them, keys of another type are refused, and a
 * message of bad input names the file and line.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <string.h>

#include <whirl/whirl.h>

#include "../tap.h"

static const char text[] =
    "# a run file\n"
    "model = sfd\n"
    "IPS = 2\n"
    "ICP = [Omega, 11]\n"
    "PAR = {lambda: 0.05, 3: 0.3}\n"
    "UZR = {Omega: [0.5, 1.5]}\n"
    "NTST = 30\n"
    "DS = -0.02\n"
    "IRS = HB2\n"
    "plot = MAX x\n";

static void check_scalars(const whirl_runfile *rf) {
  int v = -1;
  double x = 0;
  ok(whirl_runfile_int(rf, WHIRL_RK_IPS, &v) == WHIRL_OK && v == 2, "IPS = 2");
  ok(whirl_runfile_int(rf, WHIRL_RK_NTST, &v) == WHIRL_OK && v == 30, "NTST = 30");
  ok(whirl_runfile_int(rf, WHIRL_RK_NCOL, &v) == WHIRL_OK && v == 4,
     "NCOL defaults to 4");
  ok(whirl_runfile_int(rf, WHIRL_RK_IRS, &v) == WHIRL_OK && v == 2,
     "IRS = HB2: the count 2");
  ok(strcmp(whirl_runfile_string(rf, WHIRL_RK_IRS), "HB") == 0,
     "IRS = HB2: the type HB");
  ok(whirl_runfile_real(rf, WHIRL_RK_DS, &x) == WHIRL_OK && x == -0.02,
     "DS = -0.02");
  ok(whirl_runfile_real(rf, WHIRL_RK_EPSS, &x) == WHIRL_OK && x == 1e-5,
     "EPSS defaults to 1e-5");
  ok(strcmp(whirl_runfile_string(rf, WHIRL_RK_MODEL), "sfd") == 0, "model");
  ok(strcmp(whirl_runfile_string(rf, WHIRL_RK_PLOT), "MAX x") == 0, "plot");
  ok(strcmp(whirl_runfile_string(rf, WHIRL_RK_OUT), "") == 0,
     "OUT not given: empty");
  v = 77;
  ok(whirl_runfile_int(rf, WHIRL_RK_DS, &v) == WHIRL_EINVAL && v == 77,
     "DS is not an integer key: refused, v untouched");
  ok(whirl_runfile_real(rf, WHIRL_RK_MODEL, &x) == WHIRL_EINVAL,
     "MODEL is not a real key");
  ok(whirl_runfile_string(rf, WHIRL_RK_NTST) == NULL, "NTST is not text");
}

static void check_lists(const whirl_runfile *rf) {
  whirl_run_value it;
  ok(whirl_runfile_count(rf, WHIRL_RK_ICP) == 2, "ICP has 2 items");
  ok(whirl_runfile_item(rf, WHIRL_RK_ICP, 0, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "Omega") == 0 && it.ref.index == 0,
     "ICP[0] is Omega by name");
  ok(whirl_runfile_item(rf, WHIRL_RK_ICP, 1, &it) == WHIRL_OK &&
         it.ref.index == 11 && it.ref.name[0] == '\0',
     "ICP[1] is parameter 11 by index");
  ok(whirl_runfile_item(rf, WHIRL_RK_ICP, 2, &it) == WHIRL_EINVAL,
     "ICP[2] out of range");
  ok(whirl_runfile_count(rf, WHIRL_RK_PAR) == 2, "PAR has 2 items");
  ok(whirl_runfile_item(rf, WHIRL_RK_PAR, 1, &it) == WHIRL_OK &&
         it.ref.index == 3 && it.value == 0.3,
     "PAR[1] is 3: 0.3");
  ok(whirl_runfile_count(rf, WHIRL_RK_UZR) == 2 &&
         whirl_runfile_item(rf, WHIRL_RK_UZR, 1, &it) == WHIRL_OK &&
         it.value == 1.5 && strcmp(it.ref.name, "Omega") == 0,
     "UZR: two values of Omega, the second 1.5");
  ok(whirl_runfile_count(rf, WHIRL_RK_BASIN_GRID) == 2 &&
         whirl_runfile_item(rf, WHIRL_RK_BASIN_GRID, 0, &it) == WHIRL_OK &&
         it.value == 41,
     "BASIN_GRID defaults to 41 points per axis");
  ok(whirl_runfile_count(rf, WHIRL_RK_DS) == 0, "DS is not a list");
  whirl_run_range ax;
  ok(whirl_runfile_axis(rf, 0, &ax) == WHIRL_EINVAL, "no basin axes given");
}

static void check_error(void) {
  whirl_runfile *rf = whirl_runfile_alloc();
  const char bad[] = "model = sfd\nNTST = -3\n";
  ok(whirl_runfile_parse(rf, "bad.whirl", bad, sizeof bad - 1) == WHIRL_EINVAL,
     "NTST = -3 refused");
  ok(strncmp(whirl_runfile_errmsg(rf), "bad.whirl:2: ", 13) == 0,
     "the message starts with the file and line: %s", whirl_runfile_errmsg(rf));
  ok(strstr(whirl_runfile_errmsg(rf), ".c:") == NULL,
     "and names no source file");
  whirl_runfile_free(rf);
}

/* BASIN_METHOD: DOP853 by default, dopri5 when given, others refused */
static void check_basin_method(void) {
  whirl_runfile *rf = whirl_runfile_alloc();
  int v = -1;
  const char def[] = "model = sfd\n", d5[] = "model = sfd\nBASIN_METHOD = dopri5\n",
             bad[] = "model = sfd\nBASIN_METHOD = rk4\n";
  int good = whirl_runfile_parse(rf, "m.whirl", def, sizeof def - 1) == WHIRL_OK &&
             whirl_runfile_int(rf, WHIRL_RK_BASIN_METHOD, &v) == WHIRL_OK;
  ok(good && v == WHIRL_ODE_DOP853, "BASIN_METHOD defaults to dop853 (%d)", v);
  whirl_runfile_free(rf);
  rf = whirl_runfile_alloc();
  good = whirl_runfile_parse(rf, "m.whirl", d5, sizeof d5 - 1) == WHIRL_OK &&
         whirl_runfile_int(rf, WHIRL_RK_BASIN_METHOD, &v) == WHIRL_OK;
  ok(good && v == WHIRL_ODE_DOPRI5, "BASIN_METHOD = dopri5 (%d)", v);
  whirl_runfile_free(rf);
  rf = whirl_runfile_alloc();
  ok(whirl_runfile_parse(rf, "m.whirl", bad, sizeof bad - 1) == WHIRL_EINVAL &&
         strstr(whirl_runfile_errmsg(rf), "m.whirl:2: ") == whirl_runfile_errmsg(rf) &&
         strstr(whirl_runfile_errmsg(rf), "dop853 or dopri5") != NULL,
     "BASIN_METHOD = rk4 refused: %s", whirl_runfile_errmsg(rf));
  whirl_runfile_free(rf);
}


/* THL and THU: weights of the arclength norm, by name or index; a negative
 * weight is refused at its line */
static void check_weights(void) {
  whirl_runfile *rf = whirl_runfile_alloc();
  whirl_run_value it;
  const char good[] = "model = sfd\nTHL = {PERIOD: 0, Omega: 2}\nTHU = {1: 0.5}\n",
             neg[] = "model = sfd\n\nTHU = {2: -1}\n";
  int rc = whirl_runfile_parse(rf, "w.whirl", good, sizeof good - 1);
  ok(rc == WHIRL_OK && whirl_runfile_count(rf, WHIRL_RK_THL) == 2 &&
         whirl_runfile_count(rf, WHIRL_RK_THU) == 1,
     "THL has 2 weights, THU 1 (%s)", whirl_runfile_errmsg(rf));
  ok(whirl_runfile_item(rf, WHIRL_RK_THL, 0, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "PERIOD") == 0 && it.value == 0,
     "THL[0] is PERIOD: 0");
  ok(whirl_runfile_item(rf, WHIRL_RK_THL, 1, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "Omega") == 0 && it.value == 2,
     "THL[1] is Omega: 2");
  ok(whirl_runfile_item(rf, WHIRL_RK_THU, 0, &it) == WHIRL_OK && it.ref.index == 1 &&
         it.value == 0.5,
     "THU[0] is 1: 0.5");
  ok(strstr(whirl_runfile_ignored(rf) ? whirl_runfile_ignored(rf) : "", "THL") == NULL,
     "THL is not among the ignored keys");
  whirl_runfile_free(rf);
  rf = whirl_runfile_alloc();
  ok(whirl_runfile_parse(rf, "w.whirl", neg, sizeof neg - 1) == WHIRL_EINVAL &&
         strncmp(whirl_runfile_errmsg(rf), "w.whirl:3: ", 11) == 0 &&
         strstr(whirl_runfile_errmsg(rf), "negative"),
     "a negative THU weight refused at its line: %s", whirl_runfile_errmsg(rf));
  whirl_runfile_free(rf);
}


/* STOP: AUTO's stopping points, a type and a count (a type alone: 1),
 * quoted or not; anything else refused at its line */
static void check_stop(void) {
  whirl_runfile *rf = whirl_runfile_alloc();
  whirl_run_value it;
  const char good[] = "model = sfd\nSTOP = ['TR1', LP2, hb]\n",
             bad[] = "model = sfd\n\nSTOP = [TR0]\n", bad2[] = "model = sfd\nSTOP = [XY1]\n";
  int rc = whirl_runfile_parse(rf, "w.whirl", good, sizeof good - 1);
  ok(rc == WHIRL_OK && whirl_runfile_count(rf, WHIRL_RK_STOP) == 3,
     "STOP has 3 points (%s)", whirl_runfile_errmsg(rf));
  ok(whirl_runfile_item(rf, WHIRL_RK_STOP, 0, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "TR") == 0 && it.value == 1, "STOP[0] is TR 1");
  ok(whirl_runfile_item(rf, WHIRL_RK_STOP, 1, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "LP") == 0 && it.value == 2, "STOP[1] is LP 2");
  ok(whirl_runfile_item(rf, WHIRL_RK_STOP, 2, &it) == WHIRL_OK &&
         strcmp(it.ref.name, "HB") == 0 && it.value == 1, "STOP[2] is HB 1 (hb, no count)");
  ok(strstr(whirl_runfile_ignored(rf) ? whirl_runfile_ignored(rf) : "", "STOP") == NULL,
     "STOP is not among the ignored keys");
  whirl_runfile_free(rf);
  rf = whirl_runfile_alloc();
  ok(whirl_runfile_parse(rf, "w.whirl", bad, sizeof bad - 1) == WHIRL_EINVAL &&
         strncmp(whirl_runfile_errmsg(rf), "w.whirl:3: ", 11) == 0 &&
         strstr(whirl_runfile_errmsg(rf), "'TR0'"),
     "STOP = [TR0] refused at its line: %s", whirl_runfile_errmsg(rf));
  whirl_runfile_free(rf);
  rf = whirl_runfile_alloc();
  ok(whirl_runfile_parse(rf, "w.whirl", bad2, sizeof bad2 - 1) == WHIRL_EINVAL &&
         strstr(whirl_runfile_errmsg(rf), "'XY1' is not a point type"),
     "STOP = [XY1] refused: %s", whirl_runfile_errmsg(rf));
  whirl_runfile_free(rf);
}

/* A locus label's LOCUS field: written, read back, optional (older files),
 * and a wrong one refused with the file and line */
static void check_solution_locus(void) {
  double par[3] = {0.1, 14, 3}, x[2] = {0.4, 1.4};
  whirl_solution so;
  memset(&so, 0, sizeof so);
  so.label = 1, so.br = 1, so.pt = 0, so.kind = WHIRL_SOL_EQ, so.icp = 0, so.icp2 = 1;
  so.npar = 3, so.nx = 2, so.par = par, so.x = x, so.stable = -1;
  memcpy(so.ty, "EP", 3);
  memcpy(so.locus, "PD", 3);
  FILE *f = tmpfile();
  whirl_solution back;
  char msg[256] = "";
  const whirl_solution_shape any = {NULL, 0, 0, -1};
  if (f) fputs("# whirl solutions: model ab, npar 3\n", f);
  int rc = f ? whirl_solution_write(f, &so) : -1;
  if (f) rewind(f);
  rc = rc ? rc : whirl_solution_read(f, "s", &any, 1, "", &back, msg, sizeof msg);
  ok(rc == 0 && !strcmp(back.locus, "PD") && back.icp2 == 1,
     "LOCUS PD written and read back (%s)", msg);
  if (!rc) whirl_solution_free(&back);
  if (f) fclose(f);
  static const char old[] = "# whirl solutions: model ab, npar 3\nLAB 1 TY EP BR 1 PT 0 KIND eq ICP 1 ICP2 2 NX 2 STAB -1\n"
                            "PAR 0.1 14 3\nX 0.4 1.4\nEND\n",
                    bad[] = "# whirl solutions: model ab, npar 3\nLAB 1 TY EP BR 1 PT 0 KIND eq ICP 1 ICP2 2 NX 2 STAB -1 LOCUS XX\n"
                            "PAR 0.1 14 3\nX 0.4 1.4\nEND\n";
  f = tmpfile();
  if (f) fputs(old, f), rewind(f);
  rc = f ? whirl_solution_read(f, "s", &any, 1, "", &back, msg, sizeof msg) : -1;
  ok(rc == 0 && back.locus[0] == 0, "a file without LOCUS reads (no locus) (%s)", msg);
  if (!rc) whirl_solution_free(&back);
  if (f) fclose(f);
  f = tmpfile();
  if (f) fputs(bad, f), rewind(f);
  rc = f ? whirl_solution_read(f, "s", &any, 1, "", &back, msg, sizeof msg) : 0;
  ok(rc != 0 && strstr(msg, "s:2: ") == msg && strstr(msg, "LOCUS"),
     "LOCUS XX refused at its line: %s", msg);
  if (!rc) whirl_solution_free(&back);
  if (f) fclose(f);
}

int main(void) {
  whirl_runfile *rf = whirl_runfile_alloc();
  ok(rf != NULL, "alloc");
  ok(whirl_runfile_parse(rf, "t.whirl", text, sizeof text - 1) == WHIRL_OK,
     "parse: %s", whirl_runfile_errmsg(rf));
  check_scalars(rf);
  check_lists(rf);
  whirl_runfile_free(rf);
  check_error();
  check_basin_method();
  check_weights();
  check_stop();
  check_solution_locus();
  return done_testing();
}
