"""A small client for OpenAI-compatible chat-completions servers, on the standard library only.

``POST {base_url}/chat/completions`` with ``model``, ``messages``, ``temperature``,
``max_tokens`` and ``seed``; ``Authorization: Bearer KEY`` when a key is configured. Works with
hosted APIs and with local servers (vLLM, Ollama's ``http://localhost:11434/v1``, llama.cpp).
Loopback servers are reached directly, never through an HTTP proxy from the environment.

Every failure is an :class:`LLMTransportError` with a one-line message and a ``retryable``
flag: HTTP 429 and 5xx, timeouts and malformed envelopes may be retried; connection refused and
other 4xx answers may not (retrying cannot help).
"""

from __future__ import annotations

import http.client
import ipaddress
import json
import socket
import time
import urllib.error
import urllib.request
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlsplit

from holomj.errors import HolomjError
from holomj.plan.llm_config import LLMConfig
from holomj.version import __version__

MAX_RESPONSE_BYTES = 8 * 1024 * 1024
_BODY_SNIPPET = 200


class LLMTransportError(HolomjError):
    """The server could not be reached or did not answer with a chat completion."""

    def __init__(
        self,
        what: str,
        *,
        retryable: bool,
        status: int | None = None,
        where: str | None = None,
        fix: str | None = None,
    ) -> None:
        self.retryable = retryable
        self.status = status
        super().__init__(what, where=where, fix=fix)


@dataclass(frozen=True)
class ChatResponse:
    """One completion: the text, why it stopped, and what it cost."""

    content: str
    finish_reason: str | None
    prompt_tokens: int
    completion_tokens: int
    seconds: float
    model: str | None = None


class ChatClient:
    """Sends chat-completions requests to the server of one :class:`LLMConfig`."""

    def __init__(self, config: LLMConfig) -> None:
        self.config = config
        handlers: list[urllib.request.BaseHandler] = []
        if _is_loopback(urlsplit(config.base_url).hostname or ""):
            handlers.append(urllib.request.ProxyHandler({}))
        self._opener = urllib.request.build_opener(*handlers)

    def request_body(self, messages: Sequence[Mapping[str, str]], *, seed: int) -> dict[str, Any]:
        """The JSON body sent for ``messages``."""
        return {
            "model": self.config.model,
            "messages": [{"role": m["role"], "content": m["content"]} for m in messages],
            "temperature": self.config.temperature,
            "max_tokens": self.config.max_tokens,
            "seed": seed,
            "stream": False,
        }

    def complete(self, messages: Sequence[Mapping[str, str]], *, seed: int) -> ChatResponse:
        """Send one request and return the first choice; :class:`LLMTransportError` on failure."""
        body = json.dumps(self.request_body(messages, seed=seed)).encode("utf-8")
        headers = {
            "Content-Type": "application/json",
            "Accept": "application/json",
            "User-Agent": f"holomj/{__version__}",
        }
        if self.config.api_key:
            headers["Authorization"] = f"Bearer {self.config.api_key}"
        request = urllib.request.Request(
            self.config.endpoint, data=body, headers=headers, method="POST"
        )
        start = time.monotonic()
        raw = self._send(request)
        seconds = time.monotonic() - start
        return parse_completion(raw, seconds, self.config.endpoint)

    def _send(self, request: urllib.request.Request) -> bytes:
        url = self.config.endpoint
        timeout = self.config.timeout_s
        try:
            with self._opener.open(request, timeout=timeout) as response:
                data = response.read(MAX_RESPONSE_BYTES + 1)
        except urllib.error.HTTPError as err:
            raise _http_error(err, url) from None
        except urllib.error.URLError as err:
            raise _connection_error(err.reason, url, timeout) from None
        except TimeoutError:
            raise _timeout(url, timeout) from None
        except (ConnectionError, OSError) as err:
            raise _connection_error(err, url, timeout) from None
        except (http.client.HTTPException, ValueError) as err:  # bad status line, cut-off body
            raise LLMTransportError(
                f"malformed HTTP answer: {err}", retryable=True, where=url
            ) from None
        if len(data) > MAX_RESPONSE_BYTES:
            raise LLMTransportError(
                f"answer larger than {MAX_RESPONSE_BYTES // (1024 * 1024)} MiB",
                retryable=False,
                where=url,
            )
        return data


