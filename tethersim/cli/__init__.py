"""The ``tethersim`` command line: one module per command over shared option groups.

:func:`main` (also ``tethersim.cli.main.main``) is the console script; the
commands are ``tethersim/cli/<command>.py``, the shared options
:mod:`tethersim.cli.options`.
"""
from tethersim.cli.main import main

__all__ = ["main"]
