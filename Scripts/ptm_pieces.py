"""Reading and writing the mesher's per-rank VTK XML pieces without VTK.

The solver runs under the system Python (/usr/bin/python3, where dolfinx and
petsc4py live), which has no VTK; meshio reads .vtu but not the boundary
.vtp, so this is a small reader of exactly what tetmesh.py writes: XML files
whose arrays are uncompressed, appended raw (tetmesh.py since session 15),
inline base64 (before, and this module's own writer) or ascii. Anything else
(base64-encoded appended or compressed data) is refused with a message
instead of being misread.
"""
import base64
import os
import re
import xml.etree.ElementTree as ET

import numpy as np

VTK_TYPES = {
    "Int8": np.int8, "UInt8": np.uint8, "Int16": np.int16, "UInt16": np.uint16,
    "Int32": np.int32, "UInt32": np.uint32, "Int64": np.int64, "UInt64": np.uint64,
    "Float32": np.float32, "Float64": np.float64,
}
VTK_TETRA = 10


class PieceError(RuntimeError):
    """A piece file that is missing, malformed or not what the mesher writes."""


def piece_sources(parallel_file):
    """The piece file names of a .pvtu/.pvtp, in piece (= rank) order."""
    try:
        root = ET.parse(parallel_file).getroot()
    except (OSError, ET.ParseError) as e:
        raise PieceError(f"cannot read {parallel_file}: {e}") from e
    base = os.path.dirname(os.path.abspath(parallel_file))
    sources = [os.path.join(base, p.get("Source")) for p in root.iter("Piece")]
    if not sources:
        raise PieceError(f"{parallel_file} lists no <Piece Source=...>")
    return sources


def _block(raw, start, header_type, name, path):
    """The bytes of one binary block at `start` of `raw`: a length header of
    `header_type`, then that many bytes (nothing may follow for inline data)."""
    hsize = np.dtype(header_type).itemsize
    if len(raw) < start + hsize:
        raise PieceError(f"{path}: array {name}: truncated binary data")
    nbytes = int(np.frombuffer(raw[start:start + hsize], dtype=header_type)[0])
    if len(raw) < start + hsize + nbytes:
        raise PieceError(f"{path}: array {name}: header says {nbytes} bytes, "
                         f"found {len(raw) - start - hsize}")
    return raw[start + hsize:start + hsize + nbytes], start + hsize + nbytes


def _decode(array, header_type, path, appended):
    """One <DataArray> as a numpy array (components as a second axis);
    `appended` is the raw bytes after the AppendedData's '_' (or None)."""
    name = array.get("Name", "?")
    dtype = VTK_TYPES.get(array.get("type"))
    if dtype is None:
        raise PieceError(f"{path}: array {name}: unsupported type {array.get('type')}")
    fmt = array.get("format", "ascii")
    text = (array.text or "").strip()
    if fmt == "ascii":
        values = np.array(text.split(), dtype=dtype)
    elif fmt == "binary":
        raw = base64.b64decode(text)
        data, end = _block(raw, 0, header_type, name, path)
        if end != len(raw):
            raise PieceError(f"{path}: array {name}: header says {len(data)} bytes, "
                             f"found {len(raw) - np.dtype(header_type).itemsize}")
        values = np.frombuffer(data, dtype=dtype).copy()
    elif fmt == "appended" and appended is not None:
        data, _ = _block(appended, int(array.get("offset", "0").strip()), header_type, name, path)
        values = np.frombuffer(data, dtype=dtype).copy()
    else:
        raise PieceError(f"{path}: array {name}: format '{fmt}' not supported "
                         "(tetmesh.py writes appended raw data)")
    ncomp = int(array.get("NumberOfComponents", "1"))
    return values.reshape(-1, ncomp) if ncomp > 1 else values


def _arrays(element, header_type, path, appended):
    if element is None:
        return {}
    return {a.get("Name"): _decode(a, header_type, path, appended) for a in element.findall("DataArray")}


def _parse(path):
    """The XML root of a piece and its appended raw bytes (None if it has
    none). Raw appended data is not XML, so the XML is the text before it,
    closed by hand."""
    try:
        with open(path, "rb") as f:
            content = f.read()
    except OSError as e:
        raise PieceError(f"cannot read piece {path}: {e}") from e
    tag = re.search(rb"<AppendedData([^>]*)>", content)
    try:
        if tag is None:
            return ET.fromstring(content), None
        if b'encoding="raw"' not in tag.group(1):
            raise PieceError(f"{path}: appended data that is not raw (base64) is not supported")
        underscore = content.index(b"_", tag.end())
        root = ET.fromstring(content[:tag.start()] + b"</VTKFile>")
    except (ET.ParseError, ValueError) as e:
        raise PieceError(f"cannot read piece {path}: {e}") from e
    return root, memoryview(content)[underscore + 1:]


