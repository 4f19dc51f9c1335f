"""USD prim writers that know no physics: poses, triangle meshes, preview-surface materials and
lights. Used by :mod:`holomj.formats.usd` (the stage) and :mod:`holomj.formats.usd_physics`.

Needs ``usd-core`` (the ``export`` extra); callers check with :func:`holomj.formats.usd.load_pxr`.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from holomj.formats.model_geometry import Look, Triangles, matrix_to_quat_wxyz, quat_from_to

_UNSAFE = re.compile(r"[^A-Za-z0-9_]")


def valid_name(name: str) -> str:
    """``name`` as a USD prim name (letters, digits, underscores; not starting with a digit)."""
    text = _UNSAFE.sub("_", name) or "_"
    return f"_{text}" if text[0].isdigit() else text


def string_attr(prim: Any, name: str, value: str) -> None:
    """A string attribute ``name`` on ``prim``."""
    prim.CreateAttribute(name, sdf().ValueTypeNames.String).Set(value)


def sdf() -> Any:
    """The ``pxr.Sdf`` module."""
    from pxr import Sdf

    return Sdf


def quatf(wxyz: np.ndarray) -> Any:
    """A single-precision USD quaternion from MuJoCo's (w, x, y, z) order."""
    from pxr import Gf

    return Gf.Quatf(float(wxyz[0]), float(wxyz[1]), float(wxyz[2]), float(wxyz[3]))


def rotation_from_quat(wxyz: np.ndarray) -> np.ndarray:
    """The 3x3 rotation matrix of a (w, x, y, z) quaternion."""
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.asarray(wxyz, dtype=float))
    return matrix.reshape(3, 3)


def set_pose(
    xformable: Any, pos: np.ndarray, rot: np.ndarray, scale: list[float] | None = None
) -> None:
    """Translate, orient (and scale) ops on ``xformable``, in double precision."""
    from pxr import Gf, UsdGeom

    xform = UsdGeom.Xformable(xformable)
    xform.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*(float(v) for v in pos)))
    quat = matrix_to_quat_wxyz(rot)
    xform.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(
        Gf.Quatd(float(quat[0]), float(quat[1]), float(quat[2]), float(quat[3]))
    )
    if scale is not None:
        xform.AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*scale))


def mesh_prim(stage: Any, path: str, tris: Triangles) -> Any:
    """A double-sided triangle mesh at ``path`` with per-vertex normals and its extent."""
    from pxr import UsdGeom, Vt

    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(tris.positions)))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(tris.faces), 3, np.int32)))
    mesh.CreateFaceVertexIndicesAttr(
        Vt.IntArray.FromNumpy(np.ascontiguousarray(tris.faces.reshape(-1).astype(np.int32)))
    )
    mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(tris.normals)))
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDoubleSidedAttr(True)
    low, high = tris.positions.min(axis=0), tris.positions.max(axis=0)
    mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(np.vstack([low, high]).astype(np.float32)))
    return mesh


def visual_mesh(
    stage: Any, path: str, tris: Triangles, look: Look, pos: np.ndarray, rot: np.ndarray
) -> Any:
    """A visual mesh at ``path`` posed at ``pos``/``rot``: texture coordinates (``st``) when
    ``tris`` has them and ``look`` a texture, the look's display colour and opacity."""
    from pxr import UsdGeom, Vt

    mesh = mesh_prim(stage, path, tris)
    set_pose(mesh, pos, rot)
    if look.texture is not None and tris.uvs is not None:
        primvar = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(
            "st", sdf().ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex
        )
        uv = tris.uvs.astype(float).copy()
        uv[:, 1] = 1.0 - uv[:, 1]  # USD's st has t = 0 at the image's bottom row
        primvar.Set(Vt.Vec2fArray.FromNumpy(uv.astype(np.float32)))
    mesh.CreateDisplayColorAttr([tuple(float(c) for c in look.linear_rgba[:3])])
    if look.rgba[3] < 1.0:
        mesh.CreateDisplayOpacityAttr([float(look.rgba[3])])
    return mesh


