"""A short simulation that reports every MuJoCo warning a model raises."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco


@dataclass(frozen=True)
class SmokeResult:
    """What a short run of the simulator saw."""

    seconds: float
    steps: int
    warnings: dict[str, int]

    @property
    def ok(self) -> bool:
        """True when MuJoCo raised no warning at all."""
        return not self.warnings


def warning_counts(data: mujoco.MjData) -> dict[str, int]:
    """Non-zero warning counters of ``data`` by name (e.g. ``mjWARN_CONTACTFULL``)."""
    return {
        mujoco.mjtWarning(i).name: int(data.warning[i].number)
        for i in range(len(data.warning))
        if data.warning[i].number > 0
    }


def simulate(model: mujoco.MjModel, seconds: float = 1.0) -> SmokeResult:
    """Step ``model`` from its initial state for ``seconds`` of simulated time."""
    data = mujoco.MjData(model)
    steps = max(1, round(seconds / model.opt.timestep))
    mujoco.mj_forward(model, data)
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return SmokeResult(
        seconds=steps * model.opt.timestep, steps=steps, warnings=warning_counts(data)
    )
