"""A small PartNet-Mobility-style cabinet and an MJCF one, written by hand for the import tests.

The cabinet (0.8 m tall, 0.8 m wide, 0.5 m deep, plus a door and a drawer front) has a carcass of
panels, a door on the lower section hinged on its left edge and a drawer above it. The URDF
follows PartNet-Mobility's layout and conventions (see :mod:`asset_pipeline.urdf`): a folder
with ``mobility.urdf``, ``meta.json``, ``semantics.txt`` and ``textured_objs/*.obj``; an empty
``base`` link, a fixed joint with ``rpy="1.5708 0 -1.5708"`` to the carcass link; OBJ meshes in
a Y-up frame with the front towards +Z, normalised (1 unit = :data:`UNIT_M` metres); moving
links whose visual origin is minus their joint origin; the door's hinge written with its axis
up and a range [-1.9, 0] (opening negative, as many PartNet-Mobility doors are).

Design coordinates below are "asset-like" (metres, X front, Y left, Z up, bottom at 0); they are
turned into PartNet-Mobility's mesh frame by :func:`to_mesh`.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np

UNIT_M = 0.8  # PartNet-Mobility models are normalised: 1 unit of the files is 0.8 m here
HEIGHT_M = 0.8
DOOR_RANGE = (-1.9, 0.0)  # radians, as written (opening negative)
DRAWER_TRAVEL_M = 0.35
Box = tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
SHRINK_M = 0.00025  # boxes are written this much smaller on every side: no two share a vertex

CARCASS: list[Box] = [
    ((-0.25, 0.25), (-0.40, 0.40), (0.00, 0.02)),  # bottom
    ((-0.25, 0.25), (-0.40, 0.40), (0.78, 0.80)),  # top
    ((-0.25, 0.25), (-0.40, -0.38), (0.02, 0.78)),  # left side
    ((-0.25, 0.25), (0.38, 0.40), (0.02, 0.78)),  # right side
    ((-0.25, -0.23), (-0.38, 0.38), (0.02, 0.78)),  # back
    ((-0.23, 0.25), (-0.38, 0.38), (0.53, 0.55)),  # rail between door and drawer
]
DOOR: list[Box] = [((0.253, 0.271), (-0.385, 0.385), (0.025, 0.525))]
DOOR_HINGE = (0.253, -0.385)  # x, y of the hinge line (asset-like)
KNOB_CENTRE = (0.286, 0.33, 0.40)
KNOB_SIZE = 0.03
DRAWER: list[Box] = [
    ((0.253, 0.271), (-0.385, 0.385), (0.56, 0.775)),  # front
    ((-0.20, 0.253), (-0.36, 0.36), (0.565, 0.575)),  # bottom
    ((-0.20, 0.253), (-0.36, -0.35), (0.575, 0.72)),  # sides
    ((-0.20, 0.253), (0.35, 0.36), (0.575, 0.72)),
    ((-0.21, -0.20), (-0.36, 0.36), (0.565, 0.72)),  # back
    ((0.271, 0.301), (-0.06, 0.06), (0.65, 0.685)),  # pull
]


def to_mesh(point) -> np.ndarray:
    """Asset-like metres -> PartNet-Mobility mesh units (Y up, front +Z, centred)."""
    x, y, z = point
    return np.array([y, z - HEIGHT_M / 2, x]) / UNIT_M


def box_mesh(boxes: list[Box]) -> str:
    """OBJ text of boxes given in asset-like metres, written in the mesh frame."""
    lines, offset = [], 0
    quads = [(1, 3, 2, 0), (6, 7, 5, 4), (4, 5, 1, 0), (3, 7, 6, 2), (2, 6, 4, 0), (5, 7, 3, 1)]
    for box in boxes:
        (x0, x1), (y0, y1), (z0, z1) = ((lo + SHRINK_M, hi - SHRINK_M) for lo, hi in box)
        corners = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
        lines += ["v {:.6f} {:.6f} {:.6f}".format(*to_mesh(c)) for c in corners]
        for a, b, c, d in quads:
            lines.append(f"f {a + offset + 1} {b + offset + 1} {c + offset + 1}")
            lines.append(f"f {a + offset + 1} {c + offset + 1} {d + offset + 1}")
        offset += 8
    return "\n".join(lines) + "\n"


def _vec(values) -> str:
    return " ".join(f"{float(v):.9g}" for v in values)


def write_partnet_cabinet(folder: Path, knob: Path | None = None) -> Path:
    """Write the cabinet into ``folder`` (PartNet-Mobility layout); return its mobility.urdf.

    ``knob``: an OBJ (with its .mtl and textures beside it) used as the door's knob, scaled and
    centred at the knob's place; a box when None.
    """
    objs = folder / "textured_objs"
    objs.mkdir(parents=True, exist_ok=True)
    (objs / "original-1.obj").write_text(box_mesh(CARCASS))
    (objs / "original-2.obj").write_text(box_mesh(DOOR))
    (objs / "original-3.obj").write_text(box_mesh(DRAWER))
    hinge = to_mesh((*DOOR_HINGE, 0.3))
    slide = to_mesh((0.253, 0.0, 0.6))
    knob_xml = _knob(objs, knob, hinge)
    urdf = f"""<?xml version="1.0" ?>
