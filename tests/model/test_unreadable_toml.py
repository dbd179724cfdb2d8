"""A satellite file that is not UTF-8 text is refused in one line naming the file and the
byte, from the API (SatelliteError, not a bare UnicodeDecodeError) and the CLI."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.cli.main import main
from tethersim.model.satellite import SatelliteError


@pytest.mark.parametrize("data, byte, offset", [
    (b'name = "x"\n\xff\xfe', "0xff", 11),
    ("name = \"sat\u00e9\"\n".encode("latin-1"), "0xe9", 11),  # Latin-1, not UTF-8
])
def test_load_names_the_file_and_the_byte(tmp_path, data, byte, offset):
    assert data[offset] == int(byte, 16)
    path = tmp_path / "bad.toml"
    path.write_bytes(data)
    with pytest.raises(SatelliteError) as info:
        ts.load(path)
    assert str(info.value) == (f"{path}: not a TOML text file: byte {byte} at offset {offset} "
                               f"is not UTF-8 (TOML files are UTF-8 text)")


def test_cli_says_it_in_one_line(tmp_path, capsys):
    path = tmp_path / "bin.toml"
    path.write_bytes(bytes(range(256)))
    assert main(["show", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and str(path) in err and "not UTF-8" in err
