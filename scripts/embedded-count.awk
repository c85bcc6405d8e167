# Counts the instructions executed between entries of probe_start and
# probe_end in a QEMU `-singlestep -d exec,nochain` trace (one line per
# executed instruction: "Trace N: HOST [FLAGS/PC/...] SYMBOL").
# Variables: start, end = the markers' addresses as 8 lowercase hex digits.
# Prints: evaluations, mean, min, max, then "fn NAME COUNT" per function
# (instructions per evaluation, summed over the run).
{
    i = index($0, "[")
    if (i == 0) next
    pc = substr($0, i + 10, 8)
    if (pc == start) { on = 1; n = 0; next }
    if (pc == end && on) {
        on = 0; runs++; total += n
        if (runs == 1 || n < lo) lo = n
        if (n > hi) hi = n
        next
    }
    if (on) { n++; per[$NF]++ }
}
END {
    if (runs == 0) { print "no evaluations found"; exit 1 }
    printf "evaluations %d mean %.1f min %d max %d\n", runs, total / runs, lo, hi
    for (f in per) printf "fn %s %.1f\n", f, per[f] / runs
}