<robot name="partnet_test_cabinet">
\t<link name="base"/>
\t<link name="link_0">
\t\t<visual name="door-2">
\t\t\t<origin xyz="{_vec(-hinge)}"/>
\t\t\t<geometry><mesh filename="textured_objs/original-2.obj"/></geometry>
\t\t</visual>
{knob_xml}
\t\t<collision>
\t\t\t<origin xyz="{_vec(-hinge)}"/>
\t\t\t<geometry><mesh filename="textured_objs/original-2.obj"/></geometry>
\t\t</collision>
\t</link>
\t<joint name="joint_0" type="revolute">
\t\t<origin xyz="{_vec(hinge)}"/>
\t\t<axis xyz="0 1 0"/>
\t\t<child link="link_0"/>
\t\t<parent link="link_2"/>
\t\t<limit lower="{DOOR_RANGE[0]}" upper="{DOOR_RANGE[1]}"/>
\t</joint>
\t<link name="link_1">
\t\t<visual name="drawer-3">
\t\t\t<origin xyz="{_vec(-slide)}"/>
\t\t\t<geometry><mesh filename="textured_objs/original-3.obj"/></geometry>
\t\t</visual>
\t</link>
\t<joint name="joint_1" type="prismatic">
\t\t<origin xyz="{_vec(slide)}"/>
\t\t<axis xyz="0 0 1"/>
\t\t<child link="link_1"/>
\t\t<parent link="link_2"/>
\t\t<limit lower="0" upper="{DRAWER_TRAVEL_M / UNIT_M:.9g}"/>
\t</joint>
\t<link name="link_2">
\t\t<visual name="frame-1">
\t\t\t<origin xyz="0 0 0"/>
\t\t\t<geometry><mesh filename="textured_objs/original-1.obj"/></geometry>
\t\t</visual>
\t</link>
\t<joint name="joint_2" type="fixed">
\t\t<origin rpy="1.570796326794897 0 -1.570796326794897" xyz="0 0 0"/>
\t\t<child link="link_2"/>
\t\t<parent link="base"/>
\t</joint>
</robot>
"""
    path = folder / "mobility.urdf"
    path.write_text(urdf)
    (folder / "meta.json").write_text(
        json.dumps({"model_cat": "StorageFurniture", "anno_id": "test", "version": "3"})
    )
    (folder / "semantics.txt").write_text(
        "link_0 hinge door\nlink_1 slider drawer\nlink_2 static cabinet_frame\n"
    )
    return path


def _knob(objs: Path, knob: Path | None, hinge: np.ndarray) -> str:
    """The knob's <visual> (in link_0, whose frame sits at ``hinge``)."""
    centre = to_mesh(KNOB_CENTRE)
    if knob is None:
        half = KNOB_SIZE / 2
        (x, y, z) = KNOB_CENTRE
        (objs / "knob.obj").write_text(box_mesh([((x - half, x + half), (y - half, y + half),
                                                   (z - half, z + half))]))  # fmt: skip
        origin, name, scale = -hinge, "knob.obj", ""
    else:
        import trimesh

        for companion in knob.parent.iterdir():
            if companion.is_file() and companion.suffix.lower() in (".obj", ".mtl", ".png"):
                shutil.copy(companion, objs / companion.name)
        mesh = trimesh.load(str(knob), force="mesh", process=False)
        low, high = np.asarray(mesh.bounds)
        factor = KNOB_SIZE / UNIT_M / float(np.max(high - low))
        origin = centre - hinge - factor * (low + high) / 2
        name, scale = knob.name, f' scale="{factor:.9g} {factor:.9g} {factor:.9g}"'
    return (
        f'\t\t<visual name="handle-4">\n\t\t\t<origin xyz="{_vec(origin)}"/>\n'
        f'\t\t\t<geometry><mesh filename="textured_objs/{name}"{scale}/></geometry>\n'
        "\t\t</visual>"
    )


