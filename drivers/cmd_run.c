/* drivers/cmd_run.c — `whirl run FILE [--KEY=value ...]`: parse the
 * command line, run the run file through the library (whirl/run.h), and
 * write its output directory as one transaction (outdir.h) with the
 * picture (run_plot.c):
 *
 *   branches.tsv   branch pt type label, parameters, norms, state, stable (doc/tables.md)
 *   solutions      labelled solutions, full precision, restartable (IRS)
 *   run.log        diagnostics: settings, model, steps, stop reasons
 *   diagram.png    the bifurcation diagram (gnuplot), or basins.png
 * SPDX-License-Identifier: BSD-3-Clause */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whirl/rotor.h>

#include "blocks.h"
#include "cli.h"
#include "run_cmd.h"
#include "run_study.h"

static void usage(FILE *f) {
  fprintf(f,
          "usage: whirl run FILE [--KEY=value ...] [--format=F] [--no-plot] [--quiet]\n"
          "\n"
          "Run an AUTO-style run file: equilibria (IPS = 1), periodic orbits\n"
          "(IPS = 2, METHOD = colloc | hbm), branch switching and fold/Hopf\n"
          "loci (ISW = -1, 2) from labelled solutions (S, IRS), basins of\n"
          "attraction (IPS = basins).  Any key can be overridden on the\n"
          "command line, e.g. --DS=0.01 --ICP=[B] --out=dir.\n"
          "Output directory (default FILE's name with .out): branches.tsv,\n"
          "solutions, run.log, diagram.png.  The format: doc/run-files.md.\n"
          "Paths (model, S, OUT) written in FILE are relative to FILE's directory\n"
          "(the default output too); on the command line, to the current one.\n"
          "\n"
          "A parameter study (STUDY = {name: [values], ...}: study.tsv, a row a\n"
          "point) and basins (IPS = basins) resume from OUT.checkpoint when started\n"
          "again, run on MPI under mpirun (built --with-mpi), and in parts\n"
          "(doc/parameter-studies.md):\n"
          "  --chunk=I/N        the I-th of N parts, into OUT.chunk-I-of-N/\n"
          "  --merge-chunks=N   join the N parts into OUT\n"
          "\n"
          "  --format=F         the picture as png (default), pdf or svg\n"
          "  --no-plot          no picture (nor its gnuplot script)\n");
}

/* "--NMX 5": an override written with a blank for '=' would take its value
 * for a second run file; 1 (message printed) if argv[i] is one. */
static int override_without_eq(int argc, char **argv, int i) {
  const char *a = argv[i];
  if (strncmp(a, "--", 2) || strchr(a, '=') || !strcmp(a, "--quiet") ||
      i + 1 >= argc || !strncmp(argv[i + 1], "--", 2))
    return 0;
  fprintf(stderr, "whirl run: %s needs '=': write %s=%s\n", a, a, argv[i + 1]);
  return 1;
}

/* ---- the run's io: messages, summary, files, progress ------------------- */

typedef struct run_io_ctx {
  cli_outdir od;
  int quiet, no_plot;
  cli_progress progress;
} run_io_ctx;

/* the progress line is taken off before a message or a summary line (the
 * terminal may show stdout too) and drawn again at the next progress */
static void io_message(const char *line, void *ctx) {
  cli_progress_clear(&((run_io_ctx *)ctx)->progress);
  cli_error("run", "%s", line);
}
static void io_summary(const char *line, void *ctx) {
  run_io_ctx *c = ctx;
  cli_progress_clear(&c->progress);
  if (!c->quiet) printf("%s\n", line), fflush(stdout);
}
static FILE *io_open(const char *name, void *ctx) {
  return cli_outdir_fopen(&((run_io_ctx *)ctx)->od, name);
}
static int io_close(FILE *f, const char *name, void *ctx) {
  return cli_outdir_fclose(&((run_io_ctx *)ctx)->od, f, name);
}
static void io_progress(size_t done, size_t total, void *ctx) {
  cli_progress_show(&((run_io_ctx *)ctx)->progress, done, total);
}

/* The files and names of the command line: argv[i] "--KEY=value" are the
 * overrides, one other argument is the run file.  0, or the exit status. */
/* --chunk=I/N, --merge-chunks=N: 1 if argv[i] is one (parsed into so, or
 * a message and *bad = 2). */
static int study_option(const char *a, study_opts *so, size_t *merge, int *bad) {
  char tail;
  if (!strncmp(a, "--chunk=", 8)) {
    if (sscanf(a + 8, "%zu/%zu%c", &so->chunk, &so->chunks, &tail) != 2 || so->chunks == 0) {
      fprintf(stderr, "whirl run: %s: write --chunk=I/N, the I-th of N parts (1 <= I <= N)\n", a);
      *bad = 2;
    }
    return 1;
  }
  if (!strncmp(a, "--merge-chunks=", 15)) {
    if (sscanf(a + 15, "%zu%c", merge, &tail) != 1 || *merge == 0) {
      fprintf(stderr, "whirl run: %s: write --merge-chunks=N, N >= 1\n", a);
      *bad = 2;
    }
    return 1;
  }
  return 0;
}

