"""generated/trig.py: the sine and cosine every generated kernel calls.

Why not libm: numba's build has no vector libm (``numba -s``: SVML not available), so
a call to ``math.sin`` keeps LLVM from vectorising the loop that holds it.  The lane
form of the rhs (derive/lanes.py) advances K sweep points at once; with libm it had
to compute sin θ, cos θ lane by lane before its vector loop, and those calls took a
fifth of a sweep's time.  ``sincos_poly`` is plain IEEE arithmetic (no call, no
branch), so a lane loop that holds it vectorises, and one lane gives the same bits as
the scalar call (no fast-math flags: LLVM neither fuses nor reorders).

It is a numba ``intrinsic``: its LLVM instructions are emitted in place at each call,
so the kernels that hold it grow by about 45 instructions and nothing else.  Written as
numba functions inlined at numba's level, the same arithmetic doubled the compile time
of the sweep blocks (81 → 145-194 s for the adaptive lanes; numba re-infers the types of
a function after each inline), and not inlined it made every scalar run 20 % slower.

What they compute, from FreeBSD msun / musl (Sun's fdlibm):

* reduction (musl ``__rem_pio2``, its medium path): x = n·π/2 + (y0 + y1), n the
  nearest integer to 2x/π, π/2 in three pieces pio2_1 (33 bits), pio2_2 (33 bits) and
  pio2_2t, so n·pio2_1 and n·pio2_2 are exact for |n| < 2^20; musl's second round is
  taken always (it is conditional there only for speed);
* kernels on |y| ≤ π/4 (musl ``__sin``, ``__cos``): minimax polynomials of degree
  13 and 14 with the tail y1 carried, each within 1 ulp;
* the quadrant n mod 4 from n by the same round-to-integer trick, chosen by selects.

For |x| ≥ LIMIT = 2^20·π/2 (and NaN, inf) ``sincos`` returns libm's values.  The
test (tests/derive/test_trig.py) checks them against libm to 1 ulp on random
arguments and beside every multiple of π/2 up to 2^17.

Sun's notice, which the coefficients carry: "Copyright (C) 1993 by Sun Microsystems,
Inc. All rights reserved.  Developed at SunPro, a Sun Microsystems, Inc. business.
Permission to use, copy, modify, and distribute this software is freely granted,
provided that this notice is preserved."
"""
from __future__ import annotations

# (name, IEEE-754 bits as musl's comments give them, meaning): printed as exact decimals
CONSTANTS = (
    ("TOINT", "0x1.8p52", "1.5·2^52: (v + TOINT) − TOINT rounds v to an integer"),
    ("INVPIO2", "0x1.45f306dc9c883p-1", "2/π"),
    ("PIO2_1", "0x1.921fb544p0", "first 33 bits of π/2"),
    ("PIO2_2", "0x1.0b4611a6p-34", "next 33 bits of π/2"),
    ("PIO2_2T", "0x1.3198a2e037073p-69", "π/2 − PIO2_1 − PIO2_2"),
    ("S1", "-0x1.5555555555549p-3", "sin kernel"),
    ("S2", "0x1.111111110f8a6p-7", ""),
    ("S3", "-0x1.a01a019c161d5p-13", ""),
    ("S4", "0x1.71de357b1fe7dp-19", ""),
    ("S5", "-0x1.ae5e68a2b9cebp-26", ""),
    ("S6", "0x1.5d93a5acfd57cp-33", ""),
    ("C1", "0x1.555555555554cp-5", "cos kernel"),
    ("C2", "-0x1.6c16c16c15177p-10", ""),
    ("C3", "0x1.a01a019cb159p-16", ""),
    ("C4", "-0x1.27e4f809c52adp-22", ""),
    ("C5", "0x1.1ee9ebdb4b1c4p-29", ""),
    ("C6", "-0x1.8fae9be8838d4p-37", ""),
    ("LIMIT", "0x1.921fb544p20", "2^20·PIO2_1: below it n < 2^20 and the reduction is exact"),
    ("SMALL", "0x1.8f5c28f5c28f6p-1", "0.78 < π/4: below it n = 0, y0 = x, y1 = 0"),
)

