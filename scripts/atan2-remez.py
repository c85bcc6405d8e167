# Usage: python3 scripts/atan2-remez.py 9 (needs mpmath and numpy): the f32
# coefficients of mechanism-core/src/trig.rs atan2_f32 (ATAN_P), with the
# truncation bound the tests check.
# Remez exchange for atan(t) ~ t + t^3 P(t^2) on [0, 1], minimizing the
# relative error of atan; P of degree n-1 in s = t^2. The coefficients are
# rounded to f32 one at a time, lowest first, re-fitting the higher ones with
# the rounded lower ones fixed.
import mpmath as mp, sys, numpy as np
mp.mp.dps = 40
def atan_rel_err(c, s):
    t = mp.sqrt(s); a = mp.atan(t)
    return (t + t**3 * sum(cj * s**j for j, cj in enumerate(c)) - a) / a
def remez(n, fixed, iters=25, N=3000):
    k = len(fixed)
    m = n - k                      # free coefficients c_k .. c_{n-1}
    def f(s):                      # what the free part must match, over s^k
        t = mp.sqrt(s)
        g = (mp.atan(t)/t - 1)/s - sum(cj*s**j for j, cj in enumerate(fixed))
        return g / s**k
    def w(s):
        t = mp.sqrt(s); return s*t/mp.atan(t) * s**k
    pts = [(1 - mp.cos(mp.pi*(i+1)/(m+1)))/2 for i in range(m+1)]
    grid = [mp.mpf(i)/N for i in range(1, N+1)]
    for it in range(iters):
        A = mp.matrix(m+1, m+1); b = mp.matrix(m+1, 1)
        for i, s in enumerate(pts):
            for j in range(m): A[i, j] = w(s)*s**j
            A[i, m] = (-1)**i
            b[i] = w(s)*f(s)
        x = mp.lu_solve(A, b)
        c = [x[j] for j in range(m)]
        E = lambda s: w(s)*(sum(c[j]*s**j for j in range(m)) - f(s))
        vals = [E(s) for s in grid]
        ext = []
        for i in range(N):
            l = abs(vals[i-1]) if i > 0 else 0
            r = abs(vals[i+1]) if i+1 < N else 0
            if abs(vals[i]) >= l and abs(vals[i]) >= r: ext.append((grid[i], vals[i]))
        alt = []
        for s, v in ext:
            if alt and mp.sign(alt[-1][1]) == mp.sign(v):
                if abs(v) > abs(alt[-1][1]): alt[-1] = (s, v)
            else: alt.append((s, v))
        while len(alt) > m+1:
            if abs(alt[0][1]) < abs(alt[-1][1]): alt.pop(0)
            else: alt.pop()
        if len(alt) < m+1: break
        pts = [s for s, _ in alt]
    return c
n = int(sys.argv[1])
fixed = []
for k in range(n):
    c = remez(n, fixed)
    if k == 0:
        exact = c
    fixed.append(mp.mpf(float(np.float32(float(c[0])))))
grid = [mp.mpf(i)/20000 for i in range(1, 20001)]
e_exact = max(abs(atan_rel_err(exact, s)) for s in grid)
e_f32 = max(abs(atan_rel_err(fixed, s)) for s in grid)
naive = [mp.mpf(float(np.float32(float(cj)))) for cj in exact]
e_naive = max(abs(atan_rel_err(naive, s)) for s in grid)
print(f"n = {n}: minimax relative error {mp.nstr(e_exact, 4)} ({mp.nstr(e_exact*2**24, 3)} x 2^-24); "
      f"f32 coefficients rounded in turn {mp.nstr(e_f32, 4)} ({mp.nstr(e_f32*2**24, 3)} x 2^-24); rounded at once {mp.nstr(e_naive*2**24, 3)} x 2^-24")
for j, cj in enumerate(fixed):
    b = np.float32(float(cj)).view(np.uint32)
    print(f"const A{2*j+3}: f32 = f32::from_bits(0x{b >> 16:04X}_{b & 0xFFFF:04X}); // {float(cj):.9e} (exact minimax {mp.nstr(exact[j], 12)})")
