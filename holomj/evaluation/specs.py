"""Annotations (the format of ``scripts/eval/prompts_dev.jsonl``): reading and checking.

One JSON object per annotation::

    id, prompt, rooms {"eq"|"ge": n}, room_types [{type, count}],
    objects [{name, count {"eq"|"ge": n}, room?, attributes? {color?, material?, shape?}}],
    relations [{subject, relation, object, quantifier? any|all|most, room?}],
    absent [name], defining [room type]
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from holomj.errors import FormatError, InputError
from holomj.evaluation.relations import RELATIONS

QUANTIFIERS = ("any", "all", "most")
ATTRIBUTES = ("color", "material", "shape")


def load_specs(source: str) -> list[dict[str, Any]]:
    """Annotations from a JSON line/object, or a .jsonl/.json file."""
    text = source.strip()
    if text.startswith("{") or text.startswith("["):
        data = json.loads(text)
        return data if isinstance(data, list) else [data]
    path = Path(source)
    raw = path.read_text()
    if path.suffix == ".jsonl":
        return [json.loads(line) for line in raw.splitlines() if line.strip()]
    data = json.loads(raw)
    return data if isinstance(data, list) else [data]


def read_spec(path: Path | str, spec_id: str | None = None) -> dict[str, Any]:
    """The one annotation of a .json or .jsonl file (``spec_id`` picks one of several), checked;
    a one-line :class:`~holomj.errors.InputError` naming the file and field otherwise."""
    where = str(path)
    try:
        specs = load_specs(str(path)) if Path(path).is_file() else None
    except OSError as err:
        raise FormatError(f"cannot read: {err.strerror or err}", where=where) from None
    except ValueError as err:
        raise FormatError(f"not JSON: {err}", where=where) from None
    if specs is None:
        raise InputError("no such file", where=where, fix="pass an annotation .json or .jsonl")
    if spec_id is not None:
        specs = [s for s in specs if isinstance(s, dict) and s.get("id") == spec_id]
    if len(specs) != 1:
        fix = "pick one with --id" if len(specs) > 1 else "check --id"
        raise InputError(f"holds {len(specs)} annotations, expected one", where=where, fix=fix)
    return check_spec(specs[0], where)


def check_spec(spec: Any, where: str = "spec") -> dict[str, Any]:
    """``spec`` when it is a well-formed annotation; else an InputError naming the field."""
    if not isinstance(spec, dict):
        raise InputError("an annotation must be a JSON object", where=where)
    if "rooms" in spec:
        _count(spec["rooms"], f"{where}: rooms")
    for i, rt in enumerate(_list(spec, "room_types", where)):
        at = f"{where}: room_types[{i}]"
        _need_str(rt, "type", at)
        _count(rt.get("count"), f"{at}.count")
    for i, obj in enumerate(_list(spec, "objects", where)):
        at = f"{where}: objects[{i}]"
        _need_str(obj, "name", at)
        _count(obj.get("count"), f"{at}.count")
        attrs = obj.get("attributes") or {}
        if not isinstance(attrs, dict) or set(attrs) - set(ATTRIBUTES):
            raise InputError(
                f"attributes must be an object of {', '.join(ATTRIBUTES)}",
                where=f"{at}.attributes",
            )
        if obj.get("room") is not None and not isinstance(obj["room"], str):
            raise InputError("must be a room type name", where=f"{at}.room")
    for i, rel in enumerate(_list(spec, "relations", where)):
        at = f"{where}: relations[{i}]"
        _need_str(rel, "subject", at)
        if rel.get("relation") not in RELATIONS:
            raise InputError(
                f"unknown relation {rel.get('relation')!r}",
                where=f"{at}.relation",
                fix="use one of: " + ", ".join(RELATIONS),
            )
        if rel.get("object") is not None and not isinstance(rel["object"], str):
            raise InputError("must be a name, wall, window, door or null", where=f"{at}.object")
        if rel.get("quantifier", "any") not in QUANTIFIERS:
            raise InputError(
                f"unknown quantifier {rel['quantifier']!r}",
                where=f"{at}.quantifier",
                fix="use any, all or most",
            )
    for key in ("absent", "defining"):
        for i, name in enumerate(_list(spec, key, where)):
            if not isinstance(name, str) or not name.strip():
                raise InputError("must be a name", where=f"{where}: {key}[{i}]")
    return spec


def _list(spec: dict[str, Any], key: str, where: str) -> list[Any]:
    value = spec.get(key, [])
    if not isinstance(value, list):
        raise InputError("must be a list", where=f"{where}: {key}")
    for i, item in enumerate(value):
        if key in ("room_types", "objects", "relations") and not isinstance(item, dict):
            raise InputError("must be an object", where=f"{where}: {key}[{i}]")
    return value


def _need_str(item: dict[str, Any], key: str, at: str) -> None:
    if not isinstance(item.get(key), str) or not item[key].strip():
        raise InputError("missing or not a name", where=f"{at}.{key}")


def _count(count: Any, at: str) -> None:
    ok = (
        isinstance(count, dict)
        and len(count) == 1
        and next(iter(count)) in ("eq", "ge")
        and isinstance(next(iter(count.values())), int)
        and not isinstance(next(iter(count.values())), bool)
        and next(iter(count.values())) >= 0
    )
    if not ok:
        raise InputError(
            f"must be {{'eq': n}} or {{'ge': n}} with a whole number n >= 0, not {count!r}",
            where=at,
        )
