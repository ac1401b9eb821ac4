/* drivers/outdir.c — output directories and atomic files: every file is
 * written under a temporary name and renamed into place only when complete,
 * so an error never leaves a half-written file behind.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

int cli_mkdirs(const char *path) {
  char buf[4096];
  size_t len = strlen(path);
  if (len == 0 || len >= sizeof buf) {
    errno = ENAMETOOLONG;
    return -1;
  }
  memcpy(buf, path, len + 1);
  for (char *q = buf + 1; *q; ++q) {
    if (*q != '/') continue;
    *q = '\0';
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
    *q = '/';
  }
  if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
  struct stat st;
  if (stat(buf, &st) != 0) return -1;
  if (!S_ISDIR(st.st_mode)) {
    errno = ENOTDIR;
    return -1;
  }
  return 0;
}

int out_open(out_file *o, const char *dir, const char *name) {
  int a = snprintf(o->tmp, sizeof o->tmp, "%s/.%s.tmp", dir, name);
  int b = snprintf(o->final, sizeof o->final, "%s/%s", dir, name);
  if (a < 0 || b < 0 || (size_t)a >= sizeof o->tmp || (size_t)b >= sizeof o->final) {
    errno = ENAMETOOLONG;
    o->fp = NULL;
    return -1;
  }
  o->fp = fopen(o->tmp, "w");
  return o->fp ? 0 : -1;
}

int out_commit(out_file *o) {
  int bad = ferror(o->fp);
  if (fclose(o->fp) != 0) bad = 1;
  o->fp = NULL;
  if (bad || rename(o->tmp, o->final) != 0) {
    unlink(o->tmp);
    return -1;
  }
  return 0;
}

void out_abort(out_file *o) {
  if (o->fp) fclose(o->fp);
  o->fp = NULL;
  unlink(o->tmp);
}
