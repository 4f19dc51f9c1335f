"""Where the LLM planner finds its server: arguments, environment, then ``config.toml``.

Precedence, highest first: the arguments of :func:`load_llm_config`, the environment
(``HOLOMJ_LLM_BASE_URL``, ``HOLOMJ_LLM_MODEL``, ``HOLOMJ_LLM_API_KEY``, with ``OPENAI_BASE_URL``
and ``OPENAI_API_KEY`` as fallbacks), then the ``[llm]`` table of a TOML file
(``$HOLOMJ_HOME/config.toml`` unless another file is given)::

    [llm]
    base_url = "http://localhost:11434/v1"   # any OpenAI-compatible server (vLLM, Ollama, ...)
    model = "qwen2.5:14b"
    api_key = "..."          # optional; sent as "Authorization: Bearer ..."
    timeout_s = 60           # per request
    max_retries = 2          # extra attempts per step
    temperature = 0.2
    max_tokens = 4096
    backoff_s = 0.5          # first pause after an HTTP error or a timeout (doubles each time)
"""

from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

from holomj.errors import FormatError, InputError
from holomj.library.location import holomj_home

ENV_BASE_URL = ("HOLOMJ_LLM_BASE_URL", "OPENAI_BASE_URL")
ENV_MODEL = ("HOLOMJ_LLM_MODEL",)
ENV_API_KEY = ("HOLOMJ_LLM_API_KEY", "OPENAI_API_KEY")

# Numeric settings of the [llm] table: type and allowed range (inclusive).
_NUMBERS: dict[str, tuple[type, float, float]] = {
    "timeout_s": (float, 0.01, 3600.0),
    "max_retries": (int, 0, 10),
    "temperature": (float, 0.0, 2.0),
    "max_tokens": (int, 16, 1_000_000),
    "backoff_s": (float, 0.0, 60.0),
}
_STRINGS = ("base_url", "model", "api_key")


@dataclass(frozen=True)
class LLMConfig:
    """How to reach an OpenAI-compatible chat-completions server and how to use it."""

    base_url: str
    model: str
    api_key: str | None = field(default=None, repr=False)
    timeout_s: float = 60.0
    max_retries: int = 2
    temperature: float = 0.2
    max_tokens: int = 4096
    backoff_s: float = 0.5

    def __post_init__(self) -> None:
        object.__setattr__(self, "base_url", check_base_url(self.base_url, "base_url"))
        if not self.model.strip():
            raise InputError("empty LLM model name", where="llm.model")
        for name, (kind, low, high) in _NUMBERS.items():
            value = getattr(self, name)
            object.__setattr__(self, name, _number(value, name, kind, low, high, "llm"))

    @property
    def endpoint(self) -> str:
        """The chat-completions URL: ``{base_url}/chat/completions``."""
        return f"{self.base_url}/chat/completions"


def default_config_file() -> Path:
    """``$HOLOMJ_HOME/config.toml``."""
    return holomj_home() / "config.toml"


def load_llm_config(
    *,
    base_url: str | None = None,
    model: str | None = None,
    api_key: str | None = None,
    config_file: Path | None = None,
) -> LLMConfig:
    """Build the LLM configuration from arguments, environment and the config file.

    A missing base URL or model raises :class:`InputError` naming the environment variables and
    the config file that could have given it. A given ``config_file`` must exist; the default one
    may be absent. On Python 3.10 (no ``tomllib``) the file is skipped and the error says so.
    """
    path = Path(config_file) if config_file is not None else default_config_file()
    table, file_note = _read_table(path, required=config_file is not None)
    values: dict[str, Any] = {k: v for k, v in table.items() if k not in _STRINGS}
    chosen = {
        "base_url": _first(base_url, _env(ENV_BASE_URL), table.get("base_url")),
        "model": _first(model, _env(ENV_MODEL), table.get("model")),
        "api_key": _first(api_key, _env(ENV_API_KEY), table.get("api_key")),
    }
    for key, env_names in (("base_url", ENV_BASE_URL), ("model", ENV_MODEL)):
        if chosen[key] is None:
            raise InputError(
                f"no LLM {key.replace('_', ' ')} configured{file_note}",
                where="--planner llm",
                fix=f"set {' or '.join(env_names)}, or '{key}' in the [llm] table of {path}",
            )
    return LLMConfig(
        base_url=str(chosen["base_url"]),
        model=str(chosen["model"]),
        api_key=chosen["api_key"],
        **values,
    )


def check_base_url(url: str, where: str) -> str:
    """An ``http(s)://host[:port][/path]`` URL, no trailing slash; else :class:`InputError`."""
    text = url.strip().rstrip("/")
    parts = urlsplit(text)
    if parts.scheme not in ("http", "https") or not parts.netloc or parts.query or parts.fragment:
        raise InputError(
            f"LLM base URL {url!r} is not an http(s) URL",
            where=where,
            fix="give the server's API root, e.g. http://localhost:11434/v1",
        )
    return text


def _first(*candidates: str | None) -> str | None:
    for value in candidates:
        if value is not None and value.strip():
            return value.strip()
    return None


def _env(names: tuple[str, ...]) -> str | None:
    return _first(*(os.environ.get(name) for name in names))


def _read_table(path: Path, *, required: bool) -> tuple[dict[str, Any], str]:
    """The validated ``[llm]`` table of ``path`` and a note for errors when it was skipped."""
    if not path.is_file():
        if required:
            raise FormatError("config file not found", where=str(path))
        return {}, ""
    if sys.version_info < (3, 11):
        if required:
            raise InputError(
                "reading a TOML config file needs Python 3.11 or newer",
                where=str(path),
                fix="use the HOLOMJ_LLM_* environment variables instead",
            )
        return {}, f" ({path} skipped: reading TOML needs Python 3.11 or newer)"
    import tomllib

    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as err:
        raise FormatError(f"cannot read config file: {err}", where=str(path)) from None
    except tomllib.TOMLDecodeError as err:
        raise FormatError(f"invalid TOML: {err}", where=str(path)) from None
    table = data.get("llm", {})
    if not isinstance(table, dict):
        raise FormatError("'llm' must be a table", where=str(path), fix="write it as [llm]")
    known = {f.name for f in fields(LLMConfig)}
    for key, value in table.items():
        where = f"{path}: llm.{key}"
        if key not in known:
            raise FormatError(f"unknown setting (known: {', '.join(sorted(known))})", where=where)
        if key in _STRINGS and not isinstance(value, str):
            raise FormatError("must be a string", where=where)
    numbers = {
        key: _number(value, key, *_NUMBERS[key], str(path))
        for key, value in table.items()
        if key in _NUMBERS
    }
    return {**table, **numbers}, ""


def _number(value: Any, name: str, kind: type, low: float, high: float, source: str) -> Any:
    where = f"{source}: llm.{name}" if source != "llm" else f"llm.{name}"
    ok_type = isinstance(value, (int, float)) and not isinstance(value, bool)
    if kind is int and ok_type and isinstance(value, float) and value.is_integer():
        value = int(value)
    if not ok_type or (kind is int and not isinstance(value, int)):
        raise InputError(f"must be {'an integer' if kind is int else 'a number'}", where=where)
    if not math.isfinite(value) or not low <= value <= high:
        raise InputError(f"{value} is outside [{low:g}, {high:g}]", where=where)
    return kind(value)