def metric_box_obj(boxes: list[Box]) -> str:
    """OBJ text of boxes in asset-like metres as they are (Z up), for the MJCF model."""
    lines, offset = [], 0
    quads = [(1, 3, 2, 0), (6, 7, 5, 4), (4, 5, 1, 0), (3, 7, 6, 2), (2, 6, 4, 0), (5, 7, 3, 1)]
    for box in boxes:
        (x0, x1), (y0, y1), (z0, z1) = ((lo + SHRINK_M, hi - SHRINK_M) for lo, hi in box)
        corners = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
        lines += ["v {:.6f} {:.6f} {:.6f}".format(*c) for c in corners]
        for a, b, c, d in quads:
            lines.append(f"f {a + offset + 1} {b + offset + 1} {c + offset + 1}")
            lines.append(f"f {a + offset + 1} {c + offset + 1} {d + offset + 1}")
        offset += 8
    return "\n".join(lines) + "\n"


def write_mjcf_cabinet(folder: Path) -> Path:
    """The same cabinet as an MJCF file (meshes in ``meshes/``, angles in degrees, a free joint
    on the carcass, the drawer's pull as a box geom); return its path."""
    meshes = folder / "meshes"
    meshes.mkdir(parents=True, exist_ok=True)
    (meshes / "carcass.obj").write_text(metric_box_obj(CARCASS))
    (meshes / "door.obj").write_text(metric_box_obj(DOOR))
    (meshes / "drawer.obj").write_text(metric_box_obj(DRAWER[:-1]))
    hx, hy = DOOR_HINGE
    path = folder / "cabinet.xml"
    path.write_text(
        f"""<mujoco model="mjcf cabinet">
  <compiler angle="degree" meshdir="meshes"/>
  <asset>
    <mesh name="carcass" file="carcass.obj"/>
    <mesh name="door" file="door.obj"/>
    <mesh name="drawer" file="drawer.obj"/>
    <material name="oak" rgba="0.6 0.45 0.3 1"/>
  </asset>
  <worldbody>
    <body name="cabinet">
      <freejoint/>
      <geom type="mesh" mesh="carcass" material="oak"/>
      <body name="door">
        <joint name="door_hinge" type="hinge" axis="0 0 -1" pos="{hx} {hy} 0.3"
               range="0 100" damping="3"/>
        <geom type="mesh" mesh="door" rgba="0.8 0.8 0.8 1"/>
        <geom type="box" size="0.015 0.015 0.015" pos="0.286 0.33 0.4" rgba="0.2 0.2 0.2 1"/>
      </body>
      <body name="drawer">
        <joint name="drawer_slide" type="slide" axis="1 0 0" range="0 {DRAWER_TRAVEL_M}"/>
        <geom type="mesh" mesh="drawer" material="oak"/>
        <geom type="box" size="0.015 0.06 0.0175" pos="0.286 0 0.6675"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
    )
    return path
