"""Benchmark data sets that fgdwa reads: maps, reference paths and scoring.

Only loaders and converters live here; the data itself is never part of the
package (see docs/barn.md for the BARN maps).
"""

from fgdwa.datasets.barn import (
    BARN_FIELD_SIZE,
    BarnDataset,
    BarnWorld,
    barn_score,
    find_barn_file,
    load_barn,
    parse_world_selection,
)
from fgdwa.datasets.barn_convert import convert_barn_worlds, fill_holes, read_barn_world

__all__ = [
    "BARN_FIELD_SIZE",
    "BarnDataset",
    "BarnWorld",
    "barn_score",
    "convert_barn_worlds",
    "fill_holes",
    "find_barn_file",
    "load_barn",
    "parse_world_selection",
    "read_barn_world",
]
