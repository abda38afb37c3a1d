import os
from pathlib import Path

import numpy as np
import pytest

import fgdwa
from fgdwa.io import load_barn

DEFAULT_BARN_DIR = Path("/work/shared/benchmarks/barn")


def barn_locations():
    """(barn.npz, the directory of the challenge's original files, where they were looked for):
    FGDWA_BARN_DATA (barn.npz or its directory), else the shared benchmark directory."""
    env = os.environ.get("FGDWA_BARN_DATA")
    base = Path(env) if env else DEFAULT_BARN_DIR
    npz = base if base.suffix == ".npz" else base / "barn.npz"
    return npz, npz.parent / "worlds", ("FGDWA_BARN_DATA" if env else "the default location")


@pytest.fixture(scope="session")
def barn_file():
    npz, _, where = barn_locations()
    if not npz.is_file():
        pytest.skip(f"BARN data not found: no {npz} ({where}); set FGDWA_BARN_DATA to barn.npz or its directory")
    return npz


@pytest.fixture(scope="session")
def barn(barn_file):
    return load_barn(barn_file)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


def random_block_grid(rng, rows=60, cols=80, blocks=12, max_size=8):
    """A grid with random rectangular obstacles, as uint8."""
    cells = np.zeros((rows, cols), dtype=np.uint8)
    for _ in range(blocks):
        r, c = rng.integers(0, rows), rng.integers(0, cols)
        h, w = rng.integers(1, max_size + 1, size=2)
        cells[r:r + h, c:c + w] = 1
    return cells


def brute_force_square_distance(points, cells, resolution, origin):
    """Exact distance from each point to the union of the occupied cells' squares."""
    rows, cols = np.nonzero(cells)
    cx = origin[0] + (cols + 0.5) * resolution
    cy = origin[1] + (rows + 0.5) * resolution
    dx = np.maximum(np.abs(points[:, :1] - cx) - resolution / 2, 0.0)
    dy = np.maximum(np.abs(points[:, 1:2] - cy) - resolution / 2, 0.0)
    return np.sqrt(dx ** 2 + dy ** 2).min(axis=1)


@pytest.fixture
def open_world():
    cells = np.zeros((50, 50), dtype=np.uint8)
    return fgdwa.OccupancyGrid(cells, 0.1)
