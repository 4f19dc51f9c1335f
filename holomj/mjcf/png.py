"""A small greyscale PNG encoder (the procedural textures are written with it): no image library
needed, and the bytes depend on nothing but the pixels."""

from __future__ import annotations

import struct
import zlib

import numpy as np


def png_bytes(image: np.ndarray) -> bytes:
    """Encode an (h, w) uint8 array as a greyscale PNG, choosing per row the filter (none, sub,
    up, average, Paeth) with the smallest sum of absolute values, as libpng does."""
    image = np.asarray(image, dtype=np.uint8)
    if image.ndim != 2:
        raise ValueError("png_bytes takes a 2-D greyscale image")
    height, width = image.shape
    raw = image.astype(np.int16)
    left = np.zeros_like(raw)
    left[:, 1:] = raw[:, :-1]
    up = np.zeros_like(raw)
    up[1:] = raw[:-1]
    up_left = np.zeros_like(raw)
    up_left[1:, 1:] = raw[:-1, :-1]
    p = left + up - up_left
    pa, pb, pc = np.abs(p - left), np.abs(p - up), np.abs(p - up_left)
    paeth = np.where((pa <= pb) & (pa <= pc), left, np.where(pb <= pc, up, up_left))
    candidates = np.stack([raw, raw - left, raw - up, raw - (left + up) // 2, raw - paeth]).astype(
        np.uint8
    )  # wraps modulo 256, as PNG filters do
    signed = candidates.astype(np.int8).astype(np.int16)
    best = np.argmin(np.abs(signed).sum(axis=2), axis=0)
    rows = candidates[best, np.arange(height)]
    scanlines = np.concatenate([best.astype(np.uint8)[:, None], rows], axis=1)
    data = zlib.compress(scanlines.tobytes(), 9)

    def chunk(kind: bytes, payload: bytes) -> bytes:
        body = kind + payload
        return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", data) + chunk(b"IEND", b"")
    )
