"""Reading objathor files safely: the file names and limits, pickles restricted to plain data and
numpy arrays, gzip with a size cap, JSON (see :mod:`asset_pipeline.objathor` for the layout)."""

from __future__ import annotations

import gzip
import io
import json
import math
import pickle
import re
from pathlib import Path
from typing import Any

from holomj.errors import FormatError

ANNOTATION_FILES = ("annotations.json.gz", "annotations.json")
MESH_SUFFIXES = (".pkl.gz", ".pkl", ".msgpack.gz", ".msgpack", ".json.gz", ".json")
GEOMETRY_SUFFIXES = (".obj", ".glb", ".gltf")
ALBEDO_NAMES = ("albedo.jpg", "albedo.jpeg", "albedo.png")
MAX_DECOMPRESSED_BYTES = 1 << 30  # a mesh dict is a few MB; refuse gzip bombs
MAX_TEXTURE_PX = 2048
MAX_DESCRIPTION = 2000
ID_PATTERN = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.:|+\-]{0,127}$")


# -- safe pickle loading ---------------------------------------------------------------------
_SAFE_GLOBALS = frozenset(
    {
        ("builtins", "dict"),
        ("builtins", "list"),
        ("builtins", "tuple"),
        ("builtins", "set"),
        ("builtins", "frozenset"),
        ("builtins", "bytearray"),
        ("builtins", "complex"),
        ("collections", "OrderedDict"),
        ("_codecs", "encode"),  # bytes in protocol-2 pickles of numpy arrays
        ("numpy", "ndarray"),
        ("numpy", "dtype"),
        ("numpy.core.multiarray", "_reconstruct"),
        ("numpy._core.multiarray", "_reconstruct"),
        ("numpy.core.multiarray", "scalar"),
        ("numpy._core.multiarray", "scalar"),
        ("numpy.core.numeric", "_frombuffer"),
        ("numpy._core.numeric", "_frombuffer"),
    }
)


class _RestrictedUnpickler(pickle.Unpickler):
    """An unpickler that builds only plain containers and numpy arrays (no other globals)."""

    def find_class(self, module: str, name: str) -> Any:
        if (module, name) not in _SAFE_GLOBALS:
            raise pickle.UnpicklingError(f"the pickle names {module}.{name}")
        return super().find_class(module, name)


def load_pickle(path: Path) -> Any:
    """Load a (gzip-compressed or plain) pickle with the restricted unpickler.

    Raises :class:`FormatError` naming ``path`` for a corrupt file or a pickle that names any
    class or function beyond plain containers and numpy arrays.
    """
    raw = read_maybe_gzip(path)
    try:
        return _RestrictedUnpickler(io.BytesIO(raw)).load()
    except pickle.UnpicklingError as err:
        text = str(err)
        if text.startswith("the pickle names"):
            raise FormatError(
                f"unsafe pickle refused: {text} (only plain containers and numpy arrays are "
                "loaded)",
                where=str(path),
                fix="re-export the asset with objathor, or convert it to .json",
            ) from None
        raise FormatError(f"corrupt pickle: {short_error(err)}", where=str(path)) from None
    except Exception as err:  # any unpickling failure is a bad file
        raise FormatError(f"corrupt pickle: {short_error(err)}", where=str(path)) from None


def read_maybe_gzip(path: Path) -> bytes:
    """The bytes of ``path``, gunzipped when they start with the gzip magic number."""
    where = str(path)
    try:
        with open(path, "rb") as handle:
            head = handle.read(2)
            handle.seek(0)
            if head != b"\x1f\x8b":
                return handle.read()
            with gzip.GzipFile(fileobj=handle) as unzipped:
                data = unzipped.read(MAX_DECOMPRESSED_BYTES + 1)
    except FileNotFoundError:
        raise FormatError("file not found", where=where) from None
    except OSError as err:  # BadGzipFile is an OSError
        raise FormatError(f"cannot read the file: {short_error(err)}", where=where) from None
    except (EOFError, ValueError) as err:  # truncated stream, zlib errors
        raise FormatError(f"corrupt gzip data: {short_error(err)}", where=where) from None
    if len(data) > MAX_DECOMPRESSED_BYTES:
        raise FormatError("more than 1 GiB once decompressed", where=where)
    return data


def short_error(err: BaseException) -> str:
    text = " ".join(str(err).split())[:200]
    return text or type(err).__name__


def finite_number(value: Any) -> float | None:
    """A finite float from a number or a numeric string (GPT writes "175"); else None."""
    if isinstance(value, bool):
        return None
    if isinstance(value, str):
        try:
            value = float(value.strip())
        except ValueError:
            return None
    if not isinstance(value, (int, float)):
        return None
    try:
        number = float(value)
    except OverflowError:
        return None
    return number if math.isfinite(number) else None


def read_json(path: Path) -> Any:
    raw = read_maybe_gzip(path)
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise FormatError("not UTF-8 JSON text", where=str(path)) from None
    except json.JSONDecodeError as err:
        raise FormatError(f"invalid JSON: {err}", where=str(path)) from None