def preview_material(stage: Any, path: str, look: Look, texture_file: str | None) -> Any:
    """A UsdPreviewSurface material for ``look`` at ``path``; ``texture_file`` (a path anchored
    to the layer, e.g. ``./textures/wood.png``) feeds its diffuse colour, tinted by the look's
    colour, else the colour alone does."""
    from pxr import Gf, UsdShade

    types = sdf().ValueTypeNames
    material = UsdShade.Material.Define(stage, path)
    shader = UsdShade.Shader.Define(stage, f"{path}/PreviewSurface")
    shader.CreateIdAttr("UsdPreviewSurface")
    rgba = look.linear_rgba
    shader.CreateInput("roughness", types.Float).Set(float(look.roughness))
    shader.CreateInput("metallic", types.Float).Set(0.0)
    shader.CreateInput("opacity", types.Float).Set(float(rgba[3]))
    if look.emission > 0:
        shader.CreateInput("emissiveColor", types.Color3f).Set(
            Gf.Vec3f(*(min(1.0, c * look.emission) for c in rgba[:3]))
        )
    diffuse = shader.CreateInput("diffuseColor", types.Color3f)
    if texture_file is not None:
        reader = UsdShade.Shader.Define(stage, f"{path}/TexCoords")
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", types.String).Set("st")
        texture = UsdShade.Shader.Define(stage, f"{path}/Texture")
        texture.CreateIdAttr("UsdUVTexture")
        texture.CreateInput("file", types.Asset).Set(texture_file)
        texture.CreateInput("sourceColorSpace", types.Token).Set("sRGB")
        texture.CreateInput("wrapS", types.Token).Set("repeat")
        texture.CreateInput("wrapT", types.Token).Set("repeat")
        texture.CreateInput("scale", types.Float4).Set(
            Gf.Vec4f(float(rgba[0]), float(rgba[1]), float(rgba[2]), 1.0)
        )
        texture.CreateInput("st", types.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
        diffuse.ConnectToSource(texture.ConnectableAPI(), "rgb")
    else:
        diffuse.Set(Gf.Vec3f(*(float(c) for c in rgba[:3])))
    material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
    return material


def define_lights(
    stage: Any, model: mujoco.MjModel, data: mujoco.MjData, path_of: Callable[[str], str]
) -> None:
    """The model's lights under ``/World/Lights`` as UsdLux distant and sphere lights (spot
    lights shaped by their cutoff); ``path_of`` gives a light's unique prim path by its name."""
    from pxr import Gf, UsdGeom, UsdLux

    if model.nlight == 0:
        return
    UsdGeom.Xform.Define(stage, "/World/Lights")
    for light in range(model.nlight):
        name = model.light(light).name or f"light_{light}"
        diffuse = np.asarray(model.light_diffuse[light], dtype=float)
        strength = float(diffuse.max())
        color = diffuse / strength if strength > 0 else np.ones(3)
        rotation = rotation_from_quat(quat_from_to((0.0, 0.0, -1.0), data.light_xdir[light]))
        path = path_of(name)
        if int(model.light_type[light]) == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL:
            lux = UsdLux.DistantLight.Define(stage, path)
            lux.CreateIntensityAttr(2000.0 * strength)
        else:
            lux = UsdLux.SphereLight.Define(stage, path)
            lux.CreateRadiusAttr(0.05)
            lux.CreateIntensityAttr(30000.0 * strength)
            if int(model.light_type[light]) == mujoco.mjtLightType.mjLIGHT_SPOT:
                shaping = UsdLux.ShapingAPI.Apply(lux.GetPrim())
                shaping.CreateShapingConeAngleAttr(float(model.light_cutoff[light]))
        lux.CreateColorAttr(Gf.Vec3f(*color.tolist()))
        set_pose(UsdGeom.Xformable(lux), data.light_xpos[light], rotation)
        string_attr(lux.GetPrim(), "holomj:name", name)
