/* test/bench/bench_wall.c — the wall time of one whole process, without
 * the cost of timing it: `bench_wall FILE CMD [ARG...]` runs CMD (its
 * standard streams this program's), appends the seconds from fork to its
 * exit to FILE ("%.6f\n"), and exits with CMD's status.  Timing with
 * `date +%s%N` around a command adds the start of a `date` process
 * (~0.7 ms here) to every measurement: 5 % of a 13 ms whirl run, 0.3 % of
 * AUTO-07p's 210 ms (test/bench/compare_auto.sh).
 * SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: bench_wall FILE CMD [ARG...]\n");
    return 2;
  }
  FILE *out = fopen(argv[1], "a");
  if (!out) {
    fprintf(stderr, "bench_wall: cannot open %s: %s\n", argv[1], strerror(errno));
    return 2;
  }
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  const pid_t pid = fork();
  if (pid < 0) {
    fprintf(stderr, "bench_wall: fork: %s\n", strerror(errno));
    return 2;
  }
  if (pid == 0) {
    execvp(argv[2], argv + 2);
    fprintf(stderr, "bench_wall: cannot run %s: %s\n", argv[2], strerror(errno));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      fprintf(stderr, "bench_wall: waitpid: %s\n", strerror(errno));
      return 2;
    }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  fprintf(out, "%.6f\n", (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
  if (fclose(out)) return 2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
