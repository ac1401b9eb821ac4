/* drivers/plot.c — pictures through gnuplot (pngcairo, or pdfcairo and svg
 * with --format): the driver writes a self-contained script (data in
 * datablocks or the tables beside it) into the output directory, so a user
 * can edit and re-run it as it is, and runs gnuplot on it there — unless
 * the picture is a PNG whirl draws itself from that script (plot_here.c:
 * tried first).  gnuplot
 * exits 0 even when it could not write the picture (a full disk), so the
 * picture is checked to be complete (PNG: its IEND chunk; PDF: the %%EOF
 * trailer; SVG: the closing </svg>).
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config.h"
#include "cli.h"
#include "outdir.h"
#include "plot_here.h"

extern volatile pid_t cli_outdir_child; /* outdir.c: killed on a signal */

const char *cli_picture_format = "png";

/* gnuplot could not be started (not installed, or configured
 * --without-gnuplot and WHIRL_GNUPLOT unset): the pictures are skipped,
 * said once, and the run's status is what it would be with them. */
static int gnuplot_missing;

int cli_pictures_skipped(void) { return gnuplot_missing; }

int cli_picture_format_check(const char *cmd) {
  const char *f = cli_picture_format;
  if (!strcmp(f, "png") || !strcmp(f, "pdf") || !strcmp(f, "svg")) return 0;
  cli_error(cmd, "--format '%s': the pictures are png, pdf or svg", f);
  return 2;
}

const char *cli_gp_quote(const char *s, char *buf, size_t len) {
  size_t k = 0;
  if (len < 3) return "''";
  buf[k++] = '\'';
  for (; *s && k + 3 < len; s++) {
    unsigned char c = (unsigned char)*s;
    if (c == '\'') buf[k++] = '\'';
    buf[k++] = c < 0x20 || c == 0x7f ? '?' : (char)c;
  }
  buf[k++] = '\'';
  buf[k] = '\0';
  return buf;
}

/* pngcairo draws a font point as a pixel; pdfcairo at W/72 × H/72 inches
 * and svg at W × H points keep the same proportions of text to picture. */
void cli_gp_preamble(FILE *f, const char *cmd, const char *name, int w, int h,
                     const char *font) {
  const char *fmt = cli_picture_format;
  fprintf(f, "# gnuplot script written by whirl %s; redraw: gnuplot %s.gp\n",
          cmd, name);
  if (!strcmp(fmt, "pdf"))
    fprintf(f, "set terminal pdfcairo size %.2fin,%.2fin enhanced font '%s'\n",
            w / 72.0, h / 72.0, font);
  else if (!strcmp(fmt, "svg"))
    fprintf(f, "set terminal svg size %d,%d dynamic enhanced font '%s'\n", w,
            h, font);
  else
    fprintf(f, "set terminal pngcairo size %d,%d enhanced font '%s'\n", w, h,
            font);
  fprintf(f, "set output '%s.%s'\n", name, fmt);
}

/* Is PATH a complete PNG: the signature, and the IEND chunk at its end? */
static int png_complete(const char *path) {
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D',
                                         0xae, 0x42, 0x60, 0x82};
  unsigned char a[8], b[12];
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  int ok = fread(a, 1, 8, f) == 8 && !memcmp(a, sig, 8) &&
           fseek(f, -12, SEEK_END) == 0 && fread(b, 1, 12, f) == 12 &&
           !memcmp(b, iend, 12);
  fclose(f);
  return ok;
}

/* Does PATH begin with HEAD and end with TAIL (trailing blanks aside)? */
static int text_framed(const char *path, const char *head, const char *tail) {
  char a[16], b[64];
  size_t lh = strlen(head), lt = strlen(tail);
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  int ok = fread(a, 1, lh, f) == lh && !memcmp(a, head, lh) &&
           fseek(f, 0, SEEK_END) == 0;
  long size = ok ? ftell(f) : -1, from = size > 64 ? size - 64 : 0;
  size_t got = 0;
  if (ok && size > 0 && fseek(f, from, SEEK_SET) == 0)
    got = fread(b, 1, (size_t)(size - from), f);
  fclose(f);
  while (got > 0 && (b[got - 1] == '\n' || b[got - 1] == '\r' || b[got - 1] == ' '))
    --got;
  return ok && got >= lt && !memcmp(b + got - lt, tail, lt);
}

/* Is the picture PATH complete in its format? */
static int picture_complete(const char *path) {
  if (!strcmp(cli_picture_format, "pdf")) return text_framed(path, "%PDF-", "%%EOF");
  if (!strcmp(cli_picture_format, "svg")) return text_framed(path, "<?xml", "</svg>");
  return png_complete(path);
}

/* Run gnuplot in DIR with the arguments ARGS (scripts and -e commands,
 * NULL-terminated); its messages are kept in err (the first line) rather
 * than printed.  0 when it exited 0. */
