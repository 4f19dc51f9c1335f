"""What populate works with: the receptacle looked up in the scene, each request (a category
or an asset id) resolved to a library asset, and several libraries seen as one. Errors name the
option (``--on``, ``objects``) and the closest names, or list what there is.
"""

from __future__ import annotations

import numpy as np

from holomj.errors import InputError, closest_names
from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.spec.scene import SceneObject, SceneSpec


def merge_libraries(*libraries: AssetLibrary) -> AssetLibrary:
    """One read-only view of several libraries; the first that holds an id wins."""
    assets: dict[str, LibraryAsset] = {}
    for library in reversed(libraries):
        assets.update({asset_id: library.get(asset_id) for asset_id in library.ids()})
    first = libraries[0]
    return AssetLibrary(first.root, " + ".join(lib.name for lib in libraries), assets)


def find_object(scene: SceneSpec, object_id: str) -> SceneObject:
    """The scene's object ``object_id``; an :class:`InputError` naming ``--on`` (with the
    closest ids) when there is none."""
    for obj in scene.objects:
        if obj.id == object_id:
            return obj
    near = closest_names(object_id, [o.id for o in scene.objects])
    raise InputError(
        f"the scene has no object {object_id!r}",
        where="--on",
        fix=f"did you mean: {near}" if near else _listing("objects", [o.id for o in scene.objects]),
    )


def _listing(kind: str, names: list[str], limit: int = 12) -> str:
    """``objects: a, b, c`` (sorted, at most ``limit``, then ``... (N in all)``)."""
    if not names:
        return f"there are no {kind}"
    shown = sorted(names)[:limit]
    more = f", ... ({len(names)} in all)" if len(names) > limit else ""
    return f"{kind}: {', '.join(shown)}{more}"


def resolve_request(library: AssetLibrary, name: str, rng: np.random.Generator) -> LibraryAsset:
    """The asset for a request: an asset id as is, else one of the category's small objects."""
    if name in library:
        return library.get(name)
    candidates = [a for a in library.by_category(name) if "object" in a.meta.placement]
    if not candidates:
        metas = [library.get(i).meta for i in library.ids()]
        known = sorted({m.category for m in metas if "object" in m.placement})
        near = closest_names(name, known) or closest_names(name, library.ids())
        raise InputError(
            f"no small-object asset or category {name!r} in the library",
            where="objects",
            fix=f"did you mean: {near}" if near else _listing("small-object categories", known),
        )
    return candidates[int(rng.integers(len(candidates)))]
