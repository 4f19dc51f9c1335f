"""The ``holomj`` command line: thin commands that parse options, call one job, and print.

- :mod:`~holomj.cli.app`: the Typer app, every command registered, :func:`main`
- :mod:`~holomj.cli.options`: the options and arguments several commands take, declared once
- :mod:`~holomj.cli.output`: consoles, JSON output, spinners, errors as exit codes
- one module per command or command group: :mod:`~holomj.cli.compile`,
  :mod:`~holomj.cli.generate` (generate, plan), :mod:`~holomj.cli.validate`,
  :mod:`~holomj.cli.populate`, :mod:`~holomj.cli.render`, :mod:`~holomj.cli.robot`
  (add-robot), :mod:`~holomj.cli.info`, :mod:`~holomj.cli.schema`, :mod:`~holomj.cli.batch`,
  :mod:`~holomj.cli.assets`, :mod:`~holomj.cli.materials`, :mod:`~holomj.cli.layout`

The work is done by the jobs (:mod:`holomj.jobs`, and :mod:`holomj.batch` for ``batch``),
imported inside the commands. Bad input prints one line on stderr and exits with 2; failures
exit with 1. Nothing prompts.
"""

from holomj.cli.app import app, main

__all__ = ["app", "main"]
