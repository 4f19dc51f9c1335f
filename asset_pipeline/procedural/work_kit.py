"""Shared palette of the work generators (``work_*.py``).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CHROME,
    STEEL,
)
from asset_pipeline.procedural.parts import RecipeMaterial

LAB_WHITE = RecipeMaterial("lab_white", (0.88, 0.89, 0.87, 1.0), 0.4, 0.4, "white")
OFFICE_GREY = RecipeMaterial("office_grey", (0.62, 0.63, 0.62, 1.0), 0.4, 0.4, "light grey")
PUTTY = RecipeMaterial("putty", (0.80, 0.78, 0.70, 1.0), 0.4, 0.4, "putty")
METAL_HANDLES = (CHROME, BLACK_METAL, STEEL)
NUMBER_WORDS = {
    1: "one",
    2: "two",
    3: "three",
    4: "four",
    5: "five",
    6: "six",
    7: "seven",
    8: "eight",
}
