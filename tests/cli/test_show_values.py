"""``tethersim show`` prints each value as the short text that was typed, not the noise of
the SI -> edge-unit conversion (issue 19: ``show`` printed ``4.2299999999999995``).

The truth is independent of show's code: the preset TOML files' own text, and the text a
user typed with ``--set``; fed back, the printed text gives the same satellite.
"""
from __future__ import annotations

import re
from importlib import resources

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.cli.conftest import call
from tethersim.model import params
from tethersim.model.presets import PRESET_NAMES, load_preset


def _printed(argv) -> dict:
    """{name: value text} of the parameter lines of ``tethersim show``."""
    code, out, err = call(["show", *argv])
    assert code == 0, err
    rows = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[0] in params.NAMES:
            rows[parts[0]] = parts[1]
    return rows


def _toml_texts(file: str) -> dict:
    """{parameter name: its value as written in the preset file} (the file's own text)."""
    text = (resources.files("tethersim.model.presets") / file).read_text()
    found = {}
    for name, p in params.PARAMETERS.items():
        key = p.key.split(".", 1)[1]
        m = re.search(rf"^{re.escape(key)}\s*=\s*([-+0-9.eE]+)", text, flags=re.M)
        if m:
            found[name] = m.group(1)
    return found


@pytest.mark.parametrize("file", sorted(PRESET_NAMES.values()))
def test_show_prints_every_preset_value_as_its_toml_text(file):
    written = _toml_texts(file)
    assert {"E1", "E2", "altitude", "m1", "c1"} <= set(written)  # the regex found the file's
    printed = _printed([file.removesuffix(".toml")])
    for name, text in written.items():
        # the same number, and no longer than the file's text ("6" for "6.0", never noise)
        assert float(printed[name]) == float(text), name
        assert len(printed[name]) <= len(text), (name, printed[name], text)


SCALED = [n for n, p in params.PARAMETERS.items() if p.factor != 1.0]


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(SCALED), digits=st.integers(1, 9), u=st.floats(0.0, 1.0))
def test_show_prints_a_set_value_as_typed_and_it_reads_back_to_the_same_satellite(name, digits,
                                                                                 u):
    p = params.PARAMETERS[name]
    low = max(p.low, 1e-6 if p.zero_ok else p.low)
    typed = f"{low + u * (p.high - low):.{digits}g}"
    if name == "altitude" and float(typed) <= 120:  # keep the re-entry altitude below it
        typed = "300"
    argv = ["satI", "--set", f"{name}={typed}", "--allow-implausible"]
    printed = _printed(argv)[name]
    assert float(printed) == float(typed) and len(printed) <= len(typed), (printed, typed)
    again = call(["show", "satI", "--set", f"{name}={printed}", "--allow-implausible"])[1]
    assert again == call(["show", *argv])[1]


def test_show_prints_the_issues_example_without_conversion_noise():
    sat = load_preset("satI")
    sat = params.with_values(sat, {"E2": 4.23})
    assert params.edge_text(sat, "E2") == "4.23"
    assert _printed(["satI", "--set", "E2=4.23"])["E2"] == "4.23"


def test_show_rounds_the_float_noise_of_a_scale_product_to_twelve_digits():
    # 0.0423 x 100 is 4.2299999999999995 in double precision: show says 4.23
    noisy = 0.0423 * 100
    assert repr(noisy) != "4.23"  # the premise: the product carries noise
    shown = _printed(["satI", "--set", "E2=0.0423", "--scale", "E2=100"])["E2"]
    assert shown == "4.23" and abs(float(shown) - noisy) <= 5e-13 * noisy
