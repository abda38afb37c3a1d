"""Scenario maps: the occupancy grid (ASCII, PNG, .npy or empty), terrain
grades and obstacles missing from the map, rasterised onto one cell layout.

A map's resolution lies in [MIN_RESOLUTION, MAX_RESOLUTION], it has at most
MAX_MAP_CELLS cells and its corners lie within +-MAX_COORDINATE
(fgdwa.file_limits); the size of a map is checked from the numbers, the .npy
header or the PNG header before any cells are made."""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

from fgdwa import file_limits as limits
from fgdwa._core import FgdwaError, OccupancyGrid, TerrainGrid
from fgdwa.file_limits import clip, load_npy, short_repr
from fgdwa.io.scenario_values import ValueReader, join_key
from fgdwa.sim.world import World

_MAP_SOURCES = ("ascii", "png", "npy", "size")


class Layout:
    """The map's cells: shape, resolution, origin, and how many cells one ASCII character stands for."""

    def __init__(self, shape: tuple, resolution: float, origin: tuple, cells_per_char: int):
        self.shape = shape
        self.resolution = resolution
        self.origin = origin
        self.cells_per_char = cells_per_char

    @property
    def extent(self) -> tuple:
        rows, cols = self.shape
        x0, y0 = self.origin
        return x0, x0 + cols * self.resolution, y0, y0 + rows * self.resolution

    def describe(self) -> str:
        rows, cols = self.shape
        text = f"{rows} x {cols} cells"
        if self.cells_per_char > 1 and rows % self.cells_per_char == 0 and cols % self.cells_per_char == 0:
            text += f" = {rows // self.cells_per_char} rows x {cols // self.cells_per_char} characters " \
                    f"at cells_per_char {self.cells_per_char}"
        return text