def read_piece(path):
    """One .vtu or .vtp piece: points, the cell (or polygon) connectivity and
    offsets, cell types, and the point, cell and field data by name."""
    root, appended = _parse(path)
    if root.get("compressor"):
        raise PieceError(f"{path}: compressed data ({root.get('compressor')}) not supported")
    header_type = {"UInt64": np.uint64, "UInt32": np.uint32}[root.get("header_type", "UInt32")]
    grid = root[0]
    pieces = grid.findall("Piece")
    if len(pieces) != 1:
        raise PieceError(f"{path}: expected one <Piece>, found {len(pieces)}")
    piece = pieces[0]
    topo = piece.find("Cells") if root.get("type") == "UnstructuredGrid" else piece.find("Polys")
    if piece.find("Points") is None or topo is None:
        raise PieceError(f"{path}: no Points or Cells/Polys section")
    cells = _arrays(topo, header_type, path, appended)
    points = _arrays(piece.find("Points"), header_type, path, appended)
    return {
        "points": next(iter(points.values())).reshape(-1, 3).astype(np.float64)
        if points else np.zeros((0, 3)),
        "connectivity": cells.get("connectivity", np.zeros(0, np.int64)).astype(np.int64),
        "offsets": cells.get("offsets", np.zeros(0, np.int64)).astype(np.int64),
        "types": cells.get("types"),
        "point_data": _arrays(piece.find("PointData"), header_type, path, appended),
        "cell_data": _arrays(piece.find("CellData"), header_type, path, appended),
        "field_data": _arrays(grid.find("FieldData"), header_type, path, appended),
        "bytes": os.path.getsize(path),
    }


def fixed_size_cells(piece, size, what, path):
    """The connectivity as an (n, size) array, refusing other cell sizes."""
    off = piece["offsets"]
    n = len(off)
    if n and not np.array_equal(off, size * np.arange(1, n + 1)):
        raise PieceError(f"{path}: {what}: not every cell has {size} points")
    return piece["connectivity"].reshape(n, size)


def _b64(values):
    data = np.ascontiguousarray(values).tobytes()
    return base64.b64encode(np.uint64(len(data)).tobytes() + data).decode("ascii")


def _xml_array(name, values):
    values = np.asarray(values)
    vtk_type = {np.dtype(v): k for k, v in VTK_TYPES.items()}[values.dtype]
    ncomp = values.shape[1] if values.ndim == 2 else 1
    return (f'<DataArray type="{vtk_type}" Name="{name}" NumberOfComponents="{ncomp}" '
            f'format="binary">{_b64(values)}</DataArray>\n')


def write_tetra_piece(path, points, tets, point_data, cell_data):
    """One .vtu piece of linear tetrahedra with inline binary arrays (which
    read_piece reads as well as the raw appended ones tetmesh.py writes)."""
    n, m = len(points), len(tets)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n<UnstructuredGrid>\n'
                f'<Piece NumberOfPoints="{n}" NumberOfCells="{m}">\n<PointData>\n')
        for name, values in point_data.items():
            f.write(_xml_array(name, values))
        f.write("</PointData>\n<CellData>\n")
        for name, values in cell_data.items():
            f.write(_xml_array(name, values))
        f.write("</CellData>\n<Points>\n" + _xml_array("Points", points.astype(np.float64)))
        f.write("</Points>\n<Cells>\n")
        f.write(_xml_array("connectivity", tets.astype(np.int64).ravel()))
        f.write(_xml_array("offsets", 4 * np.arange(1, m + 1, dtype=np.int64)))
        f.write(_xml_array("types", np.full(m, VTK_TETRA, np.uint8)))
        f.write("</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")


def write_pvtu(path, piece_names, point_data, cell_data):
    """The .pvtu index of the pieces; point_data/cell_data map name to
    (VTK type, number of components)."""
    def decl(arrays):
        return "".join(f'<PDataArray type="{t}" Name="{k}" NumberOfComponents="{c}"/>\n'
                       for k, (t, c) in arrays.items())
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n'
                '<PUnstructuredGrid GhostLevel="0">\n')
        f.write('<PPointData GlobalIds="GlobalPointIds">\n' + decl(point_data) + "</PPointData>\n")
        f.write("<PCellData>\n" + decl(cell_data) + "</PCellData>\n")
        f.write('<PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n')
        for name in piece_names:
            f.write(f'<Piece Source="{name}"/>\n')
        f.write("</PUnstructuredGrid>\n</VTKFile>\n")
