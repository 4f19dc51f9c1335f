"""The log of a generate run: one line per event, per-stage wall times, live progress."""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

Listener = Callable[[str, str], None]  # (stage, message)


@dataclass
class StageLog:
    """Collects messages and stage timings; ``listener`` sees each message as it happens."""

    listener: Listener | None = None
    entries: list[dict[str, Any]] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    _start: float = field(default_factory=time.perf_counter)

    def info(self, stage: str, message: str) -> None:
        """Record ``message`` under ``stage``."""
        self.entries.append(
            {"t_s": round(time.perf_counter() - self._start, 3), "stage": stage, "message": message}
        )
        if self.listener is not None:
            self.listener(stage, message)

    @contextlib.contextmanager
    def stage(self, name: str) -> Iterator[None]:
        """Time the block as stage ``name`` (times add up when a stage runs more than once)."""
        self.info(name, "started")
        start = time.perf_counter()
        try:
            yield
        except BaseException as err:
            self.info(name, f"failed: {type(err).__name__}: {err}".splitlines()[0])
            raise
        finally:
            self.timings[name] = round(self.timings.get(name, 0.0) + time.perf_counter() - start, 4)
        self.info(name, f"done in {self.timings[name]:.2f} s")

    def text(self) -> str:
        """The log as text, one ``[  1.23 s] stage: message`` line per entry."""
        return "".join(f"[{e['t_s']:8.2f} s] {e['stage']}: {e['message']}\n" for e in self.entries)
