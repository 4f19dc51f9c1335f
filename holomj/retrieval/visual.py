"""The visual term V: CLIP similarity between a description and an asset's thumbnails.

Everything below the model is ours and works with any CLIP-like model, an object offering
``encode_image(images)`` (a float tensor of shape (n, 3, S, S)) and ``encode_text(tokens)``,
plus a tokenizer mapping a list of strings to the tokens ``encode_text`` takes:

- image preprocessing with PIL and numpy (alpha over white, shortest side resized to S with
  bicubic filtering, centre crop, CLIP's mean/std normalisation), batching;
- L2-normalised embeddings as numpy arrays, cosine scores, and the aggregation over an asset's
  thumbnails (the best-matching view, as Holodeck does);
- caching of image embeddings (done by the retriever, see :mod:`holomj.retrieval.cache`).

The open_clip adapter (:func:`open_clip_scorer`) only creates the model and tokenizer from a
local weights file: open-clip-torch is an optional extra (``pip install 'holomj[clip]'``),
imported here lazily, and no weights are ever downloaded. Configure them with
``HOLOMJ_CLIP_WEIGHTS`` (a local ``.bin``/``.pt``/``.safetensors`` file) and
``HOLOMJ_CLIP_MODEL`` (the architecture, default ``ViT-B-32``).
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from holomj.errors import InputError

CLIP_WEIGHTS_ENV = "HOLOMJ_CLIP_WEIGHTS"
CLIP_MODEL_ENV = "HOLOMJ_CLIP_MODEL"
DEFAULT_CLIP_MODEL = "ViT-B-32"
CLIP_MEAN = (0.48145466, 0.4578275, 0.40821073)
CLIP_STD = (0.26862954, 0.26130258, 0.27577711)
PROMPT_TEMPLATE = "a 3D model of {}"
CLIP_EXTRA_FIX = "pip install 'holomj[clip]' (open-clip-torch), or leave HOLOMJ_CLIP_WEIGHTS unset"


class ClipLikeModel(Protocol):
    """What the scorer needs of a CLIP model (open_clip's models qualify)."""

    def encode_image(self, images: Any) -> Any:
        """Image embeddings, shape (n, d), for a float tensor of shape (n, 3, S, S)."""
        ...

    def encode_text(self, tokens: Any) -> Any:
        """Text embeddings, shape (n, d), for the tokenizer's output."""
        ...


Tokenizer = Callable[[list[str]], Any]


def load_rgb(path: Path) -> Any:
    """An image file as an RGB PIL image, transparent pixels laid over white."""
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(path) as img:
            img.load()
            if img.mode in ("RGBA", "LA", "P") or "transparency" in img.info:
                rgba = img.convert("RGBA")
                white = Image.new("RGBA", rgba.size, (255, 255, 255, 255))
                return Image.alpha_composite(white, rgba).convert("RGB")
            return img.convert("RGB")
    except (OSError, UnidentifiedImageError, ValueError) as err:
        raise InputError(f"cannot read image: {err}", where=str(path)) from None


def preprocess(image: Any, size: int) -> np.ndarray:
    """CLIP's preprocessing of a PIL image: (3, size, size) float32, normalised per channel."""
    from PIL import Image

    width, height = image.size
    scale = size / min(width, height)
    resized = image.resize(
        (max(size, round(width * scale)), max(size, round(height * scale))),
        Image.Resampling.BICUBIC,
    )
    left = (resized.width - size) // 2
    top = (resized.height - size) // 2
    crop = resized.crop((left, top, left + size, top + size))
    unit = np.asarray(crop, dtype=np.float32) / 255.0
    pixels = (unit - np.asarray(CLIP_MEAN, np.float32)) / np.asarray(CLIP_STD, np.float32)
    return np.ascontiguousarray(pixels.transpose(2, 0, 1))


def normalise_rows(matrix: np.ndarray) -> np.ndarray:
    """Rows scaled to unit length (zero rows stay zero), as float32."""
    matrix = np.asarray(matrix, dtype=np.float32)
    norms = np.linalg.norm(matrix, axis=1, keepdims=True)
    return matrix / np.where(norms > 0, norms, 1.0)


def best_view_score(query: np.ndarray, views: np.ndarray) -> float:
    """V of one asset: the highest cosine between the query and any of its thumbnails."""
    if views.shape[0] == 0:
        raise ValueError("an asset without thumbnails has no visual score")
    products = views.astype(np.float64) * np.asarray(query, dtype=np.float64)
    return float(np.max(products.sum(axis=1)))


class VisualScorer:
    """Embeds thumbnails and descriptions with a CLIP-like model on the CPU.

    ``name`` identifies model and weights (it names the embedding cache file), ``image_size``
    is the model's input resolution, ``template`` wraps descriptions (Holodeck's prompt).
    """

    def __init__(
        self,
        model: ClipLikeModel,
        tokenizer: Tokenizer,
        *,
        name: str,
        image_size: int = 224,
        batch_size: int = 16,
        template: str = PROMPT_TEMPLATE,
    ) -> None:
        if image_size < 8 or batch_size < 1:
            raise ValueError("image_size must be >= 8 and batch_size >= 1")
        self.model = model
        self.tokenizer = tokenizer
        self.name = name
        self.image_size = int(image_size)
        self.batch_size = int(batch_size)
        self.template = template
        if hasattr(model, "eval"):
            model.eval()

    def encode_images(self, paths: Sequence[Path]) -> np.ndarray:
        """Normalised embeddings of image files, shape (len(paths), d), in batches."""
        import torch

        rows: list[np.ndarray] = []
        for start in range(0, len(paths), self.batch_size):
            batch = np.stack(
                [
                    preprocess(load_rgb(Path(p)), self.image_size)
                    for p in paths[start : start + self.batch_size]
                ]
            )
            with torch.no_grad():
                out = self.model.encode_image(torch.from_numpy(batch))
            rows.append(_to_numpy(out))
        if not rows:
            return np.zeros((0, 0), dtype=np.float32)
        return normalise_rows(np.concatenate(rows))

    def encode_texts(self, texts: Sequence[str]) -> np.ndarray:
        """Normalised embeddings of descriptions (wrapped in the template), shape (n, d)."""
        import torch

        if not texts:
            return np.zeros((0, 0), dtype=np.float32)
        prompts = [self.template.format(t) for t in texts]
        rows = []
        for start in range(0, len(prompts), self.batch_size):
            tokens = self.tokenizer(prompts[start : start + self.batch_size])
            with torch.no_grad():
                rows.append(_to_numpy(self.model.encode_text(tokens)))
        return normalise_rows(np.concatenate(rows))


def _to_numpy(tensor: Any) -> np.ndarray:
    out = tensor.detach().float().cpu().numpy() if hasattr(tensor, "detach") else tensor
    out = np.asarray(out, dtype=np.float32)
    if out.ndim != 2:
        raise ValueError(f"the CLIP model returned an array of shape {out.shape}, expected (n, d)")
    return out


def open_clip_scorer(weights: Path | str, arch: str = DEFAULT_CLIP_MODEL) -> VisualScorer:
    """A :class:`VisualScorer` of an open_clip architecture with weights from a local file.

    ``weights`` None-like values are not accepted: nothing is downloaded.
    """
    path = Path(weights).expanduser()
    if not path.is_file():
        raise InputError(
            "CLIP weights file not found",
            where=str(path),
            fix=f"point {CLIP_WEIGHTS_ENV} or --clip-weights at a local open_clip checkpoint",
        )
    open_clip = import_open_clip()
    try:
        model = open_clip.create_model(arch, pretrained=str(path))
        tokenizer = open_clip.get_tokenizer(arch)
    except Exception as err:  # unknown architecture, a checkpoint that does not fit: one line
        raise InputError(
            f"cannot load CLIP model {arch!r}: {type(err).__name__}: {err}".splitlines()[0],
            where=str(path),
            fix=f"check {CLIP_MODEL_ENV} names the architecture these weights are for",
        ) from None
    stat = path.stat()
    stamp = hashlib.sha256(f"{path.resolve()}:{stat.st_size}:{stat.st_mtime_ns}".encode())
    return VisualScorer(
        model,
        tokenizer,
        name=f"clip-{arch}-{stamp.hexdigest()[:12]}",
        image_size=model_image_size(model),
    )


def import_open_clip() -> Any:
    """The open_clip module, or an :class:`InputError` naming the ``clip`` extra."""
    try:
        import open_clip
    except Exception as err:  # ImportError, or a broken torchvision failing at import time
        raise InputError(
            f"open-clip is not usable ({type(err).__name__}: {err})".splitlines()[0],
            fix=CLIP_EXTRA_FIX,
        ) from None
    return open_clip


def model_image_size(model: Any) -> int:
    """The input resolution of a CLIP-like model (``model.visual.image_size``, else 224)."""
    size = getattr(getattr(model, "visual", None), "image_size", 224)
    if isinstance(size, (tuple, list)):
        size = size[0]
    return int(size)


def visual_scorer_from_env(
    weights: Path | str | None = None, arch: str | None = None
) -> VisualScorer | None:
    """The scorer for ``weights`` (else ``$HOLOMJ_CLIP_WEIGHTS``), or None when neither is set."""
    weights = weights if weights is not None else os.environ.get(CLIP_WEIGHTS_ENV) or None
    if weights is None:
        return None
    arch = arch or os.environ.get(CLIP_MODEL_ENV) or DEFAULT_CLIP_MODEL
    return open_clip_scorer(weights, arch)