static int run_gnuplot_args(const char *dir, const char *const *args, char *err,
                            size_t len) {
  const char *gp = getenv("WHIRL_GNUPLOT");
  if (!gp || !*gp) gp = WHIRL_GNUPLOT;
  if (!*gp) { /* configure --without-gnuplot */
    snprintf(err, len, "whirl was configured --without-gnuplot (set WHIRL_GNUPLOT "
             "to a gnuplot to draw them)");
    return -2;
  }
  int fd[2];
  err[0] = '\0';
  if (pipe(fd) != 0) {
    snprintf(err, len, "cannot start gnuplot: %s", strerror(errno));
    return -1;
  }
  fflush(NULL);
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(err, len, "cannot start gnuplot: %s", strerror(errno));
    close(fd[0]);
    close(fd[1]);
    return -1;
  }
  if (pid == 0) {
    dup2(fd[1], STDERR_FILENO);
    close(fd[0]);
    close(fd[1]);
    if (chdir(dir) != 0) _exit(126);
    const char *argv[2 * CLI_MAX_PICTURES + 2];
    size_t n = 0;
    argv[n++] = gp;
    for (size_t i = 0; args[i] && n + 1 < sizeof argv / sizeof *argv; i++)
      argv[n++] = args[i];
    argv[n] = NULL;
    execvp(gp, (char *const *)argv);
    _exit(127);
  }
  cli_outdir_child = pid;
  close(fd[1]);
  char buf[512];
  size_t got = 0;
  int line_done = 0;
  ssize_t r;
  while ((r = read(fd[0], buf, sizeof buf)) != 0) {
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) break;
    for (ssize_t i = 0; i < r && !line_done; i++) { /* keep the first line */
      if (buf[i] == '\n') line_done = got > 0;
      else if (got + 1 < len) err[got++] = buf[i];
    }
    err[got] = '\0';
  }
  close(fd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  cli_outdir_child = 0;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    snprintf(err, len, "gnuplot not found ('%s'); on Debian: apt-get install "
             "gnuplot-nox (or set WHIRL_GNUPLOT)", gp);
    return -2;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

static int run_gnuplot(const char *dir, const char *script, char *err, size_t len) {
  const char *args[] = {script, NULL};
  return run_gnuplot_args(dir, args, err, len);
}

/* NAME's picture by gnuplot (one process for it alone) */
static int plot_by_gnuplot(cli_outdir *d, const char *name) {
  char script[300], png[300], p[8600], shown[4400], err[300];
  snprintf(script, sizeof script, "%s.gp", name);
  snprintf(png, sizeof png, "%s.%s", name, cli_picture_format);
  snprintf(p, sizeof p, "%s/%s", d->stage, png);
  cli_outdir_shown(d, png, shown, sizeof shown);
  if (gnuplot_missing) return 0;
  int rc = run_gnuplot(d->stage, script, err, sizeof err);
  if (rc == 0 && picture_complete(p)) {
    return cli_outdir_record(d, png);
  }
  if (rc == -2) { /* no gnuplot: the scripts stay, to be run later */
    gnuplot_missing = 1;
    unlink(p);
    fprintf(stderr, "whirl %s: pictures skipped: %s; their scripts (*.gp) are "
            "written, run them with gnuplot in the output directory\n", d->cmd, err);
    return 0;
  }
  unlink(p);
  if (rc == 0)
    cli_error(d->cmd, "the picture %s is incomplete: gnuplot could not write "
              "it (%s%s)", shown, err[0] ? "gnuplot: " : "is the disk full?", err);
  else
    cli_error(d->cmd, "the picture %s failed: %s", shown,
              err[0] ? err : "gnuplot failed");
  return -1;
}

int cli_outdir_plot(cli_outdir *d, const char *name) {
  const int here = cli_draw_here(d, name);
  return here == 1 ? plot_by_gnuplot(d, name) : here;
}

/* All the pictures PICS of one run by one gnuplot process: its start-up
 * (fonts, cairo) costs more than drawing a picture.  `reset session`
 * between the scripts keeps each as it is when run alone.  Returns the
 * number of pictures it drew complete and recorded, in order; the rest are
 * drawn one by one by cli_outdir_plot, which reports what went wrong. */
static size_t plot_batch(cli_outdir *d, const char *const *pics, size_t n) {
  char scripts[CLI_MAX_PICTURES][300], pic[300], p[8600], err[300];
  const char *args[2 * CLI_MAX_PICTURES + 1];
  size_t na = 0, done = 0;
  if (n < 2 || n > CLI_MAX_PICTURES || gnuplot_missing) return 0;
  for (size_t i = 0; i < n; i++) {
    snprintf(scripts[i], sizeof scripts[i], "%s.gp", pics[i]);
    if (i) args[na++] = "-e";
    if (i) args[na++] = "unset output; reset session";
    args[na++] = scripts[i];
  }
  args[na] = NULL;
  if (run_gnuplot_args(d->stage, args, err, sizeof err) != 0) done = n;
  else done = 0;
  if (done == n) { /* the batch failed: nothing it wrote is kept */
    for (size_t i = 0; i < n; i++) {
      snprintf(p, sizeof p, "%s/%s.%s", d->stage, pics[i], cli_picture_format);
      unlink(p);
    }
    return 0;
  }
  for (; done < n; done++) {
    snprintf(pic, sizeof pic, "%s.%s", pics[done], cli_picture_format);
    snprintf(p, sizeof p, "%s/%s", d->stage, pic);
    if (!picture_complete(p) || cli_outdir_record(d, pic) != 0) break;
  }
  for (size_t i = done; i < n; i++) { /* not whirl's: redrawn, or not kept */
    snprintf(p, sizeof p, "%s/%s.%s", d->stage, pics[i], cli_picture_format);
    unlink(p);
  }
  return done;
}

int cli_outdir_finish(cli_outdir *d, int bad, const char *const *pics) {
  if (bad) {
    cli_outdir_abort(d);
    return 1;
  }
  size_t npics = 0;
  while (pics && pics[npics]) npics++;
  const char **rest = malloc((npics + 1) * sizeof *rest); /* gnuplot's */
  if (!rest) {
    cli_error(d->cmd, "out of memory");
    cli_outdir_abort(d);
    return 1;
  }
  int failed = 0;
  const size_t n = cli_draw_here_all(d, pics, rest, &failed);
  rest[n] = NULL;
  int pic = failed ? -1 : 0;
  for (size_t i = pic ? n : plot_batch(d, rest, n); i < n && !pic; i++)
    pic = plot_by_gnuplot(d, rest[i]);
  free(rest);
  return cli_outdir_commit(d) || pic;
}
