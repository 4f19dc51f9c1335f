"""A small BERT sentence encoder in plain PyTorch, for all-MiniLM-L6-v2 and its kind.

sentence-transformers imports transformers and much more: 7-9 s on a small CPU before the first
embedding, against about 0.3 s to load MiniLM and encode. This module runs the same pipeline with
only ``tokenizers`` (a small Rust package), ``safetensors`` and ``torch``:

1. the model's fast tokenizer (``tokenizer.json``), truncated to ``max_seq_length``
   (``sentence_bert_config.json``), each batch padded to its longest text;
2. a BERT encoder as in Hugging Face's ``BertModel`` (word + position + token-type embeddings,
   LayerNorm, then self-attention / GELU feed-forward layers with post-LayerNorms);
3. mean pooling over the attention mask, then L2 normalisation.

Its vectors match sentence-transformers' to float32 rounding (see
``tests/retrieval/test_minilm.py``). :func:`supports` says whether a model folder has exactly this
shape; any other folder is left to sentence-transformers. torch is imported on first use.
"""

from __future__ import annotations

import json
import math
import threading
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from holomj.errors import InputError

if TYPE_CHECKING:
    import torch

BATCH_SIZE = 64
# A batch also stops growing once (texts x longest text) reaches this many tokens: texts are
# sorted by length, so a few long ones are not run with 60 short ones padded to their length.
BATCH_TOKENS = 2048
# Work this small (texts x longest text, in tokens: one query) runs on one thread: spreading a
# few hundred multiply-adds over several threads costs more in synchronisation than it saves,
# and much more on a busy machine (one query: 20 ms on one thread, 140-460 ms on two, measured
# on a loaded 2-core host).
SINGLE_THREAD_TOKENS = 256
_TRANSFORMER = "sentence_transformers.models.Transformer"
_POOLING = "sentence_transformers.models.Pooling"
_NORMALIZE = "sentence_transformers.models.Normalize"
_WEIGHT_FILES = ("model.safetensors", "pytorch_model.bin")


def _read_json(path: Path) -> Any:
    return json.loads(path.read_text(encoding="utf-8"))


def _weights_file(folder: Path) -> Path | None:
    for name in _WEIGHT_FILES:
        if (folder / name).is_file():
            return folder / name
    return None


def supports(model_path: str | Path) -> bool:
    """Whether ``model_path`` is a sentence-transformers folder this encoder reproduces exactly.

    That is: modules Transformer (a BERT with absolute positions and GELU at the folder's root,
    with a ``tokenizer.json``), then mean-token Pooling, then optionally Normalize; no prompts.
    """
    folder = Path(model_path)
    try:
        modules = _read_json(folder / "modules.json")
        types = [m.get("type") for m in sorted(modules, key=lambda m: int(m.get("idx", 0)))]
        if types not in ([_TRANSFORMER, _POOLING], [_TRANSFORMER, _POOLING, _NORMALIZE]):
            return False
        if modules[0].get("path", "") not in ("", "."):
            return False
        pooling = _read_json(folder / modules[1]["path"] / "config.json")
        modes = {k: v for k, v in pooling.items() if k.startswith("pooling_mode") and v}
        if list(modes) != ["pooling_mode_mean_tokens"] or pooling.get("include_prompt") is False:
            return False
        config = _read_json(folder / "config.json")
        if (
            config.get("model_type") != "bert"
            or config.get("hidden_act", "gelu") != "gelu"
            or config.get("position_embedding_type", "absolute") != "absolute"
        ):
            return False
        st_config = folder / "config_sentence_transformers.json"
        if st_config.is_file():
            extra = _read_json(st_config)
            if extra.get("prompts") or extra.get("default_prompt_name"):
                return False
        return (folder / "tokenizer.json").is_file() and _weights_file(folder) is not None
    except (OSError, ValueError, TypeError, KeyError, IndexError, AttributeError):
        return False


