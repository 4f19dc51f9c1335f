"""Shared building blocks of the pure-data specs: a frozen strict model and vector types."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Any, TypeVar

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from holomj.errors import FormatError, SpecError

Vec2 = tuple[float, float]
Vec3 = tuple[float, float, float]
Vec4 = tuple[float, float, float, float]
UnitFloat = Annotated[float, Field(ge=0.0, le=1.0)]
Rgb = tuple[UnitFloat, UnitFloat, UnitFloat]
Rgba = tuple[UnitFloat, UnitFloat, UnitFloat, UnitFloat]
PositiveFloat = Annotated[float, Field(gt=0.0)]
# Ids become MuJoCo name prefixes (``f"{id}/"``) and file names: keep them plain.
Identifier = Annotated[
    str, Field(min_length=1, max_length=128, pattern=r"^[A-Za-z0-9_][A-Za-z0-9_.:|+\-]*$")
]

ModelT = TypeVar("ModelT", bound=BaseModel)


class FrozenModel(BaseModel):
    """Immutable, strict about unknown fields, and refusing NaN or infinity anywhere."""

    model_config = ConfigDict(
        frozen=True, extra="forbid", allow_inf_nan=False, validate_default=True
    )


def field_path(loc: tuple[int | str, ...]) -> str:
    """Render a pydantic error location as ``rooms[2].polygon[0]``."""
    path = ""
    for part in loc:
        if isinstance(part, int):
            path += f"[{part}]"
        else:
            path += f".{part}" if path else str(part)
    return path or "<root>"


def spec_error_from_validation(err: ValidationError, source: str) -> SpecError:
    """Turn the first pydantic error into a one-line :class:`SpecError` naming file and field."""
    first = err.errors(include_url=False)[0]
    loc = tuple(p for p in first.get("loc", ()) if not _is_union_tag(p))
    message = first.get("msg", "invalid value")
    if first.get("type") == "extra_forbidden":
        message = "unknown field"
    extra = len(err.errors()) - 1
    suffix = f" (and {extra} more error{'s' if extra > 1 else ''})" if extra else ""
    return SpecError(f"{message}{suffix}", where=f"{source}: {field_path(loc)}")


def _is_union_tag(part: int | str) -> bool:
    """Pydantic inserts union member names such as ``function-after[...]`` into locations."""
    return isinstance(part, str) and ("[" in part or part in {"float", "int", "str", "tuple"})


def validate_model(model: type[ModelT], data: Any, source: str) -> ModelT:
    """Validate ``data`` as ``model``; a failure becomes a :class:`SpecError` naming ``source``."""
    try:
        return model.model_validate(data)
    except ValidationError as err:
        raise spec_error_from_validation(err, source) from None
    except SpecError as err:
        raise err.located(source) from None
    except (ValueError, TypeError, RecursionError) as err:
        raise SpecError(f"invalid value: {err}", where=source) from None


def read_json(path: Path) -> Any:
    """Read a JSON file, turning I/O and syntax problems into a one-line :class:`FormatError`."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise FormatError("file not found", where=str(path)) from None
    except IsADirectoryError:
        raise FormatError("is a folder, expected a JSON file", where=str(path)) from None
    except (OSError, UnicodeDecodeError) as err:
        raise FormatError(f"cannot read file: {err}", where=str(path)) from None
    return parse_json(text, str(path))


def parse_json(text: str, source: str) -> Any:
    """Parse JSON text, rejecting NaN/Infinity literals and reporting line and column."""

    def _reject_constant(name: str) -> Any:
        raise ValueError(f"non-finite number {name} is not allowed")

    try:
        return json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as err:
        raise FormatError(
            f"invalid JSON: {err.msg} at line {err.lineno} column {err.colno}", where=source
        ) from None
    except (ValueError, RecursionError) as err:
        raise FormatError(f"invalid JSON: {err}", where=source) from None
