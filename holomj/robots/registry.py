"""Which robots can be attached: an MJCF path, or a name resolved from installed packages.

Named robots are read from the data files of installed packages, never imported (importing
``dm_robotics.panda`` would pull in the whole dm-robotics stack):

- ``panda``: Franka Emika Panda arm with its hand, from ``dm-robotics-panda`` (holomj only
  reads its MJCF and meshes: install it with ``pip install dm-robotics-panda --no-deps``).
- ``jaco``: Kinova Jaco arm with its three-finger hand, from dm_control's Kinova assets.

A path names any MJCF file; its home pose is its keyframe ``home`` when it has one, else its
initial pose with every joint clamped into its range.
"""

from __future__ import annotations

import importlib.metadata
import math
from dataclasses import dataclass, field
from pathlib import Path

from holomj.errors import InputError

PANDA_PIP = "pip install dm-robotics-panda --no-deps"


@dataclass(frozen=True)
class HandMount:
    """A second MJCF (a gripper) attached to a site of the arm, rotated about that site's z."""

    xml: Path
    site: str
    yaw_deg: float = 0.0


@dataclass(frozen=True)
class RobotSource:
    """Where a robot's MJCF comes from and how it stands when the scene starts.

    ``home`` maps joint names (of the arm, or ``hand/<joint>`` of the hand) to positions;
    joints it does not name start at their initial position clamped into their range.
    """

    name: str
    xml: Path
    description: str
    hand: HandMount | None = None
    home: dict[str, float] = field(default_factory=dict)
    package: str | None = None  # the installed distribution it was found in
    given: str | None = None  # the spec as the user wrote it, when it differs from ``name``

    @property
    def spec(self) -> str:
        """How a user names it: the registry name, or the path for a file."""
        return self.given or self.name


@dataclass(frozen=True)
class _Named:
    """A registry entry: a distribution and where its files lie inside it."""

    name: str
    distribution: str
    install: str
    description: str
    arm: str
    hand: str | None = None
    hand_site: str | None = None
    hand_yaw_deg: float = 0.0
    home: tuple[tuple[str, float], ...] = ()


# The Panda's "ready" pose (franka_ros); the hand is turned -45° about the flange as on the real
# robot. Jaco: Kinova's home pose, in the convention of dm_control's model (joint ranges match).
_NAMED = (
    _Named(
        name="panda",
        distribution="dm-robotics-panda",
        install=PANDA_PIP,
        description="Franka Emika Panda arm with hand (dm-robotics-panda)",
        arm="dm_robotics/panda/assets/panda/panda.xml",
        hand="dm_robotics/panda/assets/panda/panda_hand.xml",
        hand_site="wrist_site",
        hand_yaw_deg=-45.0,
        home=(
            ("panda_joint1", 0.0),
            ("panda_joint2", -math.pi / 4),
            ("panda_joint3", 0.0),
            ("panda_joint4", -3 * math.pi / 4),
            ("panda_joint5", 0.0),
            ("panda_joint6", math.pi / 2),
            ("panda_joint7", math.pi / 4),
        ),
    ),
    _Named(
        name="jaco",
        distribution="dm-control",
        install="pip install dm-control",
        description="Kinova Jaco arm with three-finger hand (dm_control)",
        arm="dm_control/third_party/kinova/jaco_arm.xml",
        hand="dm_control/third_party/kinova/jaco_hand.xml",
        hand_site="wristsite",
        home=(
            ("joint_1", 0.0),
            ("joint_2", 2.9248),
            ("joint_3", 1.002),
            ("joint_4", 4.2031),
            ("joint_5", 1.4458),
            ("joint_6", 1.3233),
        ),
    ),
)


def _package_file(distribution: str, relative: str) -> Path | None:
    """A data file of an installed distribution (without importing it), or None."""
    try:
        dist = importlib.metadata.distribution(distribution)
    except importlib.metadata.PackageNotFoundError:
        return None
    path = Path(str(dist.locate_file(relative)))
    return path if path.is_file() else None


def _resolve_named(entry: _Named) -> RobotSource | None:
    arm = _package_file(entry.distribution, entry.arm)
    if arm is None:
        return None
    hand = None
    if entry.hand is not None and entry.hand_site is not None:
        hand_xml = _package_file(entry.distribution, entry.hand)
        if hand_xml is None:
            return None
        hand = HandMount(hand_xml, entry.hand_site, entry.hand_yaw_deg)
    return RobotSource(
        name=entry.name,
        xml=arm,
        description=entry.description,
        hand=hand,
        home=dict(entry.home),
        package=entry.distribution,
    )


def available_robots() -> dict[str, str]:
    """Every registry name with a note: its description, or how to install what it needs."""
    notes = {}
    for entry in _NAMED:
        if _resolve_named(entry) is not None:
            notes[entry.name] = entry.description
        else:
            notes[entry.name] = f"not installed: {entry.install}"
    return notes


def installed_robots() -> list[str]:
    """Registry names whose files are installed."""
    return [entry.name for entry in _NAMED if _resolve_named(entry) is not None]


def resolve_robot(spec: str) -> RobotSource:
    """The robot ``spec`` names: a registry name (see :func:`available_robots`) or an MJCF path.

    Raises :class:`~holomj.errors.InputError` naming the available robots when it is neither.
    """
    spec = spec.strip()
    for entry in _NAMED:
        if spec == entry.name:
            source = _resolve_named(entry)
            if source is None:
                raise InputError(
                    f"robot {spec!r} needs the {entry.distribution} package, which is not "
                    "installed",
                    where="--robot",
                    fix=f"run '{entry.install}', or use one of: {_listing()}",
                )
            return source
    path = Path(spec).expanduser()
    if path.suffix.lower() == ".xml" or path.exists():
        if not path.is_file():
            raise InputError(
                "robot MJCF file not found", where=f"--robot {spec}", fix=f"use {_listing()}"
            )
        return RobotSource(
            name=path.stem, xml=path.resolve(), description=f"MJCF file {path}", given=spec
        )
    raise InputError(
        f"unknown robot {spec!r}",
        where="--robot",
        fix=f"give an MJCF file path or one of: {_listing()}",
    )


def _listing() -> str:
    installed = installed_robots()
    missing = [e.name for e in _NAMED if e.name not in installed]
    text = ", ".join(installed) if installed else "(no named robot installed)"
    if missing:
        text += "; not installed: " + ", ".join(
            f"{e.name} ({e.install})" for e in _NAMED if e.name in missing
        )
    return text
