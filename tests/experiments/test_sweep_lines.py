"""The one JSON-lines store (experiments/sweep/lines.py): resume, refusal, cut lines."""
import json

import pytest

from tethersim.experiments.sweep.lines import LineStore, read_lines


def test_rows_put_survive_a_reopen_and_a_cut_line_is_dropped(tmp_path):
    with LineStore(tmp_path, "rows.jsonl", '{"a": 1}', "a test store") as store:
        store.put({"i": 0})
        store.put({"i": 1})
    with (tmp_path / "rows.jsonl").open("a") as fh:
        fh.write('{"i": 2')  # an interruption cut this line
    with LineStore(tmp_path, "rows.jsonl", '{"a": 1}', "a test store") as store:
        assert store.rows() == [{"i": 0}, {"i": 1}]


def test_another_spec_is_refused_in_one_line_naming_the_folder(tmp_path):
    with LineStore(tmp_path, "rows.jsonl", '{"a": 1}', "a test store"):
        pass
    with pytest.raises(ValueError) as exc:
        with LineStore(tmp_path, "rows.jsonl", '{"a": 2}', "a test store", "do something"):
            pass
    msg = str(exc.value)
    assert str(tmp_path) in msg and "a test store of other settings: do something" in msg
    assert "\n" not in msg
    # the refused writer released the lock: the right spec opens again
    with LineStore(tmp_path, "rows.jsonl", '{"a": 1}', "a test store"):
        pass


def test_rewrite_orders_the_rows_and_keeps_an_unchanged_file(tmp_path):
    with LineStore(tmp_path, "rows.jsonl", "{}", "a test store") as store:
        store.put({"i": 1}, flush=False)
        store.put({"i": 0}, flush=False)
        store.rewrite([{"i": 0}, {"i": 1}])
    path = tmp_path / "rows.jsonl"
    assert [json.loads(x) for x in path.read_text().splitlines()] == [{"i": 0}, {"i": 1}]
    before = path.stat().st_mtime_ns
    with LineStore(tmp_path, "rows.jsonl", "{}", "a test store") as store:
        store.rewrite(store.rows())
    assert path.stat().st_mtime_ns == before
    assert read_lines(tmp_path / "absent.jsonl") == []
