"""Write a Satellite as a preset TOML file (the layout tethersim.model.presets reads)."""
from __future__ import annotations

import json
import math

from tethersim.model.presets import INITIAL_3D_KEYS, N_PER_MM2_TO_N
from tethersim.model.satellite import Satellite


def dumps(sat: Satellite, notes: dict | None = None, header: str = "") -> str:
    """TOML text for ``sat``; notes: {key: comment} written beside the values."""
    notes = notes or {}
    x0 = sat.initial
    tables = {
        "satellite": {k: getattr(sat, k) for k in ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b")},
        "tethers": {"l10": sat.l10, "l20": sat.l20, "E1_N_per_mm2": sat.E1 / N_PER_MM2_TO_N,
                    "E2_N_per_mm2": sat.E2 / N_PER_MM2_TO_N, "c1": sat.c1, "c2": sat.c2},
        "orbit": {"altitude_km": sat.altitude / 1e3},
        "initial": {"delta_x": x0[0], "delta_y": x0[1], "theta0_deg": math.degrees(x0[2]),
                    "delta_x_dot": x0[3], "delta_y_dot": x0[4], "theta_dot": x0[5]},
        "environment": {"CD": sat.CD},
    }
    if not sat.density_auto:  # else absent: the density follows the orbit when read back
        tables["environment"]["density"] = sat.density_mode
    for key, (_, name, si) in INITIAL_3D_KEYS.items():  # the 3-D start, where set
        if name in sat.initial_3d:
            tables["initial"][key] = sat.initial_3d[name] / si
    if sat.allow_implausible:
        tables["model"] = {"allow_implausible": True}
    changed = sat.to_dict()  # options away from their defaults only
    tables["orbit"].update({k: changed[k] for k in ("orbit", "j2", "eccentricity") if k in changed})
    if "reentry_altitude" in changed:
        tables["orbit"]["reentry_altitude_km"] = sat.reentry_altitude / 1e3
    tables["satellite"].update({k: changed[k] for k in ("inertia", "I1", "I2") if k in changed})
    tables["tethers"].update({k: changed[k] for k in ("Fb1", "Fb2") if k in changed})
    air = {k: changed[k] for k in ("atmosphere", "epoch", "f107", "f107a", "ap", "density_scale")
           if k in changed}
    if air:
        tables["atmosphere"] = air
    lines = [f"# {line}" if line else "#" for line in header.splitlines()]
    lines.append(f"name = {_toml_string(sat.name)}")
    for table, values in tables.items():
        lines += ["", f"[{table}]"]
        for key, v in values.items():
            # 15 significant digits: 30.0, not the 29.999999999999996 of degrees(pi/6)
            if isinstance(v, bool):
                text = "true" if v else "false"
            elif isinstance(v, (tuple, list)):  # I1, I2: [roll, pitch, yaw]
                text = "[" + ", ".join(repr(float(x)) for x in v) + "]"
            else:
                text = _toml_string(v) if isinstance(v, str) else repr(float(f"{float(v):.15g}"))
            note = notes.get(key) or notes.get(key.split("_N_per")[0])
            lines.append(f"{key} = {text}" + (f"  # {note}" if note else ""))
    return "\n".join(lines) + "\n"


def _toml_string(text: str) -> str:
    """A TOML basic string: JSON's escapes (\\", \\\\, \\n, \\uXXXX) are TOML's, and DEL,
    which JSON leaves raw but TOML forbids, escaped too."""
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")
