/* drivers/outdir.c — output directories written as one transaction
 * (outdir.h says what is replaced, what is refused and why).
 *
 * The staging directory PATH.tmp.PID is a sibling of PATH, so both renames
 * of the swap stay on one file system and are atomic.  A signal during the
 * run removes the stage (async-signal-safe calls only: open, getdents64,
 * unlinkat, rmdir, kill, waitpid); the swap itself runs with those signals
 * blocked.  Temporaries of a run that was killed with SIGKILL are removed
 * by the next run writing beside them, once their process is gone.
 * SPDX-License-Identifier: BSD-3-Clause */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.h"
#include "outdir.h"

/* Names the whirl commands of versions without a manifest wrote: such an
 * output directory is recognised by its entries (and hidden .NAME.tmp). */
static const char *const legacy_names[] = {
    "branches.tsv", "special.tsv", "response.gp", "response.png",
    "multipliers.gp", "multipliers.png", "sweep.tsv", "poincare.tsv",
    "sweep.gp", "sweep.png", "bifurcation.gp", "bifurcation.png",
    "basins.tsv", "attractors.tsv", "basins.gp", "basins.png",
    "history.tsv", "spectrum.tsv", "peaks.tsv", "history.gp", "history.png",
    "orbit.gp", "orbit.png", "spectrum.gp", "spectrum.png", "phase.gp",
    "phase.png", "nonsync.gp", "nonsync.png", "f2.gp", "f2.png", "upper.tsv",
    "lower.tsv", "band.tsv", "region.gp", "region.png", "run.log",
    "solutions", "diagram.gp", "diagram.png"};

/* ---- what the signal handler needs (fixed storage, no allocation) ------ */

