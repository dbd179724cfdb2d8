"""Derivation fixtures shared by the symbolic test modules.

``derive()`` takes about two seconds per model, so each model is derived at
most once per test session, on first use.
"""
from __future__ import annotations

import functools

import pytest


@functools.cache
def _derived(name: str):
    # derive/ (sympy) is imported only by the tests that use these fixtures
    from derive.reference import derived
    return derived(name)


@pytest.fixture(scope="session")
def derived_model():
    """derived_model(name) -> DerivedModel of derive.models.BY_NAME[name] (cached)."""
    return _derived


@pytest.fixture(scope="session")
def kin():
    """The thesis geometry, Eqs 3.10-3.17 (derive.kinematics.planar_kinematics)."""
    from derive.kinematics import planar_kinematics
    return planar_kinematics()


@pytest.fixture(scope="session")
def tether_length_defs(kin):
    """{λ1: Eq 3.41, λ2: Eq 3.42} in the plain state symbols."""
    from derive.pipeline import to_state_symbols
    return {lam: to_state_symbols(d) for lam, d in kin.tether_length_defs.items()}
