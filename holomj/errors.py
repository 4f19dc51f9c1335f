"""The one error hierarchy of holomj.

Every error says *what* was wrong, *where* (a file, a field path such as ``rooms[2].polygon``,
an object id) and, when we know it, *what to do*. The CLI prints ``str(error)`` on one line and
exits with ``error.exit_code``: 2 for bad input, 1 for a failure of ours or of the simulator.
"""

from __future__ import annotations

from collections.abc import Iterable


class HolomjError(Exception):
    """Base class: a one-line message built from what, where and fix."""

    exit_code = 1

    def __init__(self, what: str, *, where: str | None = None, fix: str | None = None) -> None:
        self.what = what
        self.where = where
        self.fix = fix
        super().__init__(self.one_line())

    def one_line(self) -> str:
        """The message as the CLI prints it: ``where: what (fix)`` on a single line."""
        text = f"{self.where}: {self.what}" if self.where else self.what
        if self.fix:
            text = f"{text} ({self.fix})"
        return " ".join(text.split())

    def located(self, where: str) -> HolomjError:
        """Return a copy of this error whose location is prefixed with ``where``."""
        joined = f"{where}: {self.where}" if self.where else where
        return type(self)(self.what, where=joined, fix=self.fix)


class InputError(HolomjError):
    """The user's input is wrong: a file, a field, an option. Exit code 2."""

    exit_code = 2


class SpecError(InputError):
    """A scene, asset or library description breaks the schema or a geometric rule."""


class FormatError(InputError):
    """An input file cannot be read or is not of a format we know."""


class AssetNotFoundError(InputError):
    """An object refers to an asset that the library does not hold."""


class OutputExistsError(InputError):
    """The output folder exists and ``--overwrite`` was not given."""


class CompileError(HolomjError):
    """MuJoCo refused the model we built (a bug of ours or a broken asset). Exit code 1."""


class ExportError(HolomjError):
    """Writing the output package failed. Exit code 1."""


def closest_names(name: str, candidates: Iterable[str], limit: int = 5) -> str:
    """A short ``did you mean`` list for error messages (empty string if nothing is close)."""
    import difflib

    matches = difflib.get_close_matches(name, sorted(set(candidates)), n=limit, cutoff=0.5)
    return ", ".join(matches)
