"""Where a warm `tethersim run satI --periods 50` spends its time (diagnostic).

Run as a fresh process (python bench/cli_phases.py OUTDIR): does what
tethersim.cli.cmd_run does for the default adaptive run, timing each phase,
and prints one JSON object.  Not a target, only an explanation of the CLI
wall time.
"""
from __future__ import annotations

import json
import sys
import time

T_START = time.perf_counter()


def main(out_dir: str) -> None:
    from pathlib import Path

    phases = {}
    t = time.perf_counter()
    import numpy  # noqa: F401
    phases["import numpy"] = time.perf_counter() - t
    t = time.perf_counter()
    import numba  # noqa: F401
    phases["import numba"] = time.perf_counter() - t
    t = time.perf_counter()
    import tethersim as ts
    from tethersim.cli.main import build_parser  # noqa: F401
    from tethersim.engine.simulate import simulate
    phases["import tethersim (cli, simulation, integrators from numba cache)"] = (
        time.perf_counter() - t)
    t = time.perf_counter()
    from tethersim.output.plots.run import plot_result
    phases["import tethersim.output.plots.run"] = time.perf_counter() - t
    from tethersim.model.presets import resolve
    sat = resolve("satI")
    t = time.perf_counter()
    res = simulate(sat, periods=50.0, check=False, progress=False)
    phases["simulate: main DOP853 run (rtol 1e-10), 1st call"] = time.perf_counter() - t
    t = time.perf_counter()
    simulate(sat, periods=50.0, rtol=1e-12, atol=1e-14, check=False, progress=False)
    phases["simulate: convergence check run (rtol 1e-12)"] = time.perf_counter() - t
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    t = time.perf_counter()
    ts.write_timeseries(res, out / "timeseries.csv")
    phases["write CSV"] = time.perf_counter() - t
    t = time.perf_counter()
    ts.write_netcdf(res, out / "timeseries.nc")
    phases["write NetCDF (scipy.io, no xarray)"] = time.perf_counter() - t
    t = time.perf_counter()
    plot_result(res, out)
    phases["plots (4 PNGs, incl. matplotlib import)"] = time.perf_counter() - t
    t = time.perf_counter()
    ts.run_summary(res)
    phases["summary"] = time.perf_counter() - t
    phases["total in process"] = time.perf_counter() - T_START
    print(json.dumps(phases))


if __name__ == "__main__":
    main(sys.argv[1])
