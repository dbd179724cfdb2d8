"""Vallado's exponential atmosphere, 0-1000 km (thesis Appendix F).

ρ(h) = ρ0 exp(−(h − h0)/H) on each band of Vallado, *Fundamentals of
Astrodynamics and Applications*, Table 8-4 (the model the thesis's Matlab
used; its Appendix F listing did not survive extraction).  Columns: base
altitude h0 [km], nominal density ρ0 [kg/m^3], scale height H [km].  The
last band (1000 km and up) is used for exactly h = 1000 km only: the model is
defined on 0 <= h <= 1000 km, and altitudes outside raise.
"""
from __future__ import annotations

import numpy as np
from numba import njit

# h0 [km], rho0 [kg/m^3], H [km]   (Vallado Table 8-4)
TABLE = np.array([
    [0.0, 1.225, 7.249],
    [25.0, 3.899e-2, 6.349],
    [30.0, 1.774e-2, 6.682],
    [40.0, 3.972e-3, 7.554],
    [50.0, 1.057e-3, 8.382],
    [60.0, 3.206e-4, 7.714],
    [70.0, 8.770e-5, 6.549],
    [80.0, 1.905e-5, 5.799],
    [90.0, 3.396e-6, 5.382],
    [100.0, 5.297e-7, 5.877],
    [110.0, 9.661e-8, 7.263],
    [120.0, 2.438e-8, 9.473],
    [130.0, 8.484e-9, 12.636],
    [140.0, 3.845e-9, 16.149],
    [150.0, 2.070e-9, 22.523],
    [180.0, 5.464e-10, 29.740],
    [200.0, 2.789e-10, 37.105],
    [250.0, 7.248e-11, 45.546],
    [300.0, 2.418e-11, 53.628],
    [350.0, 9.518e-12, 53.298],
    [400.0, 3.725e-12, 58.515],
    [450.0, 1.585e-12, 60.828],
    [500.0, 6.967e-13, 63.822],
    [600.0, 1.454e-13, 71.835],
    [700.0, 3.614e-14, 88.667],
    [800.0, 1.170e-14, 124.64],
    [900.0, 5.245e-15, 181.05],
    [1000.0, 3.019e-15, 268.00],
])
# read-only: a constant of the model, and the type compiled code gives a global array,
# so density() from Python and the air vector's compiled code share one density_kernel
TABLE.flags.writeable = False
H_MIN = 0.0  # m
H_MAX = 1000e3  # m


@njit(cache=True)
def density_kernel(h, table):
    """Density [kg/m^3] at geometric altitude h [m]; NaN outside 0-1000 km."""
    hk = h / 1000.0
    if not (hk >= 0.0 and hk <= 1000.0):
        return np.nan
    i = table.shape[0] - 1
    while table[i, 0] > hk:
        i -= 1
    return table[i, 1] * np.exp(-(hk - table[i, 0]) / table[i, 2])


def density(h: float) -> float:
    """Air density [kg/m^3] at altitude h [m] (0 <= h <= 1000 km)."""
    h = float(h)
    if not (H_MIN <= h <= H_MAX):
        raise ValueError(f"altitude {h / 1e3:g} km is outside the atmosphere model's "
                         f"range 0-1000 km (Vallado Table 8-4)")
    return float(density_kernel(h, TABLE))
