"""The catalogue of the default library: every procedural design, in a fixed order."""

from __future__ import annotations

from asset_pipeline.procedural import appliances, furniture, objects, storage
from asset_pipeline.procedural.assembly import AssetDesign


def default_designs() -> list[AssetDesign]:
    """All designs of the default library."""
    return furniture.designs() + storage.designs() + appliances.designs() + objects.designs()
