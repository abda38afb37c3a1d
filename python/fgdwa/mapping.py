"""Where the robot's map comes from: ``"known"`` (the world's grid is the
map) or ``"scan"`` (the navigator builds it from its lidar's hits on the
grid's layout). The map itself lives in the C++ :class:`fgdwa.Navigator`.
"""

from __future__ import annotations

from fgdwa._core import FgdwaError
from fgdwa.file_limits import short_repr

MAPPING_MODES = ("known", "scan")


def check_mapping(mapping: str) -> str:
    """``mapping`` when it names a mode, else FgdwaError listing the modes."""
    if mapping not in MAPPING_MODES:
        raise FgdwaError(f"mapping = {short_repr(mapping)}: expected one of {', '.join(MAPPING_MODES)}")
    return mapping
