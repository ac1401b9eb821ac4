/* drivers/plot.c — pictures through gnuplot (pngcairo): the driver writes a
 * self-contained script (data in datablocks) next to the data, so a user can
 * edit and re-run it, and runs gnuplot on it in the output directory.
 * SPDX-License-Identifier: BSD-3-Clause */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config.h"
#include "cli.h"

int cli_gnuplot(const char *dir, const char *script, char *msg, size_t len) {
  const char *gp = getenv("WHIRL_GNUPLOT");
  if (!gp || !*gp) gp = WHIRL_GNUPLOT;
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(msg, len, "cannot start gnuplot: %s", strerror(errno));
    return -1;
  }
  if (pid == 0) {
    if (chdir(dir) != 0) _exit(126);
    /* gnuplot's own messages go to our stderr */
    execlp(gp, gp, script, (char *)NULL);
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      snprintf(msg, len, "waiting for gnuplot: %s", strerror(errno));
      return -1;
    }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    snprintf(msg, len, "gnuplot not found ('%s'); on Debian: apt-get install gnuplot-nox", gp);
    return -1;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    snprintf(msg, len, "gnuplot failed on %s/%s (exit status %d)", dir, script,
             WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return -1;
  }
  return 0;
}

int cli_plot(const char *dir, const char *name, char *msg, size_t len) {
  char script[512], a[4096], b[4096];
  snprintf(script, sizeof script, "%s.gp", name);
  if (cli_gnuplot(dir, script, msg, len)) return -1;
  snprintf(a, sizeof a, "%s/.%s.png.tmp", dir, name);
  snprintf(b, sizeof b, "%s/%s.png", dir, name);
  if (rename(a, b)) {
    snprintf(msg, len, "gnuplot did not write %s: %s", a, strerror(errno));
    return -1;
  }
  return 0;
}
