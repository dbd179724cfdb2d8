"""Start a subprocess as a user's terminal would, for tests that send it Ctrl-C (SIGINT).

A command started in the background by a non-interactive shell (``make test &``, a CI
runner's ``cmd &``) inherits SIGINT *ignored* (POSIX, for asynchronous lists without job
control), and Python then installs no KeyboardInterrupt handler in its children: a real
``tethersim run`` there cannot be interrupted, whatever the CLI does.  The child gets
SIGINT's default disposition back before it execs, as it has under a terminal.
"""
from __future__ import annotations

import signal


def sigint_as_in_a_terminal() -> None:
    """``preexec_fn`` of subprocess.Popen: SIGINT's default disposition, unblocked."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, [signal.SIGINT])
