"""LLM configuration: arguments over environment over config file, and its errors."""

from __future__ import annotations

import os
from pathlib import Path
from types import SimpleNamespace

import pytest

from holomj.errors import FormatError, InputError
from holomj.plan import llm_config
from holomj.plan.llm_config import LLMConfig, default_config_file, load_llm_config

ENV_NAMES = (
    "HOLOMJ_LLM_BASE_URL",
    "HOLOMJ_LLM_MODEL",
    "HOLOMJ_LLM_API_KEY",
    "OPENAI_BASE_URL",
    "OPENAI_API_KEY",
)


@pytest.fixture(autouse=True)
def clean_env(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """No LLM variables from the caller's shell; an empty HOLOMJ_HOME of this test's own."""
    for name in ENV_NAMES:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("HOLOMJ_HOME", str(tmp_path / "home"))


def write_config(path: Path, body: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(body, encoding="utf-8")
    return path


def test_default_config_file_is_in_holomj_home(tmp_path: Path) -> None:
    assert default_config_file() == tmp_path / "home" / "config.toml"


def test_precedence_arguments_env_file(monkeypatch: pytest.MonkeyPatch) -> None:
    write_config(
        default_config_file(),
        '[llm]\nbase_url = "http://file:1/v1"\nmodel = "file-model"\napi_key = "file-key"\n'
        "timeout_s = 12\nmax_retries = 4\ntemperature = 0.7\nmax_tokens = 2048\nbackoff_s = 0\n",
    )
    config = load_llm_config()
    assert (config.base_url, config.model, config.api_key) == (
        "http://file:1/v1",
        "file-model",
        "file-key",
    )
    assert (config.timeout_s, config.max_retries, config.temperature) == (12.0, 4, 0.7)
    assert (config.max_tokens, config.backoff_s) == (2048, 0.0)
    assert isinstance(config.timeout_s, float) and isinstance(config.max_retries, int)

    monkeypatch.setenv("OPENAI_BASE_URL", "http://openai-env:2/v1")
    monkeypatch.setenv("OPENAI_API_KEY", "openai-key")
    config = load_llm_config()
    assert (config.base_url, config.api_key) == ("http://openai-env:2/v1", "openai-key")

    monkeypatch.setenv("HOLOMJ_LLM_BASE_URL", "http://holomj-env:3/v1/")
    monkeypatch.setenv("HOLOMJ_LLM_MODEL", "env-model")
    monkeypatch.setenv("HOLOMJ_LLM_API_KEY", "holomj-key")
    config = load_llm_config()
    assert (config.base_url, config.model, config.api_key) == (
        "http://holomj-env:3/v1",
        "env-model",
        "holomj-key",
    )
    assert config.timeout_s == 12.0  # numbers still come from the file

    config = load_llm_config(base_url="http://arg:4/v1", model="arg-model", api_key="arg-key")
    assert (config.base_url, config.model, config.api_key) == (
        "http://arg:4/v1",
        "arg-model",
        "arg-key",
    )
    assert config.endpoint == "http://arg:4/v1/chat/completions"


def test_given_config_file_replaces_the_default(tmp_path: Path) -> None:
    write_config(default_config_file(), '[llm]\nmodel = "default-file"\n')
    other = write_config(
        tmp_path / "other.toml", '[llm]\nbase_url = "http://localhost:11434/v1"\nmodel = "o"\n'
    )
    config = load_llm_config(config_file=other)
    assert (config.base_url, config.model, config.api_key) == (
        "http://localhost:11434/v1",
        "o",
        None,
    )


def test_missing_settings_name_the_variables_and_the_file() -> None:
    with pytest.raises(InputError) as info:
        load_llm_config(model="m")
    message = str(info.value)
    assert info.value.exit_code == 2 and "\n" not in message
    assert "no LLM base url configured" in message
    assert "HOLOMJ_LLM_BASE_URL or OPENAI_BASE_URL" in message
    assert str(default_config_file()) in message
    with pytest.raises(InputError, match="HOLOMJ_LLM_MODEL"):
        load_llm_config(base_url="http://localhost:8000/v1")


@pytest.mark.parametrize(
    ("body", "error", "text"),
    [
        ("[llm\n", FormatError, "invalid TOML"),
        ('llm = "x"\n', FormatError, "'llm' must be a table"),
        ("[llm]\nmodle = 'x'\n", FormatError, "llm.modle: unknown setting"),
        ("[llm]\nmodel = 3\n", FormatError, "llm.model: must be a string"),
        ("[llm]\ntimeout_s = 'slow'\n", InputError, "llm.timeout_s: must be a number"),
        ("[llm]\nmax_retries = 1.5\n", InputError, "llm.max_retries: must be an integer"),
        ("[llm]\nmax_retries = true\n", InputError, "llm.max_retries: must be an integer"),
        ("[llm]\ntemperature = 5\n", InputError, "outside [0, 2]"),
        ("[llm]\ntimeout_s = inf\n", InputError, "outside"),
    ],
)
def test_bad_config_files(tmp_path: Path, body: str, error: type, text: str) -> None:
    path = write_config(tmp_path / "c.toml", body)
    with pytest.raises(error) as info:
        load_llm_config(base_url="http://h/v1", model="m", config_file=path)
    assert text in str(info.value)
    assert str(path) in str(info.value)


def test_given_config_file_must_exist(tmp_path: Path) -> None:
    with pytest.raises(FormatError, match="config file not found"):
        load_llm_config(config_file=tmp_path / "missing.toml")


def test_python_310_skips_the_file(monkeypatch: pytest.MonkeyPatch) -> None:
    write_config(default_config_file(), '[llm]\nbase_url = "http://h/v1"\nmodel = "m"\n')
    monkeypatch.setattr(llm_config, "sys", SimpleNamespace(version_info=(3, 10, 14)))
    with pytest.raises(InputError, match=r"skipped: reading TOML needs Python 3\.11"):
        load_llm_config()
    assert load_llm_config(base_url="http://h/v1", model="m").model == "m"


@pytest.mark.parametrize("url", ["localhost:11434/v1", "ftp://h/v1", "http://", "http://h/v1?x=1"])
def test_base_url_must_be_http(url: str) -> None:
    with pytest.raises(InputError, match="is not an http"):
        LLMConfig(base_url=url, model="m")


def test_config_checks_values_and_hides_the_key() -> None:
    config = LLMConfig(base_url=" https://api.example.com/v1/ ", model="m", api_key="sk-secret")
    assert config.base_url == "https://api.example.com/v1"
    assert "sk-secret" not in repr(config)
    with pytest.raises(InputError, match="empty LLM model name"):
        LLMConfig(base_url="http://h", model=" ")
    with pytest.raises(InputError, match=r"llm\.max_retries"):
        LLMConfig(base_url="http://h", model="m", max_retries=-1)
    assert "HOLOMJ_LLM_BASE_URL" not in os.environ
