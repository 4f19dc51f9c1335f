"""Decor categories: flat things under furniture (rugs) that are static, visual only and take no
part in the floor layout (see :mod:`holomj.layout.rugs`)."""

from __future__ import annotations

DECOR_CATEGORIES = frozenset({"rug"})
# Geom group of a decor object's colliders: they give it its mass but take no part in contacts,
# and the physics audit (which treats group 3 as colliders) leaves them out.
DECOR_GROUP = 4
