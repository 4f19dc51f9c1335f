"""A URDF model as the kinematic tree of an articulated asset (its links' meshes loaded), with
what PartNet-Mobility adds beside the file (meta.json, semantics.txt)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

from asset_pipeline.kinematics import (
    JointInfo,
    JointKind,
    Kinematics,
    LinkGeometry,
    coloured,
    primitive,
    transformed,
)
from asset_pipeline.load import LoadedFile, load_file
from asset_pipeline.urdf import (
    Geometry,
    UrdfModel,
    read_urdf,
)
from holomj.errors import FormatError


def partnet_meta(path: Path) -> dict:
    """``meta.json`` beside a PartNet-Mobility URDF (empty when absent or unreadable)."""
    meta = Path(path).parent / "meta.json"
    try:
        data = json.loads(meta.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def partnet_labels(path: Path) -> dict[str, str]:
    """Link -> semantic label from ``semantics.txt`` (``link_0 hinge door``), if present."""
    labels = {}
    try:
        text = (Path(path).parent / "semantics.txt").read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return {}
    for line in text.splitlines():
        words = line.split()
        if len(words) >= 2:
            labels[words[0]] = words[-1].lower()
    return labels


def is_partnet(model: UrdfModel) -> bool:
    """Whether the URDF looks like PartNet-Mobility's (its meta.json or its robot name)."""
    return bool(partnet_meta(model.path).get("model_cat")) or model.name.startswith("partnet_")


def asset_id_hint(path: Path) -> str | None:
    """An id for a PartNet-Mobility ``mobility.urdf``: ``<model_cat>_<folder>`` (e.g.
    ``storagefurniture_45612``); None for other files."""
    path = Path(path)
    if path.suffix.lower() != ".urdf" or not path.stem.lower().startswith("mobility"):
        return None
    category = str(partnet_meta(path).get("model_cat") or "partnet")
    folder = re.sub(r"[^A-Za-z0-9_.\-]+", "_", path.parent.name).strip("_.-")
    text = re.sub(r"[^a-z0-9_]+", "_", category.lower()).strip("_") or "partnet"
    return f"{text}_{folder}" if folder else text


_JOINT_KINDS: dict[str, JointKind] = {
    "revolute": "hinge",
    "continuous": "hinge",
    "prismatic": "slide",
    "fixed": "fixed",
}


def load_urdf(path: Path | str, max_faces: int = 2_000_000) -> Kinematics:
    """The kinematics of the URDF at ``path``: its meshes loaded and placed at joint values 0."""
    model = read_urdf(path)
    frames = {root: np.eye(4) for root in model.roots}
    joints = []
    for joint in model.joints:
        at = frames[joint.parent] @ joint.origin
        frames[joint.child] = at
        joints.append(
            JointInfo(
                name=joint.name,
                type=_JOINT_KINDS[joint.type],
                parent=joint.parent,
                child=joint.child,
                axis=at[:3, :3] @ joint.axis,
                anchor=at[:3, 3].copy(),
                range=joint.limit,
                damping=joint.damping,
                frictionloss=joint.friction,
                where=joint.where,
            )
        )
    warnings = list(model.warnings)
    loaded: dict[Path, LoadedFile] = {}
    links: dict[str, LinkGeometry] = {}
    faces = 0
    for name in [*model.roots, *(j.child for j in model.joints)]:
        link = model.links[name]
        parts = []
        for geometry in link.geometry:
            placed = frames[name] @ geometry.origin
            if geometry.mesh is None:
                parts.append(
                    coloured(
                        transformed(primitive(geometry.kind, geometry.size), placed), geometry.rgba
                    )
                )
                continue
            mesh = loaded.get(geometry.mesh)
            if mesh is None:
                mesh = _load_mesh(geometry, model.path, max_faces - faces)
                loaded[geometry.mesh] = mesh
                warnings += [f"{geometry.mesh.name}: {w}" for w in mesh.warnings]
            scale = np.diag([*geometry.scale, 1.0])
            for part in mesh.parts:
                parts.append(coloured(transformed(part, placed @ scale), geometry.rgba))
                faces += len(part.faces)
        if faces > max_faces:
            raise FormatError(
                f"the meshes have more than {max_faces} faces",
                where=str(model.path),
                fix="decimate them first or raise max_faces",
            )
        links[name] = LinkGeometry(name, parts, link.where)
    meta = partnet_meta(model.path)
    return Kinematics(
        format="urdf",
        name=model.name,
        links=links,
        joints=joints,
        up_axis="z",
        labels=partnet_labels(model.path),
        category=str(meta["model_cat"]) if meta.get("model_cat") else None,
        partnet=is_partnet(model),
        warnings=warnings,
    )


def _load_mesh(geometry: Geometry, urdf: Path, max_faces: int) -> LoadedFile:
    assert geometry.mesh is not None
    try:
        return load_file(geometry.mesh, max(1, max_faces))
    except FormatError as err:
        raise FormatError(
            f"{geometry.where}: mesh {geometry.mesh.name}: {err.what}", where=str(urdf), fix=err.fix
        ) from None