static char sig_stage[4200];
static char sig_made[4096];
static volatile sig_atomic_t sig_armed;
volatile pid_t cli_outdir_child; /* a running gnuplot, killed first */
static const int caught[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
static struct sigaction saved[4];

struct linux_dirent64_ {
  uint64_t d_ino;
  int64_t d_off;
  unsigned short d_reclen;
  unsigned char d_type;
  char d_name[];
};

/* Unlink every entry of DIR (files only: whirl makes no subdirectories). */
static void empty_dir_raw(const char *dir) {
  int fd = open(dir, O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  char buf[4096] __attribute__((aligned(8)));
  for (int pass = 0; pass < 8; pass++) {
    long n = syscall(SYS_getdents64, fd, buf, sizeof buf), removed = 0;
    if (n <= 0) break;
    for (long off = 0; off < n;) {
      struct linux_dirent64_ *e = (struct linux_dirent64_ *)(buf + off);
      off += e->d_reclen;
      const char *s = e->d_name;
      if (s[0] == '.' && (!s[1] || (s[1] == '.' && !s[2]))) continue;
      if (unlinkat(fd, s, 0) == 0) removed++;
    }
    if (!removed) break;
    lseek(fd, 0, SEEK_SET);
  }
  close(fd);
}

/* rmdir PATH's parents from its dirname up to and including TOP while they
 * are empty (the parents cli_outdir_begin created).  Signal-safe. */
static void remove_made(const char *path, const char *top) {
  static char p[4096];
  size_t n = 0, tl = 0;
  while (path[n] && n + 1 < sizeof p) { p[n] = path[n]; n++; }
  p[n] = '\0';
  while (top[tl]) tl++;
  if (!tl) return;
  for (;;) {
    while (n > 0 && p[n - 1] != '/') n--;
    while (n > 0 && p[n - 1] == '/') n--;
    if (n < tl) return;
    p[n] = '\0';
    if (rmdir(p) != 0 || n == tl) return;
  }
}

static void on_signal(int sig) {
  pid_t child = cli_outdir_child;
  if (child > 0) {
    kill(child, SIGKILL);
    waitpid(child, NULL, 0);
  }
  if (sig_armed) {
    empty_dir_raw(sig_stage);
    rmdir(sig_stage);
    remove_made(sig_stage, sig_made);
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

static void arm(const cli_outdir *d) {
  snprintf(sig_stage, sizeof sig_stage, "%s", d->stage);
  snprintf(sig_made, sizeof sig_made, "%s", d->made);
  sig_armed = 1;
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (size_t i = 0; i < 4; i++) sigaddset(&sa.sa_mask, caught[i]);
  for (size_t i = 0; i < 4; i++) sigaction(caught[i], &sa, &saved[i]);
  signal(SIGXFSZ, SIG_IGN); /* a file-size limit fails the write instead */
}

static void disarm(void) {
  if (!sig_armed) return;
  sig_armed = 0;
  for (size_t i = 0; i < 4; i++) sigaction(caught[i], &saved[i], NULL);
}

static void block_signals(sigset_t *old) {
  sigset_t s;
  sigemptyset(&s);
  for (size_t i = 0; i < 4; i++) sigaddset(&s, caught[i]);
  sigprocmask(SIG_BLOCK, &s, old);
}

/* "whirl CMD: [WHERE: ]message" on stderr. */
static void say(const cli_outdir *d, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static void say(const cli_outdir *d, const char *fmt, ...) {
  char msg[2048];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (d->where && d->where[0]) cli_error(d->cmd, "%s: %s", d->where, msg);
  else cli_error(d->cmd, "%s", msg);
}

/* ---- what an output directory may hold ---------------------------------- */

static int is_legacy_name(const char *s) {
  for (size_t i = 0; i < sizeof legacy_names / sizeof *legacy_names; i++)
    if (!strcmp(s, legacy_names[i])) return 1;
  size_t n = strlen(s);
  return s[0] == '.' && n > 5 && !strcmp(s + n - 4, ".tmp"); /* .NAME.tmp */
}

/* The names DIR's manifest lists, as one string "\nA\nB\n", or NULL when
 * it has none. */
static char *read_manifest(const char *dir) {
  char p[8300];
  snprintf(p, sizeof p, "%s/%s", dir, CLI_OUTDIR_MANIFEST);
  FILE *f = fopen(p, "r");
  if (!f) return NULL;
  size_t cap = 256, len = 1;
  char *all = malloc(cap), line[1024];
  if (all) all[0] = '\n', all[1] = '\0';
  while (all && fgets(line, sizeof line, f)) {
    size_t n = strcspn(line, "\n");
    if (line[0] == '#' || n == 0) continue;
    line[n] = '\0';
    if (len + n + 2 > cap) {
      char *g = realloc(all, cap = 2 * (len + n + 2));
      if (!g) { free(all); all = NULL; break; }
      all = g;
    }
    memcpy(all + len, line, n);
    len += n;
    all[len++] = '\n';
    all[len] = '\0';
  }
  fclose(f);
  return all;
}

static int listed(const char *manifest, const char *name) {
  if (!manifest) return is_legacy_name(name);
  if (!strcmp(name, CLI_OUTDIR_MANIFEST)) return 1;
  size_t n = strlen(name);
  for (const char *s = strstr(manifest, name); s; s = strstr(s + 1, name))
    if (s[-1] == '\n' && s[n] == '\n') return 1;
  return 0;
}

/* 0 when every entry of the existing directory DIR is whirl's; else 2
 * with a message naming up to three others. */
static int check_replaceable(const cli_outdir *d, const char *dir) {
  DIR *h = opendir(dir);
  if (!h) {
    say(d, "cannot read the output directory '%s': %s", d->shown,
              strerror(errno));
    return 1;
  }
  char *manifest = read_manifest(dir);
  char other[600] = "";
  size_t nother = 0;
  struct dirent *e;
  while ((e = readdir(h))) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    char p[8300];
    struct stat st;
    snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
    int file = lstat(p, &st) == 0 && S_ISREG(st.st_mode);
    if (file && listed(manifest, e->d_name)) continue;
    if (nother++ < 3) {
      size_t l = strlen(other);
      snprintf(other + l, sizeof other - l, "%s'%.150s%s'", l ? ", " : "",
               e->d_name, file ? "" : "/");
    }
  }
  closedir(h);
  free(manifest);
  if (!nother) return 0;
  say(d, "output directory '%s' holds %s whirl did not write "
            "(%s%s): whirl replaces its output directory whole, so move %s or "
            "choose another output directory", d->shown,
            nother == 1 ? "an entry" : "entries", other,
            nother > 3 ? ", ..." : "", nother == 1 ? "it" : "them");
  return 2;
}

/* Remove DIR, a stage (every regular file is whirl's) or a previous output
 * (only the files its manifest lists, or the legacy names, when
 * ONLY_LISTED); anything else is left, and so is DIR then. */
static int remove_whirl_dir(const char *dir, int only_listed) {
  DIR *h = opendir(dir);
  if (!h) return errno == ENOENT ? 0 : -1;
  char *manifest = read_manifest(dir);
  struct dirent *e;
  int rc = 0;
  while ((e = readdir(h))) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    char p[8300];
    snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
    struct stat st;
    if (lstat(p, &st) == 0 && S_ISREG(st.st_mode) &&
        (!only_listed || listed(manifest, e->d_name))) {
      if (unlink(p) != 0) rc = -1;
    } else {
      rc = -1; /* not ours: left alone */
    }
  }
  closedir(h);
  free(manifest);
  if (rmdir(dir) != 0) rc = -1;
  return rc;
}

/* ---- stale temporaries of killed runs ----------------------------------- */

/* PID of "BASE.tmp.PID" or "BASE.old.PID" (kind 't' or 'o'), or 0. */
static long temp_pid(const char *name, const char *base, char *kind) {
  size_t bl = strlen(base);
  if (strncmp(name, base, bl) != 0) return 0;
  const char *s = name + bl;
  if (!strncmp(s, ".tmp.", 5)) *kind = 't';
  else if (!strncmp(s, ".old.", 5)) *kind = 'o';
  else return 0;
  char *end;
  long pid = strtol(s + 5, &end, 10);
  return *end || pid <= 0 ? 0 : pid;
}

static int process_gone(long pid) {
  return pid == (long)getpid() || (kill((pid_t)pid, 0) != 0 && errno == ESRCH);
}

static void remove_stale(const cli_outdir *d) {
  char parent[4096], b[4096];
  snprintf(parent, sizeof parent, "%s", d->path);
  char *slash = strrchr(parent, '/');
  snprintf(b, sizeof b, "%s", slash ? slash + 1 : parent);
  if (slash == parent) snprintf(parent, sizeof parent, "/");
  else if (slash) *slash = '\0';
  else snprintf(parent, sizeof parent, ".");
  DIR *h = opendir(parent);
  if (!h) return;
  struct dirent *e;
  while ((e = readdir(h))) {
    char kind = 0, p[8300];
    long pid = temp_pid(e->d_name, b, &kind);
    if (!pid || !process_gone(pid)) continue;
    snprintf(p, sizeof p, "%s/%s", parent, e->d_name);
    struct stat st;
    if (kind == 'o' && stat(d->path, &st) != 0 && errno == ENOENT)
      rename(p, d->path); /* killed mid-swap: the previous output back */
    else
      remove_whirl_dir(p, kind == 'o');
  }
  closedir(h);
}

/* ---- begin, files, commit, abort ---------------------------------------- */

/* Create the missing parents of d->path (mkdir -p), remembering the
 * topmost one created so that abort can remove it again. */
static int make_parents(cli_outdir *d) {
  char buf[4096];
  snprintf(buf, sizeof buf, "%s", d->path);
  char *last = strrchr(buf, '/');
  if (!last || last == buf) return 0;
  *last = '\0';
  for (char *q = buf + 1;; ++q) {
    if (*q != '/' && *q) continue;
    char c = *q;
    *q = '\0';
    if (mkdir(buf, 0777) == 0) {
      if (!d->made[0]) snprintf(d->made, sizeof d->made, "%s", buf);
    } else if (errno != EEXIST) {
      say(d, "cannot create '%s': %s", buf, strerror(errno));
      return 1;
    }
    *q = c;
    if (!c) break;
  }
  return 0;
}

/* Refuse '.', '..', '/' and the working directory or a directory above it
 * (replacing it would pull the directory away from under the user). */
static int check_not_cwd(const cli_outdir *d) {
  const char *base = strrchr(d->shown, '/');
  base = base ? base + 1 : d->shown;
  if (!d->shown[0] || !strcmp(d->shown, "/") || !strcmp(base, ".") ||
      !strcmp(base, "..")) {
    say(d, "'%s' cannot be an output directory (whirl replaces it "
              "whole): name a directory of its own", d->shown[0] ? d->shown : "/");
    return 2;
  }
  char cwd[PATH_MAX], rp[PATH_MAX];
  if (!realpath(d->path, rp) || !getcwd(cwd, sizeof cwd)) return 0;
  size_t n = strlen(rp);
  if (!strncmp(cwd, rp, n) && (cwd[n] == '\0' || cwd[n] == '/' || n == 1)) {
    say(d, "output directory '%s' is the working directory or "
              "contains it: whirl replaces its output directory whole, so "
              "choose one outside", d->shown);
    return 2;
  }
  return 0;
}

/* d->shown without trailing slashes; d->path the directory replaced. */
static int resolve(cli_outdir *d, const char *path) {
  size_t n = strlen(path);
  while (n > 1 && path[n - 1] == '/') n--;
  if (n >= sizeof d->shown - 16) {
    say(d, "output directory name too long (%zu characters)", n);
    return 2;
  }
  memcpy(d->shown, path, n);
  d->shown[n] = '\0';
  snprintf(d->path, sizeof d->path, "%s", d->shown);
  struct stat st;
  if (lstat(d->shown, &st) != 0) return 0;
  if (S_ISLNK(st.st_mode)) {
    char rp[PATH_MAX];
    if (!realpath(d->shown, rp) || stat(rp, &st) != 0 || !S_ISDIR(st.st_mode)) {
      say(d, "output directory '%s' is a symbolic link to no "
                "directory", d->shown);
      return 2;
    }
    snprintf(d->path, sizeof d->path, "%s", rp);
  } else if (!S_ISDIR(st.st_mode)) {
    say(d, "'%s' exists and is not a directory: choose another "
              "output directory", d->shown);
    return 2;
  }
  return 0;
}

/* The checks of cli_outdir_check on d (d->cmd set). */
static int check_path(cli_outdir *d, const char *path) {
  int rc = resolve(d, path);
  if (!rc) rc = check_not_cwd(d);
  struct stat st;
  if (!rc && stat(d->path, &st) == 0) rc = check_replaceable(d, d->path);
  return rc;
}

/* The nearest existing ancestor of PATH must let us create entries. */
static int check_writable(const cli_outdir *d) {
  char p[4096];
  struct stat st;
  snprintf(p, sizeof p, "%s", d->path);
  for (;;) {
    char *slash = strrchr(p, '/');
    if (!slash) snprintf(p, sizeof p, ".");
    else if (slash == p) p[1] = '\0';
    else *slash = '\0';
    if (stat(p, &st) == 0) break;
    if (!slash || slash == p) return 0;
  }
  if (!S_ISDIR(st.st_mode)) {
    say(d, "cannot create output directory '%s': '%s' is not a directory",
        d->shown, p);
    return 2;
  }
  if (access(p, W_OK | X_OK) == 0) return 0;
  say(d, "cannot create output directory '%s': '%s': %s", d->shown, p,
      strerror(errno));
  return 1; /* an I/O error, not a bad argument */
}

int cli_outdir_check(const char *cmd, const char *where, const char *path) {
  if (cli_picture_format_check(cmd)) return 2;
  cli_outdir *d = calloc(1, sizeof *d);
  if (!d) return 0; /* begin will say it */
  d->cmd = cmd;
  d->where = where;
  int rc = check_path(d, path);
  if (!rc) rc = check_writable(d);
  free(d);
  return rc;
}

int cli_outdir_begin(cli_outdir *d, const char *cmd, const char *where,
                     const char *path) {
  memset(d, 0, sizeof *d);
  d->cmd = cmd;
  d->where = where;
  int rc = check_path(d, path);
  if (rc) return rc;
  d->where = NULL; /* the rest are I/O errors, not the run file's */
  remove_stale(d);
  snprintf(d->stage, sizeof d->stage, "%s.tmp.%ld", d->path, (long)getpid());
  snprintf(d->old, sizeof d->old, "%s.old.%ld", d->path, (long)getpid());
  if (make_parents(d)) return 1;
  if (mkdir(d->stage, 0777) != 0) {
    say(d, "cannot create the output directory '%s' (as %s): %s",
              d->shown, d->stage, strerror(errno));
    if (d->made[0]) remove_made(d->stage, d->made);
    return 1;
  }
  arm(d);
  return 0;
}

const char *cli_outdir_shown(const cli_outdir *d, const char *name, char *buf,
                             size_t len) {
  snprintf(buf, len, "%s/%s", d->shown, name);
  return buf;
}

static int add_name(cli_outdir *d, const char *name) {
  for (size_t i = 0; i < d->nfiles; i++)
    if (!strcmp(d->files[i], name)) return 0;
  if (d->nfiles == d->cap) {
    size_t cap = d->cap ? 2 * d->cap : 16;
    char **g = realloc(d->files, cap * sizeof *g);
    if (!g) return -1;
    d->files = g;
    d->cap = cap;
  }
  if (!(d->files[d->nfiles] = strdup(name))) return -1;
  d->nfiles++;
  return 0;
}

int cli_outdir_record(cli_outdir *d, const char *name) {
  if (!add_name(d, name)) return 0;
  say(d, "out of memory");
  d->failed = 1;
  return -1;
}

FILE *cli_outdir_fopen(cli_outdir *d, const char *name) {
  char p[8300], s[4400];
  snprintf(p, sizeof p, "%s/%s", d->stage, name);
  FILE *f = add_name(d, name) ? NULL : fopen(p, "w");
  if (!f) {
    say(d, "cannot write %s: %s", cli_outdir_shown(d, name, s, sizeof s),
              strerror(errno ? errno : ENOMEM));
    d->failed = 1;
    return NULL;
  }
  /* written in pieces of 64 KiB, not stdio's 4 KiB: a response's table
   * in two system calls instead of eighteen */
  setvbuf(f, NULL, _IOFBF, (size_t)1 << 16);
  return f;
}

int cli_outdir_fclose(cli_outdir *d, FILE *f, const char *name) {
  if (!f) return -1;
  errno = 0;
  int bad = fflush(f) != 0 || ferror(f);
  int err = errno;
  if (fclose(f) != 0 && !bad) {
    bad = 1;
    err = errno;
  }
  if (!bad) return 0;
  char s[4400];
  if (!d->failed)
    say(d, "writing %s failed: %s", cli_outdir_shown(d, name, s, sizeof s),
              err ? strerror(err) : "write error");
  d->failed = 1;
  return -1;
}

void cli_outdir_discard(cli_outdir *d, const char *name) {
  char p[8300];
  snprintf(p, sizeof p, "%s/%s", d->stage, name);
  unlink(p);
  for (size_t i = 0; i < d->nfiles; i++)
    if (!strcmp(d->files[i], name)) {
      free(d->files[i]);
      d->files[i] = d->files[--d->nfiles];
      break;
    }
}

static void free_names(cli_outdir *d) {
  for (size_t i = 0; i < d->nfiles; i++) free(d->files[i]);
  free(d->files);
  d->files = NULL;
  d->nfiles = d->cap = 0;
}

void cli_outdir_abort(cli_outdir *d) {
  if (d->stage[0]) {
    empty_dir_raw(d->stage);
    rmdir(d->stage);
    if (d->made[0]) remove_made(d->stage, d->made);
  }
  disarm();
  free_names(d);
  d->stage[0] = '\0';
}

static int write_manifest(cli_outdir *d) {
  if (add_name(d, CLI_OUTDIR_MANIFEST)) return -1;
  FILE *f = cli_outdir_fopen(d, CLI_OUTDIR_MANIFEST);
  if (!f) return -1;
  fprintf(f, "# written by whirl %s: the files below are whirl's; a later run "
          "replaces this directory only while it holds nothing else\n", d->cmd);
  for (size_t i = 0; i < d->nfiles; i++)
    if (strcmp(d->files[i], CLI_OUTDIR_MANIFEST)) fprintf(f, "%s\n", d->files[i]);
  return cli_outdir_fclose(d, f, CLI_OUTDIR_MANIFEST);
}

/* The swap, with the caught signals blocked (see the file's comment). */
static int swap_in(cli_outdir *d) {
  struct stat st;
  int had_old = stat(d->path, &st) == 0;
  if (had_old && check_replaceable(d, d->path)) return 1; /* changed meanwhile */
  if (had_old && rename(d->path, d->old) != 0) {
    say(d, "cannot move the previous output '%s' aside: %s", d->shown,
              strerror(errno));
    return 1;
  }
  if (rename(d->stage, d->path) != 0) {
    int err = errno;
    if (had_old) rename(d->old, d->path);
    say(d, "cannot rename the new output into '%s': %s", d->shown,
              strerror(err));
    return 1;
  }
  d->stage[0] = '\0';
  if (had_old && remove_whirl_dir(d->old, 1) != 0)
    say(d, "warning: the previous output, moved to '%s', could not "
              "be removed completely", d->old);
  return 0;
}

int cli_outdir_commit(cli_outdir *d) {
  if (d->failed || write_manifest(d)) {
    cli_outdir_abort(d);
    return 1;
  }
  sigset_t old;
  block_signals(&old);
  int rc = swap_in(d);
  if (rc) cli_outdir_abort(d);
  disarm();
  free_names(d);
  sigprocmask(SIG_SETMASK, &old, NULL);
  return rc;
}

/* ---- single files -------------------------------------------------------- */

int out_open(out_file *o, cli_outdir *d, const char *name) {
  o->d = d;
  snprintf(o->name, sizeof o->name, "%s", name);
  o->fp = cli_outdir_fopen(d, name);
  return o->fp ? 0 : -1;
}

int out_commit(out_file *o) {
  int rc = cli_outdir_fclose(o->d, o->fp, o->name);
  o->fp = NULL;
  return rc;
}

void out_abort(out_file *o) {
  if (o->fp) fclose(o->fp);
  o->fp = NULL;
  cli_outdir_discard(o->d, o->name);
}
