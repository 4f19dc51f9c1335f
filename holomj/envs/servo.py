"""Joint position servo for a robot attached without actuators: torques on ``qfrc_applied``.

Robots are attached fixed-base with gravity compensation and no actuators of their own, so the
environment drives them as a critically damped spring per joint toward a target, scaled by the
joint's current diagonal mass (``tau = M_ii (w^2 (target - q) - 2 w qdot)``): the same response
for a heavy shoulder and a light finger, and stable at MuJoCo's time step for ``w`` well below
``1 / timestep``. Nothing in the model is changed, so a reset never needs a recompile.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.errors import InputError

DEFAULT_BANDWIDTH = 30.0  # rad/s
UNLIMITED_SPAN_RAD = math.pi  # a continuous joint's targets stay within this of its home
_MOVABLE = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))


@dataclass
class JointServo:
    """Position targets for a set of hinge/slide joints, applied as torques each step."""

    qpos_adr: np.ndarray
    dof_adr: np.ndarray
    diagonal: np.ndarray  # where each dof's diagonal entry lies in MjData.M (CSR)
    low: np.ndarray
    high: np.ndarray
    home: np.ndarray
    bandwidth: float | np.ndarray = DEFAULT_BANDWIDTH  # rad/s, one for all or one per joint

    @classmethod
    def for_joints(
        cls,
        model: mujoco.MjModel,
        names: Sequence[str],
        bandwidth: float | np.ndarray = DEFAULT_BANDWIDTH,
    ) -> JointServo:
        """A servo for the joints ``names`` of ``model``; their home is ``qpos0``."""
        ids = []
        for name in names:
            joint = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if joint < 0 or int(model.jnt_type[joint]) not in _MOVABLE:
                raise InputError(
                    f"the model has no hinge or slide joint {name!r}",
                    fix="check that objects.json is the scene's own",
                )
            ids.append(joint)
        joints = np.asarray(ids, dtype=int)
        qpos_adr = model.jnt_qposadr[joints].copy()
        home = model.qpos0[qpos_adr].copy()
        limited = model.jnt_limited[joints].astype(bool)
        low = np.where(limited, model.jnt_range[joints, 0], home - UNLIMITED_SPAN_RAD)
        high = np.where(limited, model.jnt_range[joints, 1], home + UNLIMITED_SPAN_RAD)
        dof_adr = model.jnt_dofadr[joints].copy()
        return cls(
            qpos_adr,
            dof_adr,
            (model.M_rowadr + model.M_rownnz - 1)[dof_adr].copy(),
            low,
            high,
            home,
            bandwidth,
        )

    def clip(self, target: np.ndarray) -> np.ndarray:
        """``target`` clipped into the joints' ranges."""
        return np.clip(target, self.low, self.high)

    def apply(self, data: mujoco.MjData, target: np.ndarray) -> None:
        """Set the servo torques toward ``target`` on ``data.qfrc_applied``."""
        w = self.bandwidth
        mass = data.M[self.diagonal]
        error = target - data.qpos[self.qpos_adr]
        data.qfrc_applied[self.dof_adr] = mass * (w * w * error - 2.0 * w * data.qvel[self.dof_adr])
