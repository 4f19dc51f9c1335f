"""The chat-completions client against a loopback server: what it sends, what it reads, errors."""

from __future__ import annotations

import json
import socket

import pytest

from holomj.plan.llm_client import ChatClient, LLMTransportError, _is_loopback, parse_completion
from holomj.plan.llm_config import LLMConfig
from tests.plan.llm_replay import replay_server

MESSAGES = [{"role": "system", "content": "be brief"}, {"role": "user", "content": "hello"}]


def client_for(base_url: str, **overrides: object) -> ChatClient:
    settings: dict[str, object] = {"model": "m1", "timeout_s": 5.0, **overrides}
    return ChatClient(LLMConfig(base_url=base_url, **settings))  # type: ignore[arg-type]


def test_request_body_and_headers() -> None:
    reply = {"content": "hi", "prompt_tokens": 11, "completion_tokens": 3}
    with replay_server([reply]) as server:
        client = client_for(server.base_url + "/", api_key="sk-abc", temperature=0.5)
        response = client.complete(MESSAGES, seed=42)
    assert (response.content, response.finish_reason) == ("hi", "stop")
    assert (response.prompt_tokens, response.completion_tokens) == (11, 3)
    assert response.model == "m1" and response.seconds >= 0.0
    (request,) = server.requests
    assert request.path == "/v1/chat/completions"
    assert request.headers["Authorization"] == "Bearer sk-abc"
    assert request.headers["Content-Type"] == "application/json"
    assert request.body == {
        "model": "m1",
        "messages": MESSAGES,
        "temperature": 0.5,
        "max_tokens": 4096,
        "seed": 42,
        "stream": False,
    }


def test_no_key_no_authorization_header() -> None:
    with replay_server([{"content": "hi"}]) as server:
        client_for(server.base_url).complete(MESSAGES, seed=0)
    assert "Authorization" not in server.requests[0].headers


def test_loopback_ignores_proxy_settings(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("HTTP_PROXY", "http_proxy", "ALL_PROXY", "all_proxy"):
        monkeypatch.setenv(name, "http://127.0.0.1:9")
    monkeypatch.delenv("NO_PROXY", raising=False)
    monkeypatch.delenv("no_proxy", raising=False)
    with replay_server([{"content": "direct"}]) as server:
        assert client_for(server.base_url).complete(MESSAGES, seed=0).content == "direct"
    assert _is_loopback("localhost") and _is_loopback("127.0.0.2") and _is_loopback("::1")
    assert not _is_loopback("api.example.com") and not _is_loopback("10.0.0.1")


@pytest.mark.parametrize(
    ("status", "retryable", "text"),
    [
        (500, True, "HTTP 500"),
        (503, True, "HTTP 503"),
        (429, True, "HTTP 429"),
        (401, False, "check the API key"),
        (404, False, "check the base URL"),
        (400, False, "HTTP 400"),
    ],
)
def test_http_errors(status: int, retryable: bool, text: str) -> None:
    body = {"error": {"message": "model  'x'\nnot found", "type": "invalid_request_error"}}
    replies = [{"status": status, "body": body}]
    with replay_server(replies) as server, pytest.raises(LLMTransportError) as info:
        client_for(server.base_url).complete(MESSAGES, seed=0)
    error = info.value
    assert (error.status, error.retryable) == (status, retryable)
    assert text in str(error)
    assert "model 'x' not found" in str(error)
    assert "\n" not in str(error)


def test_timeout_is_retryable() -> None:
    replies = [{"content": "late", "delay_s": 0.6}]
    with replay_server(replies) as server, pytest.raises(LLMTransportError) as info:
        client_for(server.base_url, timeout_s=0.15).complete(MESSAGES, seed=0)
    assert info.value.retryable
    assert "no answer within 0.15 s (timeout)" in str(info.value)


def test_connection_refused_is_one_line_and_final() -> None:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    with pytest.raises(LLMTransportError) as info:
        client_for(f"http://127.0.0.1:{port}/v1").complete(MESSAGES, seed=0)
    assert not info.value.retryable
    message = str(info.value)
    assert message.startswith(f"http://127.0.0.1:{port}/v1/chat/completions: cannot reach")
    assert "connection refused" in message and "\n" not in message


@pytest.mark.parametrize(
    ("raw", "text"),
    [
        ("<html>502 Bad Gateway</html>", "not a JSON chat completion"),
        ('{"object": "list", "data": []}', "no 'choices'"),
        ('{"choices": []}', "no 'choices'"),
    ],
)
def test_broken_envelopes_are_retryable(raw: str, text: str) -> None:
    with replay_server([{"raw": raw}]) as server, pytest.raises(LLMTransportError) as info:
        client_for(server.base_url).complete(MESSAGES, seed=0)
    assert info.value.retryable and text in str(info.value)


def test_parse_completion_variants() -> None:
    parts = {
        "choices": [
            {
                "message": {"content": [{"type": "text", "text": "a"}, {"text": "b"}, 3]},
                "finish_reason": "length",
            }
        ]
    }
    response = parse_completion(json.dumps(parts).encode(), 0.5)
    assert (response.content, response.finish_reason) == ("ab", "length")
    assert (response.prompt_tokens, response.completion_tokens) == (0, 0)  # no usage reported
    odd = {
        "choices": [{"message": {"content": None}, "finish_reason": 7}],
        "usage": {"prompt_tokens": -3, "completion_tokens": True},
        "model": ["x"],
    }
    response = parse_completion(json.dumps(odd).encode(), 0.1)
    assert (response.content, response.finish_reason, response.model) == ("", None, None)
    assert (response.prompt_tokens, response.completion_tokens) == (0, 0)
