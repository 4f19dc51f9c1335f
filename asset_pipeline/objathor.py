"""Import an objathor asset directory (the Objaverse assets Holodeck houses name) into a library.

Holodeck houses name Objaverse assets by their uid (32 hex digits) in ``objects[].assetId``.
Users of Holodeck keep those assets in an *objathor* directory; this module reads one and turns
each uid into a holomj asset **whose id is the uid**, so ``holomj compile house.json --library
LIB`` finds it (the ProcTHOR/Holodeck importer uses an ``assetId`` the library holds as is).

The layout (learnt from the public ``allenai/objathor`` package, ``objathor/dataset/``,
``objathor/asset_conversion/`` and ``objathor/annotation/``, and from ``allenai/Holodeck``'s
``ai2holodeck/constants.py`` and ``generation/utils.py``; this reader is our own)
------------------------------------------------------------------------------------------

``DIR`` is either a dataset version folder or its ``assets/`` folder::

    DIR/annotations.json.gz          all annotations, {uid: annotation} (gzip JSON; plain JSON
                                     is read too); absent when DIR is the assets folder itself,
                                     then DIR/../annotations.json.gz is used when DIR is named
                                     ``assets``
    DIR/assets/<uid>/                one folder per asset (or DIR/<uid>/):
        <uid>.pkl.gz                 the mesh dict, a gzip-compressed pickle (protocol 4); the
                                     conversion pipeline may also write <uid>.msgpack.gz,
                                     <uid>.msgpack, <uid>.json or <uid>.json.gz with the same dict
        albedo.jpg                   base colour (``albedoTexturePath``; .png before compression)
        normal.jpg, emission.jpg,    normal map, emission, metallic (R) / smoothness (B)
        metallic_smoothness.jpg      (not used: a MuJoCo material shows the colour texture only)
        annotations.json.gz          this asset's annotation (left out of the released tarball;
                                     used when the global file lacks the uid)
        thor_metadata.json           THOR's metadata (merged into the global annotations as
                                     ``thor_metadata``; left out of the tarball)
        <uid>.obj                    the converted mesh as OBJ, same frame as the dict (kept only
                                     when the conversion did not delete it); <uid>.glb, if
                                     present, is the original Objaverse glTF
        thor_renders/                THOR renders (not used)

Per-uid tar archives (``<uid>.tar``) are not read: extract them first.

The mesh dict (keys we read; the others, ``visibilityPoints``, ``physicalProperties``,
``annotations``, ``metallicSmoothnessTexturePath``, are ignored):

* ``vertices``: list of ``{"x", "y", "z"}`` (metres), one per face corner (Blender loops, so
  unwelded); ``triangles``: flat list of indices, three per triangle; ``uvs``: list of
  ``{"x", "y"}`` per vertex, origin bottom-left (Blender/Unity, the OBJ ``vt`` convention);
  ``normals``: per-vertex normals (not used; MuJoCo computes its own). Arrays of shape (N, 3)
  / (N, 2) / (M, 3) are accepted as well.
* ``colliders`` (optional): list of convex pieces ``{"vertices": [{x, y, z}...], "triangles":
  [flat indices]}`` from V-HACD, in the same frame as ``vertices``.
* ``yRotOffset`` (optional, degrees): a turn about the up axis THOR applies to the mesh when it
  creates the asset (objathor chooses it, within ±45°, to minimise the axis-aligned box; its
  sign is Unity's, clockwise seen from above). THOR's bounding box, and so every Holodeck
  footprint, includes it, so we apply it too.
* ``albedoTexturePath`` etc.: texture paths, relative to the asset folder or absolute (of the
  machine that converted it): only the file name is used, looked up in the asset folder.
* ``receptacleCandidate`` (optional bool): whether THOR may make the asset a receptacle.

Frame of the dict: THOR/Unity, **Y up**, left-handed, metres, already scaled to real size
(objathor scales in Blender to the annotation's ``scale``) and turned to its canonical pose
(``pose_z_rot_angle``), bottom at y = 0 and footprint centred on x = z = 0. The asset's
**front faces +z** (like every ProcTHOR asset at rotation 0). Triangles wind counter-clockwise
about the outward normal in the stored numbers (objathor mirrors x in Blender and flips the
normals back before export); the repair step re-orients closed bodies either way.

Annotations (fields read; all optional, wrong types are ignored with a warning): ``uid``,
``category`` (free text: "coffee table", "eames chair"), ``description`` (else
``description_auto``, else ``description_long``), ``height`` / ``width`` / ``depth`` (cm),
``mass`` (kg), ``receptacle`` (bool), ``onFloor`` / ``onWall`` / ``onObject`` / ``onCeiling``
(bools), ``synset`` (WordNet, e.g. ``straight_chair.n.01``), ``scale`` (metres: the height when
``z_axis_scale``, else the largest side) and ``pose_z_rot_angle`` (radians; both already applied
to the mesh dict, used only for a ``.glb``), ``license_info`` (``license``, ``uri``,
``creator_display_name``), and ``thor_metadata.assetMetadata.boundingBox`` (Unity axes, metres,
as ``{"min", "max"}``, ``{"x", "y", "z"}`` or ``{"size"}``; Holodeck's own database puts
``assetMetadata`` and ``annotations`` at the top level of an entry: read too).

Conversion
----------

A point ``v`` of the dict becomes ``a = M Ry(yRotOffset) v`` in the asset frame, with
``M = [[0, 0, 1], [-1, 0, 0], [0, 1, 0]]`` (asset ``+X`` = Unity ``+z``, the front; ``+Y`` =
Unity ``-x``; ``+Z`` = Unity ``+y``, up) and ``Ry`` Unity's turn about y. ``M`` is a reflection
(Unity is left-handed), so triangles are re-wound. This is the one choice that agrees with
:mod:`holomj.importers.frames`: an object at Unity rotation ``y`` is placed at holomj yaw
``90 - y``, and its mesh then lands where THOR draws it. The import itself (normalisation, repair,
colliders, surfaces, metadata, caching) is :mod:`asset_pipeline.objathor_import`.

An original ``.glb`` (glTF: Y up, right-handed, arbitrary units) is canonicalised as objathor
does it: Y-up to Z-up, ``pose_z_rot_angle`` about Z, scaled so its height (``z_axis_scale``) or
largest side is ``scale`` metres, then its front (Blender ``-Y``) turned to ``+X``.

Safety: pickles are loaded with a restricted unpickler that only builds plain containers
(dict, list, tuple, set), numbers, strings and numpy arrays/scalars: a pickle naming any other
class or function (the way pickles run code) is rejected with an error naming the file. A bad
file (corrupt gzip or pickle, wrong shapes, indices out of range) is a one-line
:class:`~holomj.errors.FormatError` naming it; missing optional files (texture, colliders,
annotations) are warnings.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from asset_pipeline.objathor_annotation import (
    ObjathorAnnotation,
    parse_annotation,
    read_annotation_file,
)
from asset_pipeline.objathor_files import ANNOTATION_FILES, ID_PATTERN, load_pickle
from asset_pipeline.objathor_mesh import (
    ObjathorMesh,
    find_mesh_file,
    gltf_to_asset,
    read_mesh,
    unity_to_asset,
    unity_yaw,
)
from holomj.errors import FormatError, InputError, closest_names

__all__ = [
    "ObjathorAnnotation",
    "ObjathorJob",
    "ObjathorMesh",
    "find_mesh_file",
    "gltf_to_asset",
    "load_pickle",
    "parse_annotation",
    "plan_objathor",
    "read_annotation_file",
    "read_mesh",
    "unity_to_asset",
    "unity_yaw",
]


# -- a directory of assets -------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorJob:
    """One uid to import: its folder, mesh file and raw annotation (None when absent)."""

    uid: str
    folder: Path
    mesh_file: Path | None
    annotation: Any = None
    annotation_source: str | None = None
    id_note: str | None = None


def _assets_dir(root: Path) -> Path:
    return root / "assets" if (root / "assets").is_dir() else root


def _annotation_files(root: Path, assets: Path) -> list[Path]:
    """Global annotation files: in ``root``, or beside an ``assets`` folder given as DIR."""
    folders = [root]
    if assets == root and root.name == "assets":
        folders.append(root.parent)
    for folder in folders:
        found = [folder / n for n in ANNOTATION_FILES if (folder / n).is_file()]
        if found:
            return found[:1]
    return []


def plan_objathor(directory: Path | str, uids: Sequence[str] | None = None) -> list[ObjathorJob]:
    """The jobs for the assets of an objathor ``directory`` (only ``uids`` when given).

    Checks everything a job needs up front: the directory exists and holds asset folders,
    every asked uid has a folder, the global annotation file (if any) parses. Raises
    :class:`InputError` / :class:`FormatError` before anything is written.
    """
    root = Path(directory)
    if not root.is_dir():
        raise InputError("not a folder", where=str(root), fix="give the objathor asset folder")
    assets = _assets_dir(root)
    annotations: dict[str, Any] = {}
    sources: dict[str, str] = {}
    for path in _annotation_files(root, assets):
        for uid, entry in read_annotation_file(path).items():
            annotations[uid] = entry
            sources[uid] = str(path)
    folders = {
        p.name: p
        for p in sorted(assets.iterdir())
        if p.is_dir() and ID_PATTERN.match(p.name) and find_mesh_file(p, p.name) is not None
    }
    if uids:
        wanted = list(dict.fromkeys(u.strip() for u in uids if u.strip()))
        missing = [u for u in wanted if not (assets / u).is_dir()]
        if missing:
            near = closest_names(missing[0], folders)
            raise InputError(
                f"no asset folder for uid {missing[0]!r}",
                where=str(assets),
                fix=f"did you mean {near}?" if near else "see the uid folders of the directory",
            )
    else:
        wanted = sorted(folders)
        if not wanted:
            raise InputError(
                "no objathor assets found (no <uid>/<uid>.pkl.gz, .msgpack, .json, .obj or .glb)",
                where=str(assets),
                fix="give the dataset folder (with assets/) or its assets folder",
            )
    jobs = []
    for uid in wanted:
        folder = assets / uid
        annotation, source = annotations.get(uid), sources.get(uid)
        local = _local_annotation(folder)
        if local is not None:
            if annotation is None:
                annotation, source = local
            elif isinstance(annotation, dict) and isinstance(local[0], dict):
                annotation = {**local[0], **annotation}
                source = f"{source} + {local[1]}"
        jobs.append(
            ObjathorJob(
                uid=uid,
                folder=folder,
                mesh_file=find_mesh_file(folder, uid),
                annotation=annotation,
                annotation_source=source,
            )
        )
    return jobs


def _local_annotation(folder: Path) -> tuple[Any, str] | None:
    """The per-asset annotation file's entry, or None (a bad file is the job's error later)."""
    for name in ANNOTATION_FILES:
        path = folder / name
        if path.is_file():
            try:
                entries = read_annotation_file(path)
            except FormatError as err:
                return {"__error__": err.one_line()}, str(path)
            entry = entries.get(folder.name)
            if entry is None and len(entries) == 1:
                entry = next(iter(entries.values()))
            return entry, str(path)
    return None
