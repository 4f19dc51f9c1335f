"""A loopback OpenAI-compatible server that replays scripted answers and records every request.

Each reply is a dict:

* ``content`` (+ ``finish_reason``, ``prompt_tokens``, ``completion_tokens``): a chat completion;
* ``status`` (+ ``body``): an HTTP error answer, e.g. ``{"status": 500}``;
* ``raw``: these bytes as a 200 answer's body, verbatim (a broken envelope);
* ``delay_s``: wait this long before answering (for client timeouts);
* ``expect``: a text the request's first user message must contain (the step being asked),
  else the server answers 400 so the test fails loudly.

Replies are used in order; a request after the last one gets HTTP 410 (not retryable).
Recorded conversations live in ``tests/fixtures/llm/*.json`` (``prompt``, ``seed``, ``model``,
``replies``).
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "llm"
CHAT_PATH = "/v1/chat/completions"


def load_conversation(name: str) -> dict[str, Any]:
    """A recorded conversation from ``tests/fixtures/llm/<name>.json``."""
    return json.loads((FIXTURES / f"{name}.json").read_text(encoding="utf-8"))


@dataclass(frozen=True)
class RecordedRequest:
    """What the client sent."""

    path: str
    headers: dict[str, str]
    body: dict[str, Any]

    @property
    def messages(self) -> list[dict[str, str]]:
        """The request's chat messages."""
        return self.body["messages"]


class ReplayServer:
    """Serves ``replies`` in order on 127.0.0.1 (a free port) from a background thread."""

    def __init__(self, replies: list[dict[str, Any]]) -> None:
        self.replies = list(replies)
        self.requests: list[RecordedRequest] = []
        self._lock = threading.Lock()
        self._server = ThreadingHTTPServer(("127.0.0.1", 0), _handler_for(self))
        self._server.daemon_threads = True
        self._server.block_on_close = False
        self._thread = threading.Thread(
            target=self._server.serve_forever, kwargs={"poll_interval": 0.02}, daemon=True
        )

    @property
    def base_url(self) -> str:
        """The API root to configure the client with (``http://127.0.0.1:PORT/v1``)."""
        return f"http://127.0.0.1:{self._server.server_address[1]}/v1"

    @property
    def remaining(self) -> int:
        """Replies not used yet."""
        with self._lock:
            return len(self.replies)

    def start(self) -> ReplayServer:
        """Start serving."""
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stop serving and close the socket."""
        self._server.shutdown()
        self._server.server_close()

    def _next(self, request: RecordedRequest) -> dict[str, Any] | None:
        with self._lock:
            self.requests.append(request)
            return self.replies.pop(0) if self.replies else None


@contextmanager
def replay_server(replies: list[dict[str, Any]]) -> Iterator[ReplayServer]:
    """A started :class:`ReplayServer`, stopped on exit."""
    server = ReplayServer(replies).start()
    try:
        yield server
    finally:
        server.stop()


def completion(reply: dict[str, Any], model: str, number: int) -> dict[str, Any]:
    """The chat-completions envelope of a scripted ``content`` reply."""
    return {
        "id": f"chatcmpl-replay-{number}",
        "object": "chat.completion",
        "created": 1_700_000_000 + number,
        "model": model,
        "choices": [
            {
                "index": 0,
                "message": {"role": "assistant", "content": reply["content"]},
                "finish_reason": reply.get("finish_reason", "stop"),
            }
        ],
        "usage": {
            "prompt_tokens": reply.get("prompt_tokens", 100),
            "completion_tokens": reply.get("completion_tokens", 50),
            "total_tokens": reply.get("prompt_tokens", 100) + reply.get("completion_tokens", 50),
        },
    }


def _handler_for(replay: ReplayServer) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"
        disable_nagle_algorithm = True  # headers and body are written separately

        def log_message(self, format: str, *args: Any) -> None:  # keep test output clean
            return

        def do_POST(self) -> None:
            length = int(self.headers.get("Content-Length", "0"))
            raw = self.rfile.read(length)
            try:
                body = json.loads(raw)
            except ValueError:
                body = {"unparsed": raw.decode("utf-8", "replace")}
            request = RecordedRequest(self.path, dict(self.headers.items()), body)
            reply = replay._next(request)
            if self.path != CHAT_PATH:
                self._send(404, {"error": {"message": f"no route {self.path}"}})
                return
            if reply is None:
                self._send(410, {"error": {"message": "replay: no replies left"}})
                return
            expect = reply.get("expect")
            messages = body.get("messages") or [{}, {}]
            first_user = next((m for m in messages if m.get("role") == "user"), {})
            if expect and expect not in str(first_user.get("content", "")):
                self._send(
                    400, {"error": {"message": f"replay: expected a request for {expect!r}"}}
                )
                return
            time.sleep(reply.get("delay_s", 0.0))
            if "status" in reply:
                self._send(reply["status"], reply.get("body", {"error": {"message": "scripted"}}))
            elif "raw" in reply:
                self._send(200, reply["raw"])
            else:
                self._send(200, completion(reply, body.get("model", "?"), len(replay.requests)))

        def _send(self, status: int, payload: Any) -> None:
            data = payload.encode() if isinstance(payload, str) else json.dumps(payload).encode()
            try:
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)
            except (BrokenPipeError, ConnectionResetError):  # the client gave up (timeout tests)
                pass

    return Handler
