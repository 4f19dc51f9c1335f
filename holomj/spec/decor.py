"""Decor categories: flat things under furniture (rugs) that are static, visual only and take no
part in the floor layout (see :mod:`holomj.layout.rugs`); and light fixtures, which carry the
MuJoCo light of their room (see :func:`holomj.mjcf.views.add_lights`)."""

from __future__ import annotations

DECOR_CATEGORIES = frozenset({"rug"})
# Geom group of a decor object's colliders: they give it its mass but take no part in contacts,
# and the physics audit (which treats group 3 as colliders) leaves them out.
DECOR_GROUP = 4

# Ceiling fixtures that give light: a room with one is lit from it, not from its centre.
LIGHT_FIXTURE_CATEGORIES = frozenset(
    {"pendant_light", "chandelier", "ceiling_light", "ceiling_fan", "paper_lantern",
     "fluorescent_light", "track_light"}
)  # fmt: skip
LIGHT_BELOW_FIXTURE_M = 0.08  # the light sits this far under the fixture's lowest point
