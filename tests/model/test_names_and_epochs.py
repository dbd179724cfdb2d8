"""A satellite's name is printable text of bounded length and round-trips through the TOML
that ``show --toml`` writes; its epoch is an explicit ISO date or date-time (UTC, an offset
converted to UTC), never 'now' or a number."""
from __future__ import annotations

import datetime as dt
import tomllib

import pytest

from tethersim import load_preset
from tethersim.model.presets import from_dict
from tethersim.model.presets.write import dumps
from tethersim.model.satellite import MAX_NAME, SatelliteError

SAT = load_preset("satI")
BAD_NAMES = [None, 5, "", "   ", "a\nb", "red\x1b[31m", "tab\there", "x" * (MAX_NAME + 1)]


@pytest.mark.parametrize("name", BAD_NAMES, ids=repr)
def test_bad_name_is_refused_in_one_line(name):
    with pytest.raises(SatelliteError) as err:
        SAT.replace(name=name)
    line = str(err.value)
    assert "\n" not in line and "\x1b" not in line and "name = " in line


@pytest.mark.parametrize("name", ['q"x\\y', "Satellit Ω", "a'b", "x" * MAX_NAME])
def test_toml_of_any_valid_name_reads_back_the_same(name):
    sat = SAT.replace(name=name)
    doc = tomllib.loads(dumps(sat))
    assert doc["name"] == name
    assert from_dict(doc, "x.toml") == sat


BAD_EPOCHS = [("now", "ISO date"), (5, "ISO date"), (None, "ISO date"),
              ("2017-13-01", "ISO date"), ("2017-06-23T00:00:00.5", "whole seconds")]


@pytest.mark.parametrize("epoch, why", BAD_EPOCHS, ids=[repr(e) for e, _ in BAD_EPOCHS])
def test_bad_epoch_is_refused_in_one_line(epoch, why):
    with pytest.raises(SatelliteError) as err:
        SAT.replace(atmosphere="nrlmsise00", epoch=epoch)
    assert "\n" not in str(err.value) and "epoch = " in str(err.value) and why in str(err.value)


@pytest.mark.parametrize("text", ["2017-06-23T00:00:00+05:00", "2017-06-23T05:30:00-02:00",
                                  "2017-06-23T00:00:00Z", "2017-06-23"])
def test_epoch_is_the_same_instant_in_utc(text):
    """An offset is converted (no numpy timezone warning: pytest runs warnings as errors)."""
    sat = SAT.replace(atmosphere="nrlmsise00", epoch=text)
    when = dt.datetime.fromisoformat(text)
    utc = (when.astimezone(dt.UTC).replace(tzinfo=None) if when.tzinfo else when)
    assert sat.epoch == utc.isoformat(timespec="seconds")