def parse_completion(raw: bytes, seconds: float, where: str = "LLM server") -> ChatResponse:
    """Read a chat-completions JSON envelope: ``choices[0].message.content``, finish, usage."""
    try:
        data = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError):
        raise LLMTransportError(
            f"answer is not a JSON chat completion: {_snippet(raw)!r}", retryable=True, where=where
        ) from None
    choices = data.get("choices") if isinstance(data, dict) else None
    if not isinstance(choices, list) or not choices or not isinstance(choices[0], dict):
        raise LLMTransportError(
            "answer has no 'choices' (not an OpenAI-compatible chat completion)",
            retryable=True,
            where=where,
        )
    message = choices[0].get("message")
    content = message.get("content") if isinstance(message, dict) else None
    finish = choices[0].get("finish_reason")
    usage = data.get("usage") if isinstance(data.get("usage"), dict) else {}
    model = data.get("model")
    return ChatResponse(
        content=_content_text(content),
        finish_reason=finish if isinstance(finish, str) else None,
        prompt_tokens=_count(usage.get("prompt_tokens")),
        completion_tokens=_count(usage.get("completion_tokens")),
        seconds=seconds,
        model=model if isinstance(model, str) else None,
    )


def _content_text(content: Any) -> str:
    """Message content as text: a string, or the text parts of a list of parts."""
    if isinstance(content, str):
        return content
    if isinstance(content, list):
        parts = [p.get("text") for p in content if isinstance(p, dict)]
        return "".join(p for p in parts if isinstance(p, str))
    return ""


def _count(value: Any) -> int:
    return value if isinstance(value, int) and not isinstance(value, bool) and value >= 0 else 0


def _snippet(raw: bytes) -> str:
    text = raw.decode("utf-8", errors="replace")
    return " ".join(text.split())[:_BODY_SNIPPET]


def _http_error(err: urllib.error.HTTPError, url: str) -> LLMTransportError:
    try:
        raw = err.read(64 * 1024)
    except (OSError, ValueError):
        raw = b""
    detail = _error_detail(raw)
    status = err.code
    retryable = status == 429 or status >= 500
    fix = None
    if status in (401, 403):
        fix = "check the API key (HOLOMJ_LLM_API_KEY)"
    elif status == 404:
        fix = "check the base URL (it usually ends in /v1) and the model name"
    return LLMTransportError(
        f"HTTP {status} {err.reason}{': ' + detail if detail else ''}",
        retryable=retryable,
        status=status,
        where=url,
        fix=fix,
    )


def _error_detail(raw: bytes) -> str:
    """The ``error.message`` of an OpenAI-style error body, else a snippet of the body."""
    try:
        data = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError):
        return _snippet(raw)
    error = data.get("error") if isinstance(data, dict) else None
    if isinstance(error, dict) and isinstance(error.get("message"), str):
        return " ".join(error["message"].split())[:_BODY_SNIPPET]
    if isinstance(error, str):
        return " ".join(error.split())[:_BODY_SNIPPET]
    return _snippet(raw)


def _timeout(url: str, timeout: float) -> LLMTransportError:
    return LLMTransportError(
        f"no answer within {timeout:g} s (timeout)",
        retryable=True,
        where=url,
        fix="raise timeout_s in the [llm] config table for slow models",
    )


def _connection_error(reason: Any, url: str, timeout: float) -> LLMTransportError:
    if isinstance(reason, TimeoutError):
        return _timeout(url, timeout)
    if isinstance(reason, ConnectionRefusedError):
        what = "cannot reach the LLM server (connection refused)"
    elif isinstance(reason, socket.gaierror):
        what = f"cannot resolve the LLM server's host name ({reason.strerror or reason})"
    elif isinstance(reason, (ConnectionResetError, ConnectionAbortedError)):
        return LLMTransportError("the LLM server closed the connection", retryable=True, where=url)
    else:
        what = f"cannot reach the LLM server ({reason})"
    return LLMTransportError(
        what,
        retryable=False,
        where=url,
        fix="start the server or set HOLOMJ_LLM_BASE_URL, or use --planner offline",
    )


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False
