"""tethersim/cli/validate.py: the thesis's Tables 4.4 and 4.5."""
from __future__ import annotations


def test_validate_one_satellite_prints_tables_4_4_and_4_5(cli):
    code, out, _ = cli(["validate", "satI"])
    assert code == 0
    assert "Table 4.4" in out
    assert "Table 4.5" in out
    assert "SatI" in out
    assert "kg m^2" in out and "rad/s" in out
