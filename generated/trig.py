"""GENERATED FILE - DO NOT EDIT.  sin and cos for every generated kernel.

Printed by derive/trig.py (`make derive`), which says why they are not libm's
and where they come from (FreeBSD msun / musl, Sun's fdlibm: "Copyright (C)
1993 by Sun Microsystems, Inc. All rights reserved.  Developed at SunPro, a Sun
Microsystems, Inc. business.  Permission to use, copy, modify, and distribute
this software is freely granted, provided that this notice is preserved.").
Within 1 ulp of libm (tests/derive/test_trig.py); one lane of a vector loop
gives the same bits as the scalar call.
"""
import math

from numba import njit, types
from numba.extending import intrinsic

TOINT = 6755399441055744.0  # 0x1.8p52: 1.5·2^52: (v + TOINT) − TOINT rounds v to an integer
INVPIO2 = 0.6366197723675814  # 0x1.45f306dc9c883p-1: 2/π
PIO2_1 = 1.5707963267341256  # 0x1.921fb544p0: first 33 bits of π/2
PIO2_2 = 6.077100506303966e-11  # 0x1.0b4611a6p-34: next 33 bits of π/2
PIO2_2T = 2.0222662487959506e-21  # 0x1.3198a2e037073p-69: π/2 − PIO2_1 − PIO2_2
S1 = -0.16666666666666632  # -0x1.5555555555549p-3: sin kernel
S2 = 0.00833333333332249  # 0x1.111111110f8a6p-7
S3 = -0.0001984126982985795  # -0x1.a01a019c161d5p-13
S4 = 2.7557313707070068e-06  # 0x1.71de357b1fe7dp-19
S5 = -2.5050760253406863e-08  # -0x1.ae5e68a2b9cebp-26
S6 = 1.58969099521155e-10  # 0x1.5d93a5acfd57cp-33
C1 = 0.0416666666666666  # 0x1.555555555554cp-5: cos kernel
C2 = -0.001388888888887411  # -0x1.6c16c16c15177p-10
C3 = 2.480158728947673e-05  # 0x1.a01a019cb159p-16
C4 = -2.7557314351390663e-07  # -0x1.27e4f809c52adp-22
C5 = 2.087572321298175e-09  # 0x1.1ee9ebdb4b1c4p-29
C6 = -1.1359647557788195e-11  # -0x1.8fae9be8838d4p-37
LIMIT = 1647099.3291015625  # 0x1.921fb544p20: 2^20·PIO2_1: below it n < 2^20 and the reduction is exact
SMALL = 0.78  # 0x1.8f5c28f5c28f6p-1: 0.78 < π/4: below it n = 0, y0 = x, y1 = 0


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
