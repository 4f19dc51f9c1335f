"""Part roles: what a part of a procedural asset is (its legs, its top, its handles, its shade).

A generator tags the parts a request may name ("a table with metal legs", "a cabinet with brass
handles") by wrapping them: :func:`tagged` gives every part of a list one role, and
:func:`fronts` tags what :func:`~asset_pipeline.procedural.kit.drawer_fronts` returns (fronts
and handles alternate there). A tagged part behaves exactly as the part it wraps (same mesh,
colliders, bounds, surfaces and material), so tagging never changes an asset's files; only
:mod:`asset_pipeline.procedural.attributes` reads the roles, to give the colour or material a
request names to those parts only.

Roles are the words of :data:`ROLES`; untagged parts have none.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Any

from asset_pipeline.procedural.parts import (
    Collider,
    Mesh,
    Part,
    RecipeMaterial,
    RecipeSurface,
    Vec3,
)

ROLES = (
    "top",
    "legs",
    "base",
    "pole",
    "frame",
    "body",
    "seat",
    "cushions",
    "back",
    "arms",
    "headboard",
    "bedding",
    "doors",
    "drawers",
    "handles",
    "shade",
    "shelves",
)
"""Every role a part may carry, in the order reports list them."""


@dataclass(frozen=True)
class Tagged:
    """A part with a role; everything else is the wrapped part's."""

    part: Part
    role: str

    def __post_init__(self) -> None:
        if self.role not in ROLES:
            raise ValueError(f"unknown part role {self.role!r} (known: {', '.join(ROLES)})")

    @property
    def material(self) -> RecipeMaterial:
        """The wrapped part's material."""
        return self.part.material

    def mesh(self) -> Mesh | None:
        """The wrapped part's visual mesh."""
        return self.part.mesh()

    def colliders(self) -> list[Collider]:
        """The wrapped part's colliders."""
        return self.part.colliders()

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        """The wrapped part's bounds."""
        return self.part.bounds()

    def surfaces(self) -> list[RecipeSurface]:
        """The wrapped part's support surfaces."""
        return self.part.surfaces()

    def translated(self, offset: Vec3) -> Tagged:
        """This part moved by ``offset``, still tagged."""
        return Tagged(self.part.translated(offset), self.role)

    def __getattr__(self, name: str) -> Any:
        # Anything else a part offers (now or later) is the wrapped part's.
        if name in ("part", "role") or name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.part, name)


def tagged(role: str, parts: Iterable[Part]) -> list[Part]:
    """``parts`` with role ``role`` (a part already tagged gets the new role)."""
    return [Tagged(untagged(p), role) for p in parts]


def fronts(parts: Sequence[Part], style: str = "bar") -> list[Part]:
    """What ``drawer_fronts(..., style=style)`` returned, tagged: every front ``doors`` (style
    ``door``) or ``drawers`` (``bar``, ``knob``), every handle ``handles``."""
    if len(parts) % 2:
        raise ValueError("drawer fronts come in (front, handle) pairs")
    front_role = "doors" if style == "door" else "drawers"
    return [
        Tagged(untagged(p), front_role if k % 2 == 0 else "handles") for k, p in enumerate(parts)
    ]


def role_of(part: Part) -> str | None:
    """The role of ``part``, or None when it has none."""
    return part.role if isinstance(part, Tagged) else None


def untagged(part: Part) -> Part:
    """The part without its role."""
    while isinstance(part, Tagged):
        part = part.part
    return part


def with_material(part: Part, material: RecipeMaterial) -> Part:
    """``part`` made of ``material`` (its role kept)."""
    if isinstance(part, Tagged):
        return Tagged(with_material(part.part, material), part.role)
    return replace(part, material=material)


def roles_in(parts: Iterable[Part]) -> set[str]:
    """The roles the parts carry."""
    return {r for r in (role_of(p) for p in parts) if r is not None}
