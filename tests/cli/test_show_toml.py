"""``tethersim show --toml FILE`` writes the satellite shown, which reads back the same."""
from __future__ import annotations

import dataclasses

import pytest

import tethersim as ts
from tethersim.cli.main import main
from tethersim.model.params import apply_overrides


@pytest.mark.parametrize("preset, sets", [
    ("satI", ["E1=0.006"]),
    ("satII", ["orbit=free", "altitude=250", "I1=1,1.2,0.3", "phi0_deg=5"]),
    ("dumbsat", ["atmosphere=nrlmsise00", "epoch=2003-10-29T00:00:00", "density=per-body"]),
])
def test_the_written_file_reads_back_as_the_satellite_shown(tmp_path, capsys, preset, sets):
    path = tmp_path / "mine.toml"
    argv = ["show", preset, *[a for s in sets for a in ("--set", s)], "--toml", str(path)]
    assert main(argv) == 0
    assert f"wrote {path}" in capsys.readouterr().out
    got = ts.load(path)
    want = apply_overrides(ts.load_preset(preset), sets)
    differ = [f.name for f in dataclasses.fields(got)
              if f.name != "source" and getattr(got, f.name) != getattr(want, f.name)]
    assert differ == []


def test_a_toml_name_without_the_suffix_is_refused_in_one_line(tmp_path, capsys):
    assert main(["show", "satI", "--toml", str(tmp_path / "mine.txt")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "--toml" in err and ".toml" in err
    assert not (tmp_path / "mine.txt").exists()
