#!/usr/bin/env python3
"""Table of mechanism-core/src/sincos64.rs: sin(i pi/32) and cos(i pi/32) for
i = 0..=15 in double-double, each as (hi, lo) with hi the nearest f64 and lo
the nearest f64 to the rest, from 60-digit values (mpmath), printed as Rust
literals (bit patterns, with the decimal value in a comment). Usage:
    pip install mpmath && python3 scripts/sincos-f64-table.py
"""
import struct
from mpmath import mp, mpf, sin, cos, pi

mp.dps = 60


def f64(x):
    """Nearest f64 of the mpmath value x (Python's float() of a 60-digit
    decimal string rounds correctly)."""
    return float(mp.nstr(x, 60, strip_zeros=False))


def lit(v):
    bits = struct.unpack("<Q", struct.pack("<d", v))[0]
    return f"f64::from_bits(0x{bits:016x}) /* {v!r} */"


print("const TABLE: [[f64; 4]; 16] = [")
for i in range(16):
    a = i * pi / 32
    s, c = sin(a), cos(a)
    sh, ch = f64(s), f64(c)
    sl, cl = f64(s - mpf(sh)), f64(c - mpf(ch))
    print(f"    [\n        {lit(sh)},\n        {lit(sl)},\n        {lit(ch)},\n        {lit(cl)},\n    ],")
print("];")
