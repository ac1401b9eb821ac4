# test/bench/blocks_model.awk — the schedule of blocks.c's MPI protocol
# (drivers/blocks_mpi.c) replayed on measured block costs: rank 0 hands
# each of R - 1 ranks q = min(4, max(1, M / 2R)) of a stage's M blocks,
# computes blocks itself between messages (a message waits until rank 0
# finishes its block), gives a rank its next block with each one it gets
# back; a stage ends when all are back (then the broadcast, free here).
# Messages take no time; each rank computes a block in its measured CPU
# seconds (as on cores of its own).  Input: a WHIRL_BLOCK_TIMES file (stage,
# block, rank, start, end, bytes, cpu).  -v R=ranks -v S=seconds every rank
# spends outside the blocks (the attractors, the states, taking in the
# rounds).  Prints the time on R ranks and the efficiency T1 / (R T_R).
# usage: awk -F '\t' -v R=2 -v S=0.3 -f blocks_model.awk times.tsv
# SPDX-License-Identifier: BSD-3-Clause
NR > 1 { c[$1, $2] = $7; if ($2 + 1 > nb[$1]) nb[$1] = $2 + 1; if ($1 + 1 > ns) ns = $1 + 1; tot += $7 }
function assign(w, b, t) { b = ordv[b]; fin[w] = (fin[w] > t ? fin[w] : t) + c[st, b]; np++; pt[np] = fin[w]; pw[np] = w }
function pop_earliest(limit,   i, k) { # the earliest reply at or before limit: its rank, or 0
  k = 0
  for (i = 1; i <= np; i++) if (pt[i] <= limit && (k == 0 || pt[i] < pt[k])) k = i
  if (k == 0) return 0
  w = pw[k]; pt[k] = pt[np]; pw[k] = pw[np]; np--
  return w
}
END {
  now = 0
  for (st = 0; st < ns; st++) {
    M = nb[st]; q = int(M / (2 * R)); q = q < 1 ? 1 : q > 4 ? 4 : q
    nxt = 0; np = 0; j = 0; per = int((M + 7) / 8)
    for (k = 0; k < 8 * per; k++) { i = (k % per) * 8 + int(k / per); if (i < M) ordv[j++] = i }
    for (w = 1; w < R; w++) fin[w] = now
    for (k = 0; k < q; k++) for (w = 1; w < R && nxt < M; w++) assign(w, nxt++, now)
    for (;;) {
      w = pop_earliest(now)
      if (w) { if (nxt < M) assign(w, nxt++, now); continue }
      if (nxt < M) { now += c[st, ordv[nxt++]]; continue }
      if (np == 0) break
      e = 1e300; for (i = 1; i <= np; i++) if (pt[i] < e) e = pt[i]
      now = e
    }
  }
  t1 = S + tot; tr = S + now
  printf "R = %d: blocks %.2f s in one process, %.2f s on %d ranks; with %.2f s outside blocks on each: T1 = %.2f s, T%d = %.2f s, efficiency %.3f\n", R, tot, now, R, S, t1, R, tr, t1 / (R * tr)
}
