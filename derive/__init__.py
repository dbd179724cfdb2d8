"""Symbolic derivation of the thesis model and generation of its numba code.

``python -m derive`` (``make derive``) rewrites generated/.  Never imported by
the runtime (import-linter contract in pyproject.toml).
"""
