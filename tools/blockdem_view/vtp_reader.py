"""The body frames of a 3-D run (vtk/bodies.pvd and vtk/bodies_NNNNNN.vtp), read back for drawing.

A small reader of the one format src/io/vtk_3d_writer.cpp writes (VTK XML PolyData, ASCII: the
points, each face a polygon as connectivity and offsets, cell data `body`, `tilt_rad`,
`speed_m_s`), rather than Debian's python3-vtk9, which brings a few hundred MB of rendering
libraries to read three frames. numpy parses each array's text at once. Anything else (binary or
appended data, a missing array) is refused with the file named."""
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


class VtpFormatError(Exception):
    """A .vtp or .pvd file that is not what the 3-D writer writes."""


@dataclass
class BodyFrame:
    """Every body's faces at one time."""
    time_s: float               # [s]
    points_m: np.ndarray        # (n, 3) [m] world coordinates of the vertices
    connectivity: np.ndarray    # the point indices of every face, one face after another
    offsets: np.ndarray         # the end of each face in connectivity (VTK's convention)
    cell_data: dict = field(default_factory=dict)  # per face: body (index), tilt_rad, speed_m_s

    def face_starts(self):
        return np.concatenate(([0], self.offsets[:-1]))

    def face_sizes(self):
        return np.diff(np.concatenate(([0], self.offsets)))

    def face_body(self):
        """The body index of every face (the order of summary.json's bodies)."""
        return self.cell_data["body"].astype(int)


def read_collection(pvd_path):
    """[(time [s], .vtp path)] of a .pvd collection, in time order."""
    pvd_path = Path(pvd_path)
    try:
        root = ET.parse(pvd_path).getroot()
    except (ET.ParseError, OSError) as e:
        raise VtpFormatError(f"{pvd_path}: not a VTK collection: {e}") from e
    frames = []
    for data_set in root.iter("DataSet"):
        try:
            frames.append((float(data_set.get("timestep")), pvd_path.parent / data_set.get("file")))
        except (TypeError, ValueError) as e:
            raise VtpFormatError(f"{pvd_path}: a DataSet without a timestep or a file") from e
    return sorted(frames, key=lambda f: f[0])


def _values(array, path, dtype):
    if array.get("format", "ascii") != "ascii":
        raise VtpFormatError(f"{path}: array '{array.get('Name')}' is {array.get('format')}, not ascii")
    values = np.fromstring(array.text or "", dtype=dtype, sep=" ")
    return values


def read_body_frame(path, time_s):
    """The frame in one .vtp file written by the 3-D writer."""
    path = Path(path)
    try:
        piece = ET.parse(path).getroot().find("PolyData/Piece")
    except (ET.ParseError, OSError) as e:
        raise VtpFormatError(f"{path}: not a VTK PolyData file: {e}") from e
    if piece is None:
        raise VtpFormatError(f"{path}: no PolyData/Piece")
    points = piece.find("Points/DataArray")
    polys = {a.get("Name"): a for a in piece.findall("Polys/DataArray")}
    if points is None or "connectivity" not in polys or "offsets" not in polys:
        raise VtpFormatError(f"{path}: no Points, or Polys without connectivity and offsets")
    points_m = _values(points, path, float).reshape(-1, 3)
    connectivity = _values(polys["connectivity"], path, np.int64)
    offsets = _values(polys["offsets"], path, np.int64)
    cells = {a.get("Name"): _values(a, path, float) for a in piece.findall("CellData/DataArray")}
    if "body" not in cells:
        raise VtpFormatError(f"{path}: no cell array 'body'")
    counts = (int(piece.get("NumberOfPoints", -1)), int(piece.get("NumberOfPolys", -1)))
    if counts != (len(points_m), len(offsets)) or any(len(v) != len(offsets) for v in cells.values()) or \
            (len(offsets) and (offsets[-1] != len(connectivity) or connectivity.max() >= len(points_m))):
        raise VtpFormatError(f"{path}: the arrays do not match NumberOfPoints and NumberOfPolys")
    return BodyFrame(time_s, points_m, connectivity, offsets, cells)
