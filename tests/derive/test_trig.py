"""generated/trig.py (printed by derive/trig.py): the kernels' sincos against libm, and
its lane form against the scalar one, bit for bit."""
import math

import numpy as np
import pytest
from numba import njit

from derive.trig import CONSTANTS, trig_source
from tethersim.generated import trig


@njit(cache=True)
def _scalar(x, s, c):
    for i in range(x.size):
        s[i], c[i] = trig.sincos(x[i])


@njit(cache=True)
def _lanes(x, s, c):
    """The lane form as derive/lanes.py prints it: libm's values beyond the limit in a
    first loop, then one loop of selects (vectorised by LLVM where the CPU allows)."""
    sb, cb = np.empty(x.size), np.empty(x.size)
    for i in range(x.size):
        sb[i], cb[i] = trig.sincos_beyond(x[i])
    for i in range(x.size):
        s[i], c[i] = trig.sincos_lane(x[i], sb[i], cb[i])


def _evaluate(f, x):
    s, c = np.empty_like(x), np.empty_like(x)
    f(x, s, c)
    return s, c


def _ulps(got, libm):
    return np.abs(got - libm) / np.spacing(np.abs(libm))


@pytest.mark.parametrize("half_width", [math.pi / 4, 10.0, 1e3, trig.LIMIT])
def test_sin_cos_within_one_ulp_of_libm_on_random_arguments(half_width):
    x = np.random.default_rng(7).uniform(-half_width, half_width, 200_000)
    s, c = _evaluate(_scalar, x)
    assert _ulps(s, np.sin(x)).max() <= 1.0
    assert _ulps(c, np.cos(x)).max() <= 1.0


def test_sin_cos_within_one_ulp_beside_every_multiple_of_half_pi():
    # where the reduction cancels most: the doubles nearest n*pi/2, n up to 2^17
    k = np.arange(1.0, 2.0**17) * (np.pi / 2)
    for x in (k, np.nextafter(k, np.inf), np.nextafter(k, -np.inf)):
        for signed in (x, -x):
            s, c = _evaluate(_scalar, signed)
            assert _ulps(s, np.sin(signed)).max() <= 1.0
            assert _ulps(c, np.cos(signed)).max() <= 1.0


def test_libm_beyond_the_limit_and_for_non_finite_arguments():
    x = np.array([trig.LIMIT, -trig.LIMIT, 2e6, -1e12, 1e300, np.inf, -np.inf, np.nan])
    with np.errstate(invalid="ignore"):
        libm_s, libm_c = np.sin(x), np.cos(x)
    s, c = _evaluate(_scalar, x)
    np.testing.assert_array_equal(s, libm_s)
    np.testing.assert_array_equal(c, libm_c)


def test_signed_zero_and_exact_values():
    s, c = _evaluate(_scalar, np.array([0.0, -0.0]))
    assert math.copysign(1.0, s[0]) == 1.0 and math.copysign(1.0, s[1]) == -1.0
    assert c.tolist() == [1.0, 1.0]


@njit(cache=True)
def _reduced_always(x, s, c):
    for i in range(x.size):
        s[i], c[i] = trig.sincos_poly(x[i])


def test_the_small_argument_path_skips_only_what_gives_the_same_bits():
    # below SMALL the scalar sincos leaves out the reduction (n = 0 there): the lanes,
    # which always reduce, must still equal it to the last bit
    x = np.random.default_rng(5).uniform(-trig.SMALL, trig.SMALL, 100_000)
    x = np.concatenate([x, [0.0, -0.0, 5e-324, -1e-300, np.nextafter(trig.SMALL, 0)]])
    for a, b in zip(_evaluate(_scalar, x), _evaluate(_reduced_always, x)):
        assert a.view(np.uint64).tolist() == b.view(np.uint64).tolist()
    assert trig.SMALL * trig.INVPIO2 < 0.5  # n = round(x 2/pi) = 0 below SMALL


def test_lane_form_equals_the_scalar_calls_bit_for_bit():
    rng = np.random.default_rng(11)
    x = np.concatenate([rng.uniform(-50.0, 50.0, 4093), rng.uniform(-1.0, 1.0, 1000),
                        [3e6, -np.inf, np.nan]])
    rng.shuffle(x)
    scalar, lanes = _evaluate(_scalar, x), _evaluate(_lanes, x)
    for a, b in zip(scalar, lanes):
        assert a.view(np.uint64).tolist() == b.view(np.uint64).tolist()


def test_constants_are_printed_exactly_and_the_module_is_what_derive_prints():
    from pathlib import Path
    printed = Path(trig.__file__).read_text()
    assert printed == trig_source()
    for name, bits, _ in CONSTANTS:
        assert getattr(trig, name) == float.fromhex(bits)
    # the reduction is exact below the limit: n*PIO2_1 has at most 20 + 33 bits
    assert trig.LIMIT == 2.0**20 * trig.PIO2_1