class MiniLMEncoder:
    """A BERT mean-pooling sentence encoder (e.g. all-MiniLM-L6-v2), run on the CPU in float32."""

    def __init__(
        self, model_path: str | Path, name: str | None = None, batch_size: int = BATCH_SIZE
    ) -> None:
        folder = Path(model_path)
        if not folder.is_dir():
            raise InputError("text model folder not found", where=str(folder))
        try:
            self._load(folder)
        except InputError:
            raise
        except Exception as err:  # a broken model folder: name it, in one line
            raise InputError(
                f"cannot load the text model: {type(err).__name__}: {err}".splitlines()[0],
                where=str(folder),
            ) from None
        self.name = name or folder.name
        self.batch_size = max(1, int(batch_size))
        self._lock = threading.Lock()

    def _load(self, folder: Path) -> None:
        import torch
        from tokenizers import Tokenizer

        config = _read_json(folder / "config.json")
        self.dim = int(config["hidden_size"])
        self._heads = int(config["num_attention_heads"])
        self._layers = int(config["num_hidden_layers"])
        self._eps = float(config.get("layer_norm_eps", 1e-12))
        max_positions = int(config.get("max_position_embeddings", 512))
        st_path = folder / "sentence_bert_config.json"
        st_config = _read_json(st_path) if st_path.is_file() else {}
        self.max_length = min(int(st_config.get("max_seq_length") or max_positions), max_positions)
        self._lower = bool(st_config.get("do_lower_case", False))

        tokenizer = Tokenizer.from_file(str(folder / "tokenizer.json"))
        tokenizer.no_padding()  # padding is done per length-sorted batch, below
        tokenizer.enable_truncation(max_length=self.max_length, strategy="longest_first")
        self._tokenizer = tokenizer
        self._pad_id = int(config.get("pad_token_id") or 0)

        weights_file = _weights_file(folder)
        if weights_file is None:
            raise InputError("the text model has no weights file", where=str(folder))
        if weights_file.suffix == ".safetensors":
            from safetensors.torch import load_file

            raw = load_file(str(weights_file), device="cpu")
        else:
            raw = torch.load(str(weights_file), map_location="cpu", weights_only=True)
        weights: dict[str, torch.Tensor] = {}
        for key, tensor in raw.items():
            key = key.removeprefix("bert.")
            if tensor.is_floating_point():
                tensor = tensor.to(torch.float32)
            weights[key] = tensor.contiguous()
        missing = [k for k in self._required_keys() if k not in weights]
        if missing:
            raise InputError(
                f"the text model lacks {len(missing)} weights, e.g. {missing[0]}",
                where=str(weights_file),
            )
        self._w = weights

    def _required_keys(self) -> list[str]:
        keys = [
            "embeddings.word_embeddings.weight",
            "embeddings.position_embeddings.weight",
            "embeddings.token_type_embeddings.weight",
            "embeddings.LayerNorm.weight",
            "embeddings.LayerNorm.bias",
        ]
        for i in range(self._layers):
            p = f"encoder.layer.{i}."
            for part in (
                "attention.self.query",
                "attention.self.key",
                "attention.self.value",
                "attention.output.dense",
                "attention.output.LayerNorm",
                "intermediate.dense",
                "output.dense",
                "output.LayerNorm",
            ):
                keys += [f"{p}{part}.weight", f"{p}{part}.bias"]
        return keys

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        """Normalised embeddings of ``texts`` (shape (n, dim), float32)."""
        if not texts:
            return np.zeros((0, self.dim), dtype=np.float32)
        import torch

        items = [str(t) for t in texts]
        if self._lower:
            items = [t.lower() for t in items]
        with self._lock:
            encodings = self._tokenizer.encode_batch(items)
            ids = [e.ids for e in encodings]
            order = sorted(range(len(ids)), key=lambda i: -len(ids[i]))
            out = np.empty((len(ids), self.dim), dtype=np.float32)
            threads = torch.get_num_threads()
            small = len(ids) * len(ids[order[0]]) <= SINGLE_THREAD_TOKENS
            if small and threads > 1:
                torch.set_num_threads(1)
            try:
                with torch.inference_mode():
                    for chosen in self._batches(order, [len(i) for i in ids]):
                        longest = len(ids[chosen[0]])
                        batch = np.full((len(chosen), longest), self._pad_id, dtype=np.int64)
                        mask = np.zeros((len(chosen), longest), dtype=bool)
                        for row, i in enumerate(chosen):
                            batch[row, : len(ids[i])] = ids[i]
                            mask[row, : len(ids[i])] = True
                        vectors = self._forward(torch.from_numpy(batch), torch.from_numpy(mask))
                        out[chosen] = vectors.numpy()
            finally:
                if small and threads > 1:
                    torch.set_num_threads(threads)
        return out

    def _batches(self, order: list[int], lengths: list[int]) -> list[list[int]]:
        """``order`` (longest first) cut into batches of at most ``batch_size`` texts and about
        ``BATCH_TOKENS`` padded tokens (a text longer than that gets a batch of its own)."""
        batches: list[list[int]] = []
        for i in order:
            if batches:
                last = batches[-1]
                rows = len(last) + 1
                if rows <= self.batch_size and rows * lengths[last[0]] <= BATCH_TOKENS:
                    last.append(i)
                    continue
            batches.append([i])
        return batches

    def _forward(self, ids: torch.Tensor, mask: torch.Tensor) -> torch.Tensor:
        """Pooled, normalised embeddings of one padded batch (``mask``: True on real tokens)."""
        import torch
        import torch.nn.functional as F

        w, eps = self._w, self._eps
        batch, length = ids.shape
        heads, width = self._heads, self.dim // self._heads
        x = (
            F.embedding(ids, w["embeddings.word_embeddings.weight"])
            + w["embeddings.position_embeddings.weight"][:length]
            + w["embeddings.token_type_embeddings.weight"][0]
        )
        x = F.layer_norm(
            x, (self.dim,), w["embeddings.LayerNorm.weight"], w["embeddings.LayerNorm.bias"], eps
        )
        # Additive mask as in BertModel: 0 on real tokens, the float32 minimum on padding.
        bias = torch.zeros((batch, 1, 1, length), dtype=x.dtype)
        bias.masked_fill_(~mask[:, None, None, :], torch.finfo(x.dtype).min)
        scale = 1.0 / math.sqrt(width)

        def split(t: torch.Tensor) -> torch.Tensor:
            return t.view(batch, length, heads, width).transpose(1, 2)

        for i in range(self._layers):
            p = f"encoder.layer.{i}."
            q = split(
                F.linear(
                    x, w[p + "attention.self.query.weight"], w[p + "attention.self.query.bias"]
                )
            )
            k = split(
                F.linear(x, w[p + "attention.self.key.weight"], w[p + "attention.self.key.bias"])
            )
            v = split(
                F.linear(
                    x, w[p + "attention.self.value.weight"], w[p + "attention.self.value.bias"]
                )
            )
            scores = torch.matmul(q, k.transpose(-1, -2)) * scale + bias
            context = torch.matmul(torch.softmax(scores, dim=-1), v)
            context = context.transpose(1, 2).reshape(batch, length, self.dim)
            attended = F.linear(
                context,
                w[p + "attention.output.dense.weight"],
                w[p + "attention.output.dense.bias"],
            )
            x = F.layer_norm(
                attended + x,
                (self.dim,),
                w[p + "attention.output.LayerNorm.weight"],
                w[p + "attention.output.LayerNorm.bias"],
                eps,
            )
            hidden = F.gelu(
                F.linear(x, w[p + "intermediate.dense.weight"], w[p + "intermediate.dense.bias"])
            )
            hidden = F.linear(hidden, w[p + "output.dense.weight"], w[p + "output.dense.bias"])
            x = F.layer_norm(
                hidden + x,
                (self.dim,),
                w[p + "output.LayerNorm.weight"],
                w[p + "output.LayerNorm.bias"],
                eps,
            )
        weights = mask.to(x.dtype).unsqueeze(-1)
        pooled = (x * weights).sum(dim=1) / weights.sum(dim=1).clamp(min=1e-9)
        return F.normalize(pooled, p=2.0, dim=1)