class MapReader(ValueReader):
    """The map parts of a scenario document."""

    def occupancy_map(self, value: Any) -> tuple:
        key = "map"
        self.mapping(value, key, _MAP_SOURCES + ("resolution", "origin", "cells_per_char", "threshold", "border",
                                                 "rectangles"))
        sources = [s for s in _MAP_SOURCES if value.get(s) is not None]
        if len(sources) != 1:
            self.fail(key, sorted(value), f"give exactly one of {', '.join(_MAP_SOURCES)} (got "
                                          f"{', '.join(sources) or 'none'})")
        source = sources[0]
        resolution = self.number(value.get("resolution", 0.1), join_key(key, "resolution"),
                                 low=limits.MIN_RESOLUTION, high=limits.MAX_RESOLUTION)
        origin = self.point(value.get("origin", [0.0, 0.0]), join_key(key, "origin"))
        per_char = self.integer(value.get("cells_per_char", 1), join_key(key, "cells_per_char"), low=1)
        if value.get("threshold") is not None and source != "png":
            self.fail(join_key(key, "threshold"), value["threshold"], "applies to a png map only")
        skey = join_key(key, source)
        if source == "ascii":
            cells = self.ascii(value[source], skey, {"#": 1, ".": 0}, per_char)
        elif source == "png":
            threshold = self.number(value.get("threshold", 0.5), join_key(key, "threshold"), low=0.0, high=1.0)
            cells = self.png(value[source], skey, threshold)
        elif source == "npy":
            cells = self.npy(value[source], skey, allowed=(0, 1), what="0 (free) or 1 (obstacle)")
        else:
            size = value[source]
            if not isinstance(size, list) or len(size) != 2:
                self.fail(skey, size, "expected [width, height] in metres")
            size = [self.length(v, join_key(skey, i), positive=True) for i, v in enumerate(size)]
            shape = tuple(int(round(s / resolution)) for s in reversed(size))
            if min(shape) < 1:
                self.fail(skey, value[source], f"[width, height] must each hold at least one cell of {resolution} m")
            self.map_cells(shape, skey, value[source])
            cells = np.zeros(shape, dtype=np.uint8)
        layout = Layout(cells.shape, resolution, origin, per_char)
        x0, x1, y0, y1 = layout.extent
        if max(abs(x0), abs(x1), abs(y0), abs(y1)) > limits.MAX_COORDINATE:
            self.fail(key, {"origin": list(origin), "resolution": resolution, "cells": list(cells.shape)},
                      f"the map spans x {x0:g} to {x1:g}, y {y0:g} to {y1:g}: its corners must lie within "
                      f"+-{limits.MAX_COORDINATE:g} m (fgdwa.file_limits.MAX_COORDINATE)")
        if self.boolean(value.get("border", False), join_key(key, "border")):
            cells[0, :] = cells[-1, :] = 1
            cells[:, 0] = cells[:, -1] = 1
        for i, rect in enumerate(self.list_of(value.get("rectangles"), join_key(key, "rectangles"))):
            self.paint(cells, layout, rect, join_key(join_key(key, "rectangles"), i), 1)
        grid = self.core(key, source, lambda: OccupancyGrid(cells, resolution, origin))
        return grid, layout

    def map_cells(self, shape: tuple, key: str, value: Any) -> None:
        """Refuses a map layer of more than MAX_MAP_CELLS cells, before it is made."""
        cells = int(np.prod([int(n) for n in shape], dtype=object))
        if cells > limits.MAX_MAP_CELLS:
            self.fail(key, value, f"{' x '.join(str(int(n)) for n in shape)} = {cells} cells, over "
                                  f"{limits.MAX_MAP_CELLS} (fgdwa.file_limits.MAX_MAP_CELLS)")

    def ascii(self, text: Any, key: str, alphabet: dict, per_char: int) -> np.ndarray:
        """Rows of characters, the first text row the highest y: returned with row 0 at the bottom."""
        self.string(text, key)
        lines = [line.rstrip() for line in text.splitlines()]
        while lines and not lines[0]:
            lines.pop(0)
        while lines and not lines[-1]:
            lines.pop()
        if not lines:
            self.fail(key, text, "empty")
        width = len(lines[0])
        self.map_cells((len(lines) * per_char, width * per_char), key, f"<{len(lines)} rows of {width} characters "
                                                                     f"at cells_per_char {per_char}>")
        for r, line in enumerate(lines):
            if len(line) != width:
                self.fail(key, line, f"text row {r + 1} (from the top) has {len(line)} characters, "
                                     f"the first row {width}: every row must be as wide")
            for c, char in enumerate(line):
                if char not in alphabet:
                    self.fail(key, char, f"at text row {r + 1} (from the top), column {c + 1}: expected one of "
                                         f"{' '.join(repr(a) for a in alphabet)}")
        cells = np.array([[alphabet[ch] for ch in line] for line in lines], dtype=np.uint8)
        cells = np.flipud(cells)
        if per_char > 1:
            cells = np.kron(cells, np.ones((per_char, per_char), dtype=np.uint8))
        return np.ascontiguousarray(cells)

    def png(self, value: Any, key: str, threshold: float) -> np.ndarray:
        import matplotlib.image

        path = self.file(value, key, (".png",))
        try:
            import PIL.Image

            with PIL.Image.open(path) as header:  # reads the size, not the pixels
                width, height = header.size
        except Exception as error:  # PIL raises many kinds for a bad file
            self.fail(key, value, f"cannot read the image ({clip(error)})")
        self.map_cells((height, width), key, value)
        try:
            image = np.asarray(matplotlib.image.imread(path), dtype=float)
        except Exception as error:  # matplotlib/PIL raise many kinds for a bad file
            self.fail(key, value, f"cannot read the image ({clip(error)})")
        if image.max(initial=0) > 1.0:
            image = image / 255.0
        if image.ndim == 2:
            luminance, alpha = image, None
        elif image.ndim == 3 and image.shape[2] in (3, 4):
            luminance = image[..., :3] @ np.array([0.299, 0.587, 0.114])
            alpha = image[..., 3] if image.shape[2] == 4 else None
        elif image.ndim == 3 and image.shape[2] in (1, 2):
            luminance = image[..., 0]
            alpha = image[..., 1] if image.shape[2] == 2 else None
        else:
            self.fail(key, value, f"unexpected image shape {image.shape}")
        dark = luminance < threshold
        if alpha is not None:
            dark &= alpha >= 0.5  # transparent pixels are free
        return np.ascontiguousarray(np.flipud(dark).astype(np.uint8))

    def npy(self, value: Any, key: str, allowed: tuple, what: str) -> np.ndarray:
        path = self.file(value, key, (".npy",))
        try:
            shape, _ = limits.npy_shape(path, str(path))
        except (FgdwaError, OSError) as error:
            self.fail(key, value, f"cannot read the array ({clip(error, 1000)})")
        if len(shape) == 2:
            self.map_cells(shape, key, value)
        try:
            array = load_npy(path, str(path))
        except FgdwaError as error:
            self.fail(key, value, f"cannot read the array ({clip(error, 1000)})")
        if array.ndim != 2 or min(array.shape) < 1:
            self.fail(key, value, f"expected a 2-D array, got shape {array.shape}")
        if array.dtype.kind not in "biuf":
            self.fail(key, value, f"expected numbers, got dtype {array.dtype}")
        bad = ~np.isin(array, allowed)
        if bad.any():
            r, c = np.argwhere(bad)[0]
            self.fail(key, value, f"cell [{r}, {c}] = {short_repr(array[r, c])}: every cell must be {what}")
        return np.ascontiguousarray(array.astype(np.uint8))

    def same_layout(self, cells: np.ndarray, layout: Layout, key: str, value: Any, per_char_text: bool):
        if cells.shape != layout.shape:
            if per_char_text:
                rows, cols = cells.shape[0] // layout.cells_per_char, cells.shape[1] // layout.cells_per_char
                got = f"{rows} rows x {cols} characters (= {cells.shape[0]} x {cells.shape[1]} cells)"
            else:
                got = f"shape {cells.shape[0]} x {cells.shape[1]}"
            self.fail(key, value, f"{got} differs from the map's layout ({layout.describe()})")

    def rect(self, value: Any, key: str, layout: Layout, extra: int = 0) -> list:
        if not isinstance(value, (list, tuple)) or len(value) != 4 + extra:
            shape = "[x0, y0, x1, y1, grade]" if extra else "[x0, y0, x1, y1]"
            self.fail(key, value, f"expected {shape} (corners in metres)")
        x0, y0, x1, y1 = (self.number(v, join_key(key, i)) for i, v in enumerate(value[:4]))
        if not (x0 < x1 and y0 < y1):
            self.fail(key, value, "expected x0 < x1 and y0 < y1")
        ex0, ex1, ey0, ey1 = layout.extent
        slack = 0.5 * layout.resolution
        if x0 < ex0 - slack or x1 > ex1 + slack or y0 < ey0 - slack or y1 > ey1 + slack:
            self.fail(key, value, f"outside the map (x {ex0:g} to {ex1:g}, y {ey0:g} to {ey1:g})")
        return [x0, y0, x1, y1]

    def paint(self, cells: np.ndarray, layout: Layout, value: Any, key: str, fill: Optional[int]) -> None:
        """Sets the cells of a rectangle (the cells whose centres it covers; at least one per axis)."""
        extra = 1 if fill is None else 0
        x0, y0, x1, y1 = self.rect(value, key, layout, extra)
        if fill is None:
            fill = self.integer(value[4], join_key(key, 4), low=0)
            if fill > 4:
                self.fail(join_key(key, 4), fill, "a slope grade must be 0-4")
        ox, oy = layout.origin
        res = layout.resolution
        rows, cols = layout.shape
        c0, c1 = int(round((x0 - ox) / res)), int(round((x1 - ox) / res))
        r0, r1 = int(round((y0 - oy) / res)), int(round((y1 - oy) / res))
        c1, r1 = max(c1, c0 + 1), max(r1, r0 + 1)
        cells[max(r0, 0):min(r1, rows), max(c0, 0):min(c1, cols)] = fill

    def terrain(self, value: Any, layout: Layout) -> tuple:
        default_factors = World.__dataclass_fields__["passing_factors"].default
        if value is None:
            return None, default_factors
        key = "terrain"
        self.mapping(value, key, ("ascii", "npy", "rectangles", "passing_factors"))
        if value.get("ascii") is not None and value.get("npy") is not None:
            self.fail(key, sorted(value), "give ascii or npy, not both")
        grades = np.zeros(layout.shape, dtype=np.uint8)
        if value.get("ascii") is not None:
            alphabet = {str(g): g for g in range(5)}
            alphabet["."] = 0
            grades = self.ascii(value["ascii"], join_key(key, "ascii"), alphabet, layout.cells_per_char)
            self.same_layout(grades, layout, join_key(key, "ascii"), value["ascii"], per_char_text=True)
        elif value.get("npy") is not None:
            grades = self.npy(value["npy"], join_key(key, "npy"), allowed=(0, 1, 2, 3, 4), what="a slope grade 0-4")
            self.same_layout(grades, layout, join_key(key, "npy"), value["npy"], per_char_text=False)
        for i, rect in enumerate(self.list_of(value.get("rectangles"), join_key(key, "rectangles"))):
            self.paint(grades, layout, rect, join_key(join_key(key, "rectangles"), i), None)
        factors = default_factors
        if value.get("passing_factors") is not None:
            fkey = join_key(key, "passing_factors")
            raw = value["passing_factors"]
            if not isinstance(raw, list) or len(raw) != 5:
                self.fail(fkey, raw, "expected 5 numbers in [0, 1], one per grade 0-4")
            factors = tuple(self.number(v, join_key(fkey, i), low=0.0, high=1.0) for i, v in enumerate(raw))
        grid = self.core(key, "terrain", lambda: TerrainGrid(grades, layout.resolution, layout.origin))
        return grid, factors

    def unknown_obstacles(self, value: Any, layout: Layout) -> Optional[OccupancyGrid]:
        if value is None:
            return None
        key = "unknown_obstacles"
        if isinstance(value, list):
            value = {"rectangles": value}
            rect_key = key
        else:
            self.mapping(value, key, ("rectangles", "ascii", "npy"))
            rect_key = join_key(key, "rectangles")
        cells = np.zeros(layout.shape, dtype=np.uint8)
        if value.get("ascii") is not None:
            cells = self.ascii(value["ascii"], join_key(key, "ascii"), {"#": 1, ".": 0}, layout.cells_per_char)
            self.same_layout(cells, layout, join_key(key, "ascii"), value["ascii"], per_char_text=True)
        if value.get("npy") is not None:
            layer = self.npy(value["npy"], join_key(key, "npy"), allowed=(0, 1), what="0 (free) or 1 (obstacle)")
            self.same_layout(layer, layout, join_key(key, "npy"), value["npy"], per_char_text=False)
            cells |= layer
        for i, rect in enumerate(self.list_of(value.get("rectangles"), rect_key)):
            self.paint(cells, layout, rect, join_key(rect_key, i), 1)
        return self.core(key, "unknown_obstacles", lambda: OccupancyGrid(cells, layout.resolution, layout.origin))