BODY = '''

def _poly(context, builder, x, reduce):
    """(sin x, cos x) for |x| < LIMIT as LLVM instructions: IEEE operations in the
    written order (no fast-math flags), no branch, no call.  Without ``reduce`` (for
    |x| < SMALL, where n = 0) the kernels alone: y0 = x, y1 = 0 are what the reduction
    gives there, to the bit, and the quadrant's selects keep their operands."""
    def k(v):
        return context.get_constant(types.float64, v)

    mul, add, sub = builder.fmul, builder.fadd, builder.fsub
    if not reduce:
        return _kernels(k, builder, x, k(0.0))
    # reduction: x = n*pi/2 + y0 + y1 (musl __rem_pio2, medium path, second round always)
    n = sub(add(mul(x, k(INVPIO2)), k(TOINT)), k(TOINT))
    t = sub(x, mul(n, k(PIO2_1)))
    w = mul(n, k(PIO2_2))
    r = sub(t, w)
    w = sub(mul(n, k(PIO2_2T)), sub(sub(t, r), w))
    y0 = sub(r, w)
    y1 = sub(sub(r, y0), w)
    sk, ck = _kernels(k, builder, y0, y1)
    # quadrant m = n - 4*round(n/4) in {-2, -1, 0, 1, 2}
    m = sub(n, mul(k(4.0), sub(add(mul(k(0.25), n), k(TOINT)), k(TOINT))))

    def cmp(op, v):
        return builder.fcmp_ordered(op, m, k(v))

    odd = builder.or_(cmp("==", 1.0), cmp("==", -1.0))
    s = builder.select(odd, ck, sk)
    c = builder.select(odd, sk, ck)
    s = builder.select(builder.or_(cmp("<", 0.0), cmp(">", 1.0)), builder.fneg(s), s)
    c = builder.select(builder.or_(cmp(">", 0.0), cmp("<", -1.0)), builder.fneg(c), c)
    return s, c


def _kernels(k, builder, y0, y1):
    """sin and cos of y0 + y1, |y0 + y1| <= pi/4 (musl __sin with its tail, __cos)."""
    mul, add, sub = builder.fmul, builder.fadd, builder.fsub
    z = mul(y0, y0)
    w = mul(z, z)
    rs = add(add(k(S2), mul(z, add(k(S3), mul(z, k(S4))))),
             mul(mul(z, w), add(k(S5), mul(z, k(S6)))))
    v = mul(z, y0)
    sk = sub(y0, sub(sub(mul(z, sub(mul(k(0.5), y1), mul(v, rs))), y1), mul(v, k(S1))))
    rc = add(mul(z, add(k(C1), mul(z, add(k(C2), mul(z, k(C3)))))),
             mul(mul(w, w), add(k(C4), mul(z, add(k(C5), mul(z, k(C6)))))))
    hz = mul(k(0.5), z)
    wc = sub(k(1.0), hz)
    ck = add(wc, add(sub(sub(k(1.0), wc), hz), sub(mul(z, rc), mul(y0, y1))))
    return sk, ck


def _emitted(reduce):
    def typer(typingctx, x):
        def codegen(context, builder, signature, args):
            values = _poly(context, builder, args[0], reduce)
            return context.make_tuple(builder, signature.return_type, values)

        return types.UniTuple(types.float64, 2)(types.float64), codegen

    return intrinsic(typer)


# (sin x, cos x) by the polynomials, emitted in place: for |x| < LIMIT, and the kernels
# alone for |x| < SMALL (the same bits; a scalar run's pitch is mostly there)
sincos_poly = _emitted(reduce=True)
sincos_small = _emitted(reduce=False)


@njit(cache=True, inline="always")
def sincos(x):
    """(sin x, cos x): the polynomials for |x| < LIMIT, else libm's."""
    if abs(x) < SMALL:  # the same bits as sincos_poly, without the reduction's latency
        return sincos_small(x)
    if abs(x) < LIMIT:
        return sincos_poly(x)
    return math.sin(x), math.cos(x)


@njit(cache=True, inline="always")
def sincos_beyond(x):
    """libm's (sin x, cos x) where sincos does not use the polynomials, else zeros: the
    lane form's first (scalar) loop, so that its vector loop holds no call."""
    if abs(x) < LIMIT:
        return 0.0, 0.0
    return math.sin(x), math.cos(x)


@njit(cache=True, inline="always")
def sincos_lane(x, sin_beyond, cos_beyond):
    """sincos(x) inside a vector loop, bit for bit: the polynomials, or the values
    sincos_beyond(x) computed before the loop."""
    s, c = sincos_poly(x)
    small = abs(x) < LIMIT
    return (s if small else sin_beyond), (c if small else cos_beyond)
'''

# what the printed kernels call (derive/printer.py, derive/lanes.py)
CALLED = ("sincos", "sincos_beyond", "sincos_lane")


def trig_source() -> str:
    """Source text of generated/trig.py."""
    lines = ['"""GENERATED FILE - DO NOT EDIT.  sin and cos for every generated kernel.',
             "",
             "Printed by derive/trig.py (`make derive`), which says why they are not libm's",
             "and where they come from (FreeBSD msun / musl, Sun's fdlibm: \"Copyright (C)",
             "1993 by Sun Microsystems, Inc. All rights reserved.  Developed at SunPro, a Sun",
             "Microsystems, Inc. business.  Permission to use, copy, modify, and distribute",
             'this software is freely granted, provided that this notice is preserved.").',
             "Within 1 ulp of libm (tests/derive/test_trig.py); one lane of a vector loop",
             "gives the same bits as the scalar call.",
             '"""',
             "import math", "", "from numba import njit, types",
             "from numba.extending import intrinsic", ""]
    for name, bits, meaning in CONSTANTS:
        note = f"  # {bits}" + (f": {meaning}" if meaning else "")
        lines.append(f"{name} = {float.fromhex(bits)!r}{note}")
    return "\n".join(lines) + "\n" + BODY