static int parse_args(int argc, char **argv, const char **file, int *quiet, int *no_plot,
                      const char **ov, size_t *nov, study_opts *so, size_t *merge) {
  *file = NULL;
  *nov = 0;
  *no_plot = 0;
  for (int i = 1; i < argc; i++) {
    int bad = 0;
    if (study_option(argv[i], so, merge, &bad)) {
      if (bad) return bad;
      continue;
    }
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      usage(stdout);
      return -1;
    }
    if (!strcmp(argv[i], "--quiet") || !strcmp(argv[i], "-q")) {
      *quiet = 1;
      continue;
    }
    if (!strcmp(argv[i], "--no-plot")) {
      *no_plot = 1;
      continue;
    }
    if (!strncmp(argv[i], "--format=", 9)) { /* a picture option, not a key */
      cli_picture_format = argv[i] + 9;
      if (cli_picture_format_check("run")) return 2;
      continue;
    }
    if (override_without_eq(argc, argv, i)) return 2;
    if (argv[i][0] == '-' && argv[i][1] == '-') {
      ov[(*nov)++] = argv[i];
      continue;
    }
    if (*file) {
      fprintf(stderr, "whirl run: more than one run file ('%s' and '%s'); "
              "overrides are written --KEY=value\n", *file, argv[i]);
      return 2;
    }
    *file = argv[i];
  }
  if (!*file) {
    usage(stderr);
    return 2;
  }
  return 0;
}

/* Draw the picture and swap the output directory in: 0, or 1 (the picture
 * failed, the rest kept; or the commit failed). */
static int finish_output(run_io_ctx *c, const whirl_run *r) {
  const char *pic = NULL;
  if (!c->no_plot && run_write_plot(&c->od, r, &pic)) {
    cli_outdir_abort(&c->od);
    return 1;
  }
  const int pic_failed =
      c->no_plot || cli_outdir_plot(&c->od, pic) != 0 || cli_pictures_skipped();
  if (cli_outdir_commit(&c->od)) return 1;
  const int basins = whirl_run_plot_info(r)->basins;
  if (!c->quiet)
    printf("wrote %s/ (%s%s%s)\n", whirl_run_output(r),
           basins ? "basins.tsv, run.log" : "branches.tsv, solutions, run.log",
           pic_failed ? "" : basins ? ", basins." : ", diagram.",
           pic_failed ? "" : cli_picture_format);
  return pic_failed && !c->no_plot && !cli_pictures_skipped();
}

/* A study: its points through run_study.c; 0, 1 or 2. */
static int run_study_of(whirl_run *r, study_opts *so, size_t merge, int rank, int nranks) {
  if (merge && so->chunks) {
    cli_error("run", "--chunk and --merge-chunks: one or the other");
    return 2;
  }
  if (merge) {
    so->chunks = merge;
    return rank == 0 ? run_study_merge(r, so) : 0;
  }
  return run_study_command(r, so, rank, nranks);
}

static int cmd_run_ranked(int argc, char **argv, int rank, int nranks);

int cmd_run(int argc, char **argv) {
  int rank, nranks;
  blocks_processes(&argc, &argv, &rank, &nranks);
  int status = cmd_run_ranked(argc, argv, rank, nranks);
  blocks_processes_end();
  return status;
}

static int cmd_run_ranked(int argc, char **argv, int rank, int nranks) {
  const char *file, **ov = calloc((size_t)argc + 1, sizeof *ov);
  size_t nov, merge = 0;
  run_io_ctx c;
  study_opts so;
  memset(&c, 0, sizeof c);
  memset(&so, 0, sizeof so);
  if (!ov) return 1;
  int status = parse_args(argc, argv, &file, &c.quiet, &c.no_plot, ov, &nov, &so, &merge);
  if (status) {
    free(ov);
    return status < 0 ? 0 : status;
  }
  if (rank != 0) c.quiet = 1;
  char msg[512];
  whirl_model_registry *models = whirl_model_registry_alloc();
  if (!models || whirl_rotor_register_models(models, msg, sizeof msg) != WHIRL_OK) {
    cli_error("run", "the registered models are not available: %s",
              models ? msg : "out of memory");
    whirl_model_registry_free(models);
    free(ov);
    return 1;
  }
  cli_progress_init(&c.progress, "whirl run", c.quiet);
  const whirl_run_io io = {io_message, io_summary, io_open, io_close, io_progress, &c};
  whirl_run *r = whirl_run_alloc(models, &io);
  status = r ? whirl_run_load(r, file, ov, nov) : 1;
  so.file = file, so.ov = ov, so.nov = nov, so.quiet = c.quiet;
  so.no_plot = c.no_plot;
  if (status == 0 && whirl_run_rows(r) > 0) { /* a study, or basins */
    status = run_study_of(r, &so, merge, rank, nranks);
    goto done;
  }
  if (status == 0 && (so.chunks || merge)) {
    cli_error("run", "--chunk and --merge-chunks are for parameter studies (STUDY) and basins");
    status = 2;
  }
  if (status == 0 && rank != 0) goto done; /* one process runs anything else */
  const char *where = r ? whirl_run_output_where(r) : "";
  /* the output directory: checked now, staged before the run writes */
  if (status == 0) status = cli_outdir_check("run", where, whirl_run_output(r));
  if (status == 0) status = cli_outdir_begin(&c.od, "run", where, whirl_run_output(r));
  if (status == 0) {
    status = whirl_run_execute(r);
    cli_progress_end(&c.progress);
    if (status) cli_outdir_abort(&c.od);
    else status = finish_output(&c, r);
    if (status == 0 && whirl_run_failed(r)) status = 1; /* kept, said */
  }
done:
  whirl_run_free(r);
  whirl_model_registry_free(models);
  free(ov);
  return status;
}
