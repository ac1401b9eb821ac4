/* drivers/outdir.h — output directories written as one transaction.
 *
 * Every command writes its files into a staging directory beside the
 * output directory, PATH.tmp.PID, and only when all of them are complete
 * swaps it in: the previous output is renamed aside (PATH.old.PID), the
 * staging directory renamed to PATH, and only then the previous output's
 * files are removed.  A failure, a full disk or a signal at any moment
 * leaves either the previous output untouched or the new one complete,
 * never a mixture and never a half-written file.
 *
 * What may be replaced: a missing PATH, an empty directory, or a directory
 * whose every entry whirl wrote (listed in its manifest .whirl-output, or,
 * for outputs of earlier versions without one, named like a whirl output
 * file).  Refused with a message: '.', '..', '/', the working directory or
 * a directory above it, a PATH that is not a directory, and any directory
 * holding something whirl did not write.  A PATH that is a symbolic link
 * to a directory stands for that directory: the link is kept and the
 * directory it points to is replaced.  Trailing slashes are ignored.
 *
 * Every function prints its own one-line message ("whirl CMD: ...") on
 * failure, so callers only pass the status on.
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_OUTDIR_H
#define WHIRL_OUTDIR_H

#include <stddef.h>
#include <stdio.h>

#define CLI_OUTDIR_MANIFEST ".whirl-output"

typedef struct cli_outdir {
  const char *cmd;   /* "sfd response", "run": the messages' prefix */
  const char *where; /* NULL, or "FILE:LINE" that named PATH (run files) */
  char shown[4096];  /* PATH as the user wrote it (trailing '/' removed) */
  char path[4096];   /* the directory replaced (a symbolic link resolved) */
  char stage[4200];  /* PATH.tmp.PID, where everything is written */
  char old[4200];    /* PATH.old.PID during the swap */
  char made[4096];   /* the topmost parent directory created, or "" */
  char **files;      /* names written into the stage (the manifest) */
  size_t nfiles, cap;
  int failed;        /* a write failed: commit refuses */
} cli_outdir;

/* Check PATH as cli_outdir_begin will (and that its nearest existing
 * directory is writable), creating nothing: called before a computation,
 * so that a bad output directory is reported before the work, not after.
 * WHERE (or NULL) is put before the messages: the run file's FILE:LINE.
 * Returns 0, 2 (PATH cannot be an output directory) or 1 (it cannot be
 * created there: permissions), with the message printed. */
int cli_outdir_check(const char *cmd, const char *where, const char *path);

/* Check PATH, remove stale temporaries that killed runs left beside it,
 * create missing parents and the staging directory, and arm the signal
 * handlers that remove the stage on SIGINT, SIGTERM, SIGHUP and SIGPIPE.
 * Returns 0, 2 (PATH cannot be an output directory) or 1 (I/O error). */
int cli_outdir_begin(cli_outdir *d, const char *cmd, const char *where,
                     const char *path);

/* Open NAME in the staging directory for writing; NULL on failure. */
FILE *cli_outdir_fopen(cli_outdir *d, const char *name);

/* Close a stream of cli_outdir_fopen, checking every write: 0 or -1. */
int cli_outdir_fclose(cli_outdir *d, FILE *f, const char *name);

/* The most pictures one command draws with one gnuplot process
 * (cli_outdir_finish; more are drawn one by one). */
#define CLI_MAX_PICTURES 8

/* Record NAME, a file another program wrote into the stage, as whirl's. */
int cli_outdir_record(cli_outdir *d, const char *name);

/* Remove NAME from the stage (an optional file that is not wanted). */
void cli_outdir_discard(cli_outdir *d, const char *name);

/* Swap the stage in (see above); frees d.  0, or 1 with the previous
 * output left as it was. */
int cli_outdir_commit(cli_outdir *d);

/* A command's last step: when BAD (a table or script could not be
 * written; the message is printed) abort and return 1; else draw the
 * pictures PICS (NULL-terminated names, or NULL for none) and commit.
 * A picture that fails is left out and the rest kept.  0, or 1 when a
 * picture or the commit failed. */
int cli_outdir_finish(cli_outdir *d, int bad, const char *const *pics);

/* Remove the stage and the parents begin created; frees d. */
void cli_outdir_abort(cli_outdir *d);

/* The file NAME of the stage as "PATH/NAME" for messages. */
const char *cli_outdir_shown(const cli_outdir *d, const char *name,
                             char *buf, size_t len);

/* A file of an output directory: out_open(&o, d, "x.tsv"), write to o.fp,
 * out_commit(&o) checks and closes it (0 or -1, message printed). */
typedef struct out_file {
  FILE *fp;
  cli_outdir *d;
  char name[256];
} out_file;
int out_open(out_file *o, cli_outdir *d, const char *name);
int out_commit(out_file *o);
void out_abort(out_file *o);

/* Draw NAME.png (.pdf, .svg) by running gnuplot on NAME.gp in the stage,
 * and check that the picture is complete (a PNG with its IEND chunk, a PDF
 * with its trailer, an SVG closed): gnuplot exits 0 even when it could not
 * write.  0, or -1 with the picture removed; 0 without a picture when
 * gnuplot cannot be started (cli_pictures_skipped). */
int cli_outdir_plot(cli_outdir *d, const char *name);

/* The pictures' format, png (default), pdf or svg: --format of
 * CLI_OPTS_OUT (drivers/cli.h).  cli_picture_format_check: 0, or 2 with the
 * message printed for another value. */
extern const char *cli_picture_format;
int cli_picture_format_check(const char *cmd);

/* 1 once a picture was skipped because gnuplot cannot be started (not
 * installed, or configured --without-gnuplot): that is said once on
 * stderr, is not a failure, and no summary may claim a picture. */
int cli_pictures_skipped(void);

/* The first lines of a picture's script: a comment naming the command,
 * the terminal (pngcairo W x H pixels, or the same proportions in pdfcairo
 * or svg) and 'set output "NAME.png"' (.pdf, .svg). */
void cli_gp_preamble(FILE *f, const char *cmd, const char *name, int w, int h,
                     const char *font);

/* S as a gnuplot single-quoted string literal, quotes included: ' is
 * doubled, control characters (a newline would end the command and let
 * the next line run as '!shell') become '?'.  Returns buf. */
const char *cli_gp_quote(const char *s, char *buf, size_t len);

#endif
