"""Every settable name with every kind of bad value: ``--set``/``--scale`` refuse it with one
line naming the field, never another exception (issue 19: ``--set phi0_deg=nan`` ended in a
KeyError traceback while the same value in a TOML file got a clean error).

The names come from the one table (tethersim.model.params: PARAMETERS, the 3-D start keys,
OPTIONS), so a name added later is attacked too.  Nothing here simulates.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.cli.conftest import call
from tethersim import load_preset
from tethersim.model.params import OPTIONS, PARAMETERS, apply_overrides
from tethersim.model.presets import INITIAL_3D_KEYS
from tethersim.model.satellite import SatelliteError

SAT = load_preset("satI")
NUMBERS = tuple(PARAMETERS) + tuple(INITIAL_3D_KEYS)
ALL_NAMES = NUMBERS + tuple(OPTIONS)
# not a finite number, or not one number: none is a value of any settable name
BAD = ("nan", "NaN", "inf", "-inf", "+inf", "abc", "", " ", "1,2", "1e999", "-1e999",
       "9" * 400, "1..2", "0x10", "1 2", "nan,nan,nan", "inf,1,1", "1,2,3,4", "\n",
       "1\n2", "2017-13-45T99:00:00")


def _refused(exc: BaseException, name: str) -> None:
    """A refusal as the project wants it: ValueError/SatelliteError, one line, names ``name``."""
    assert isinstance(exc, (ValueError, SatelliteError)), repr(exc)
    text = str(exc)
    assert len(text.strip().splitlines()) == 1, text
    assert name.removesuffix("_deg") in text, text  # the 3-D start says "phi0 = 81 deg"


def _attempt(sets=(), scales=()):
    try:
        apply_overrides(SAT, sets, scales)
    except Exception as exc:  # noqa: BLE001 - the property is "no other exception"
        return exc
    return None


@pytest.mark.parametrize("name", ALL_NAMES)
@pytest.mark.parametrize("text", BAD)
def test_every_settable_name_refuses_every_bad_text_in_one_line_naming_it(name, text):
    exc = _attempt([f"{name}={text}"])
    assert exc is not None, f"--set {name}={text!r} was accepted"
    _refused(exc, name)


@pytest.mark.parametrize("name", NUMBERS)
@pytest.mark.parametrize("text", ("nan", "inf", "-inf", "abc", "", "1,2", "1e999"))
def test_every_scalable_name_refuses_a_bad_factor_in_one_line_naming_it(name, text):
    exc = _attempt(scales=[f"{name}={text}"])
    assert exc is not None, f"--scale {name}={text!r} was accepted"
    _refused(exc, name)


@settings(max_examples=300, deadline=None)
@given(name=st.sampled_from(ALL_NAMES), text=st.text(max_size=30))
def test_any_text_for_any_name_is_accepted_or_refused_in_one_line(name, text):
    exc = _attempt([f"{name}={text}"])
    if exc is not None:
        _refused(exc, name)


@pytest.mark.parametrize("argv", [
    ["show", "satI", "--set", "phi0_deg=nan"],
    ["show", "satI", "--set", "psi0_deg=abc"],
    ["show", "satI", "--set", "delta_z=inf"],
    ["show", "satI", "--scale", "phi_dot=nan"],
    ["run", "satI", "--set", "delta_z_dot=1,2", "--periods", "0.01"],
    ["equilibrium", "satI", "--set", "I1=nan,1,1"],
])
def test_cli_refuses_a_bad_set_with_exit_2_and_one_stderr_line(argv, tmp_path):
    code, out, err = call(argv + (["--out", str(tmp_path / "o")] if argv[0] == "run" else []))
    assert code == 2
    assert len(err.strip().splitlines()) == 1, err
    name = argv[argv.index("--set" if "--set" in argv else "--scale") + 1].split("=")[0]
    assert err.startswith("tethersim: error: ") and name in err, err
    assert not (tmp_path / "o").exists()  # refused before anything was made
