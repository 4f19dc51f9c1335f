"""Asset metadata: category, description, physical defaults, and sidecar overrides.

A sidecar is a JSON or YAML mapping next to the mesh (``chair.holomj.json``,
``chair.glb.holomj.json``, or ``.yaml``/``.yml``) or passed explicitly. It may set any
:class:`~holomj.spec.assets.AssetMeta` field (``license`` and ``attribution`` included).
Precedence: explicit import options (category, description, mass) > sidecar > derived
values; the id is always the one asked for. A sidecar category or density also feeds the
derived friction, placement and mass. Errors name the sidecar file and the field.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from holomj.errors import FormatError, SpecError
from holomj.spec.assets import AssetMeta
from holomj.spec.base import validate_model

SIDECAR_SUFFIXES = (".holomj.json", ".holomj.yaml", ".holomj.yml")


def find_sidecar(path: Path) -> Path | None:
    """The sidecar next to ``path``, if there is one."""
    for base in (path.with_suffix(""), path):
        for suffix in SIDECAR_SUFFIXES:
            candidate = base.parent / f"{base.name}{suffix}"
            if candidate.is_file():
                return candidate
    return None


def read_sidecar(path: Path) -> dict[str, Any]:
    """Read a sidecar mapping; FormatError naming the file when it cannot be read."""
    where = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise FormatError("sidecar file not found", where=where) from None
    except (OSError, UnicodeDecodeError) as err:
        raise FormatError(f"cannot read the sidecar: {err}", where=where) from None
    if path.suffix.lower() in (".yaml", ".yml"):
        try:
            import yaml
        except ImportError:
            raise FormatError(
                "YAML sidecars need PyYAML", where=where, fix="pip install pyyaml, or use JSON"
            ) from None
        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as err:
            raise FormatError(f"invalid YAML: {' '.join(str(err).split())}", where=where) from None
    else:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as err:
            raise FormatError(f"invalid JSON: {err}", where=where) from None
    if data is None:
        return {}
    if not isinstance(data, dict) or not all(isinstance(k, str) for k in data):
        raise SpecError("a sidecar must be a mapping of AssetMeta fields", where=where)
    known = set(AssetMeta.model_fields)
    for key in data:
        if key not in known:
            raise SpecError("unknown field", where=f"{where}: {key}", fix=_fields_hint())
    return data


def sidecar_number(sidecar: dict, key: str, where: str) -> float | None:
    """A positive finite number from the sidecar, or None when absent."""
    if key not in sidecar or sidecar[key] is None:
        return None
    value = sidecar[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SpecError(f"must be a number, got {value!r}", where=f"{where}: {key}")
    if not math.isfinite(value) or value <= 0:
        raise SpecError(f"must be a positive number, got {value!r}", where=f"{where}: {key}")
    return float(value)


def describe(category: str) -> str:
    """``a dining table`` for ``dining_table``."""
    words = category.replace("_", " ").replace("-", " ").strip()
    article = "an" if words[:1].lower() in "aeiou" else "a"
    return f"{article} {words}"


def build_meta(
    derived: dict[str, Any],
    sidecar: dict[str, Any],
    explicit: dict[str, Any],
    source: str,
) -> tuple[AssetMeta, list[str]]:
    """Merge derived < sidecar < explicit fields and validate; errors name ``source``."""
    warnings = []
    data = dict(derived)
    for key, value in sidecar.items():
        if key == "id" and value != derived["id"]:
            warnings.append(f"sidecar id {value!r} ignored: the asset id is {derived['id']!r}")
            continue
        data[key] = value
    data.update({k: v for k, v in explicit.items() if v is not None})
    return validate_model(AssetMeta, data, source), warnings


def _fields_hint() -> str:
    names = sorted(AssetMeta.model_fields)
    return "known fields: " + ", ".join(names)
