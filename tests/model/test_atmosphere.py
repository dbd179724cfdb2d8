"""Vallado's exponential atmosphere, 0-1000 km (thesis Appendix F, lost; facts.md).

Reference values: Vallado, *Fundamentals of Astrodynamics and Applications*,
Table 8-4 (base altitude h0 [km], nominal density ρ0 [kg/m³], scale height H [km]).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.model import atmosphere
from tethersim.model.atmosphere import H_MAX, H_MIN, TABLE, density, density_kernel

# Band bases and densities, typed from Vallado Table 8-4 (independent of TABLE)
VALLADO_BASES = [
    (0, 1.225), (25, 3.899e-2), (30, 1.774e-2), (40, 3.972e-3), (50, 1.057e-3),
    (60, 3.206e-4), (70, 8.770e-5), (80, 1.905e-5), (90, 3.396e-6), (100, 5.297e-7),
    (110, 9.661e-8), (120, 2.438e-8), (130, 8.484e-9), (140, 3.845e-9),
    (150, 2.070e-9), (180, 5.464e-10), (200, 2.789e-10), (250, 7.248e-11),
    (300, 2.418e-11), (350, 9.518e-12), (400, 3.725e-12), (450, 1.585e-12),
    (500, 6.967e-13), (600, 1.454e-13), (700, 3.614e-14), (800, 1.170e-14),
    (900, 5.245e-15), (1000, 3.019e-15),
]

# Largest allowed relative jump of ρ across a band boundary.  The model is
# piecewise: band i's exponential evaluated at the next base differs from the next
# band's ρ0 because Table 8-4 rounds ρ0 and H to four or five digits.  Measured
# jumps are <= 0.14 % (at 25 km, the longest band in scale heights, 25/7.249 ≈ 3.4 H)
# and <= 0.01 % everywhere else; 0.2 % allows that rounding but catches a typo in
# the leading digits of H on the long bands (a wrong ρ0 is caught exactly by the
# band-base test).
MAX_BOUNDARY_JUMP = 2e-3


@pytest.mark.parametrize("h_km, rho0", VALLADO_BASES)
def test_density_at_band_base_equals_vallado_rho0(h_km, rho0):
    assert density(h_km * 1e3) == pytest.approx(rho0, rel=1e-12)


def test_density_at_thesis_orbit_altitude():
    # facts.md: 200 km orbit; Vallado Table 8-4: ρ0(200 km) = 2.789e-10 kg/m³
    assert density(200e3) == pytest.approx(2.789e-10, rel=1e-12)


def test_table_bands_match_vallado_bases():
    assert [row[0] for row in TABLE] == [h for h, _ in VALLADO_BASES]
    assert np.all(np.diff(TABLE[:, 0]) > 0)
    assert np.all(TABLE[:, 2] > 0)


def test_density_inside_a_band_follows_the_exponential():
    # 225 km: band 200 km, ρ = 2.789e-10 exp(-25 / 37.105) (Vallado Table 8-4, Eq 8-33)
    assert density(225e3) == pytest.approx(2.789e-10 * math.exp(-25 / 37.105), rel=1e-12)
    # 0.5 km: band 0 km, H = 7.249 km
    assert density(500.0) == pytest.approx(1.225 * math.exp(-0.5 / 7.249), rel=1e-12)


def test_density_positive_and_strictly_decreasing_on_fine_grid():
    h = np.linspace(0.0, 1000e3, 20001)  # 50 m spacing
    rho = np.array([density(x) for x in h])
    assert np.all(np.isfinite(rho))
    assert np.all(rho > 0)
    assert np.all(np.diff(rho) < 0)


def test_density_continuous_across_band_boundaries():
    jumps = []
    for (h0, rho0, H), h1 in zip(TABLE[:-1], TABLE[1:, 0]):
        below = density((h1 - 1e-6) * 1e3)  # 1 mm under the boundary
        at = density(h1 * 1e3)
        expected_below = rho0 * math.exp(-(h1 - h0) / H)
        assert below == pytest.approx(expected_below, rel=1e-6)
        jumps.append(abs(at / below - 1))
    assert max(jumps) < MAX_BOUNDARY_JUMP, dict(zip(TABLE[1:, 0], jumps))


def test_range_constants_are_zero_and_1000_km():
    assert H_MIN == 0.0
    assert H_MAX == 1000e3


@pytest.mark.parametrize("h", [0.0, 1000e3, 1e-9, 1000e3 - 1e-6])
def test_range_ends_are_inside(h):
    assert density(h) > 0


@pytest.mark.parametrize("h", [-1.0, -5e3, 1000e3 + 1.0, 1500e3, math.nan, math.inf, -math.inf])
def test_outside_0_to_1000_km_raises_value_error_naming_the_range(h):
    with pytest.raises(ValueError, match="0-1000 km"):
        density(h)


def test_kernel_returns_nan_outside_the_range():
    for h in (-1.0, 1000e3 + 1.0, math.nan):
        assert math.isnan(density_kernel(h, TABLE))
    assert density_kernel(200e3, TABLE) == density(200e3)


def test_density_accepts_numpy_scalars_and_ints():
    assert density(np.float64(200e3)) == density(200_000)
    assert isinstance(atmosphere.density(200_000), float)
