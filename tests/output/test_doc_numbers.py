"""Every figure listed in tools.docnumbers equals, to its printed precision,
what the code computes; a changed doc or a changed model fails here."""
from __future__ import annotations

import pytest

from tools.docnumbers import (
    FIGURES,
    QUANTITIES,
    agrees,
    evaluate,
    locate,
    numbers_in,
    parse,
    read,
)

FAST = [f for f in FIGURES if not f.slow]
SLOW = [f for f in FIGURES if f.slow]


def _id(f):
    return f"{f.doc.split('/')[-1]}:{f.key}"


@pytest.mark.parametrize("fig", FAST, ids=[_id(f) for f in FAST])
def test_printed_figure_is_the_computed_value(fig):
    printed, value, ok = evaluate(fig)
    assert ok, f"{fig.doc} prints {printed} after {fig.at[-1]!r}; the code gives {value:.6g}"


@pytest.mark.slow
@pytest.mark.parametrize("fig", SLOW, ids=[_id(f) for f in SLOW])
def test_printed_simulated_figure_is_the_computed_value(fig):
    printed, value, ok = evaluate(fig)
    assert ok, f"{fig.doc} prints {printed} after {fig.at[-1]!r}; the code gives {value:.6g}"


def test_every_figure_is_found_and_has_a_quantity():
    for fig in FIGURES:
        assert fig.key in QUANTITIES, fig
        locate(read(fig.doc), fig.at)


def test_the_fold_of_the_inverted_branch_is_no_longer_the_hand_typed_88():
    fig = next(f for f in FIGURES if f.key == "fold")
    value = QUANTITIES["fold"]()
    assert not agrees("88", value)
    assert agrees(locate(read(fig.doc), fig.at)[1], value)
    assert "about 88" not in read(fig.doc)


@pytest.mark.parametrize("printed, value, ok", [
    ("80.97", 80.9714, True), ("80.97", 80.9649, False), ("−0.0069", -0.00694, True),
    ("+0.012", -0.012, False), ("3.99e-3", 0.003993, True), ("3.99e-3", 0.00398, False),
    ("10,000", 10000.4, True), ("71", 71.49, True), ("71", 71.51, False)])
def test_agreement_is_to_the_printed_precision(printed, value, ok):
    assert agrees(printed, value) is ok


@pytest.mark.parametrize("printed, value, ok", [
    ("112", 109, True), ("120", 150, True), ("120", 151, False), ("120", 89, False)])
def test_a_stated_relative_tolerance_widens_the_agreement(printed, value, ok):
    assert agrees(printed, value, rtol=0.25) is ok and not agrees(printed, value)


def test_parse_reads_unicode_minus_commas_and_exponents():
    assert parse("−3.99e-3") == (-0.00399, pytest.approx(5e-6))
    assert parse("10,000") == (10000.0, 0.5)


def test_numbers_in_skips_code_page_and_equation_numbers():
    text = "See p. 5-7 and Eqs 3.48.\n```sh\nrun --periods 50\n```\nθ = 0.648 rad, 12 runs\n"
    assert [n for _, n in numbers_in(text)] == ["0.648", "12"]
