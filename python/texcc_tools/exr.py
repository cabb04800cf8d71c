"""The one OpenEXR reader and writer of the Python tools, pure Python + numpy.

texrender writes scanline EXRs of 32-bit float channels (B, G, R) with tinyexr, uncompressed
(images under 16x16) or ZIP (16 scanlines per zlib block); Blender writes 32-bit float RGBA and
multilayer files ("ViewLayer.Combined.R"...) the same way with color_depth "32". scripts/farm.py
reads its tiles with read_exr and writes stitched frames with write_exr (ZIP, the same
channels), which texrender's own reader (and texrender-compare) reads back. Other EXR features
(tiles, half floats, other compressions, multi-part) are refused with an error, not guessed.

read_exr(bytes) / read_file(path): RGB as float32 (height, width, 3), row 0 at the top.
read_channels(path): every channel by name. write_exr(rgb) / write_file(path, rgb): ZIP, B G R.
"""
import struct
import zlib

import numpy as np

MAGIC = 20000630
NO_COMPRESSION, ZIPS_COMPRESSION, ZIP_COMPRESSION = 0, 2, 3
LINES_PER_BLOCK = {NO_COMPRESSION: 1, ZIPS_COMPRESSION: 1, ZIP_COMPRESSION: 16}
FLOAT = 2


class ExrError(Exception):
    pass


def _attributes(data):
    """The header's attributes {name: (type, bytes)} and the offset after the header."""
    if len(data) < 8 or struct.unpack_from("<i", data, 0)[0] != MAGIC:
        raise ExrError("not an OpenEXR file")
    if struct.unpack_from("<i", data, 4)[0] & 0x1A00:
        raise ExrError("tiled, deep or multi-part EXR: not supported")  # 0x400: long names, fine
    pos, attrs = 8, {}
    while True:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        pos = end + 1
        if not name:
            return attrs, pos
        end = data.index(b"\0", pos)
        kind = data[pos:end].decode()
        size = struct.unpack_from("<i", data, end + 1)[0]
        pos = end + 5
        attrs[name] = (kind, data[pos:pos + size])
        pos += size


def _channels(raw):
    names, pos = [], 0
    while raw[pos:pos + 1] != b"\0":
        end = raw.index(b"\0", pos)
        names.append(raw[pos:end].decode())
        pixel_type = struct.unpack_from("<i", raw, end + 1)[0]
        if pixel_type != FLOAT:
            raise ExrError("channel %s is not 32-bit float" % names[-1])
        pos = end + 17
    return names


def _unpredict(block):
    """ZIP's inverse: undo the byte delta, then interleave the two halves."""
    d = np.frombuffer(block, dtype=np.uint8).astype(np.int64)
    d[1:] -= 128
    t = (np.cumsum(d) & 0xFF).astype(np.uint8)
    half = (len(t) + 1) // 2
    out = np.empty_like(t)
    out[0::2], out[1::2] = t[:half], t[half:]
    return out.tobytes()


def _predict(raw):
    b = np.frombuffer(raw, dtype=np.uint8)
    t = np.concatenate([b[0::2], b[1::2]]).astype(np.int64)
    d = t.copy()
    d[1:] = (t[1:] - t[:-1] + 128 + 256) & 0xFF
    return d.astype(np.uint8).tobytes()


def _planes(data):
    """The channel names and their pixels as float32 (height, channels, width)."""
    attrs, pos = _attributes(data)
    comp = attrs["compression"][1][0]
    if comp not in LINES_PER_BLOCK:
        raise ExrError("compression %d: not supported" % comp)
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"][1])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    names = _channels(attrs["channels"][1])
    lines = LINES_PER_BLOCK[comp]
    blocks = (h + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % blocks, data, pos)
    planes = np.zeros((h, len(names), w), dtype=np.float32)
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        block = data[off + 8:off + 8 + size]
        n = min(lines, y1 + 1 - y)
        expect = n * len(names) * w * 4
        if comp != NO_COMPRESSION and size < expect:
            block = _unpredict(zlib.decompress(block))
        if len(block) != expect:
            raise ExrError("a block of %d bytes where %d were expected" % (len(block), expect))
        planes[y - y0:y - y0 + n] = np.frombuffer(block, dtype="<f4").reshape(n, len(names), w)
    return names, planes


def read_channels(path):
    """{channel name: float32 (height, width)} of the EXR at path. A multi-part file (Blender's
    multilayer renders: a part per pass) is read with OpenEXR's Python bindings
    (bench/requirements.txt), its channels named PART-LAYER.PASS.C as Blender names them."""
    with open(path, "rb") as f:
        data = f.read()
    try:
        names, planes = _planes(data)
    except ExrError:
        if len(data) < 8 or not struct.unpack_from("<i", data, 4)[0] & 0x1A00:
            raise
        return _openexr_channels(path)
    return {name: planes[:, c, :] for c, name in enumerate(names)}


def _openexr_channels(path):
    """The channels of a tiled or multi-part file (Blender writes its EXRs so), through
    OpenEXR's Python bindings (bench/requirements.txt)."""
    try:
        import OpenEXR
    except ImportError:
        raise ExrError("tiled or multi-part EXR: needs OpenEXR's Python bindings "
                       "(pip install -r bench/requirements.txt)") from None
    out = {}
    with OpenEXR.File(path) as f:
        for part in f.parts:
            for name, c in part.channels.items():
                px = np.asarray(c.pixels, dtype=np.float32)
                if px.ndim == 2:
                    out[name] = px
                else:  # OpenEXR groups R, G, B(, A) of one pass
                    for k, comp in enumerate("RGBA"[:px.shape[2]]):
                        out["%s%s" % (name + "." if name not in ("RGB", "RGBA") else "", comp)] \
                            = px[:, :, k]
    return out


def read_exr(data):
    """An EXR's pixels as a float32 array (height, width, 3): R, G, B, row 0 at the top."""
    names, planes = _planes(data)
    h, w = planes.shape[0], planes.shape[2]
    rgb = np.zeros((h, w, 3), dtype=np.float32)
    for c, name in enumerate("RGB"):
        if name in names:
            rgb[:, :, c] = planes[:, names.index(name), :]
    return rgb


def _attribute(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def write_exr(rgb):
    """The bytes of a ZIP-compressed scanline EXR of rgb (height, width, 3) float32, channels
    B, G, R as texrender writes them."""
    h, w, _ = rgb.shape
    chans = b"".join(n + b"\0" + struct.pack("<iB3xii", FLOAT, 0, 1, 1) for n in (b"B", b"G", b"R"))
    box = struct.pack("<4i", 0, 0, w - 1, h - 1)
    header = struct.pack("<ii", MAGIC, 2) + b"".join([
        _attribute("channels", "chlist", chans + b"\0"),
        _attribute("compression", "compression", bytes([ZIP_COMPRESSION])),
        _attribute("dataWindow", "box2i", box),
        _attribute("displayWindow", "box2i", box),
        _attribute("lineOrder", "lineOrder", b"\0"),
        _attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
        _attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)),
        _attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)),
    ]) + b"\0"
    planar = np.ascontiguousarray(rgb[:, :, ::-1].transpose(0, 2, 1), dtype="<f4")  # y, BGR, x
    chunks = []
    for y in range(0, h, 16):
        raw = planar[y:y + 16].tobytes()
        packed = zlib.compress(_predict(raw))
        if len(packed) >= len(raw):
            packed = raw  # OpenEXR stores a block that does not shrink as it is
        chunks.append(struct.pack("<ii", y, len(packed)) + packed)
    pos = len(header) + 8 * len(chunks)
    offsets = []
    for c in chunks:
        offsets.append(pos)
        pos += len(c)
    return header + struct.pack("<%dQ" % len(offsets), *offsets) + b"".join(chunks)


def read_file(path):
    """read_exr of the file at path (a tiled or multi-part one through read_channels); an
    unreadable file is an ExrError naming it."""
    try:
        with open(path, "rb") as f:
            data = f.read()
        if len(data) >= 8 and struct.unpack_from("<i", data, 4)[0] & 0x1A00:
            ch = read_channels(path)
            return np.stack([ch[c] if c in ch else np.zeros_like(next(iter(ch.values())))
                             for c in "RGB"], axis=-1).astype(np.float32)
        return read_exr(data)
    except (OSError, ExrError, ValueError, struct.error, zlib.error) as e:
        raise ExrError("%s: %s" % (path, e.strerror if isinstance(e, OSError) else e)) from None


def write_file(path, rgb):
    """write_exr(rgb) into path, atomically (atomic.write_bytes)."""
    from texcc_tools.atomic import write_bytes
    write_bytes(path, write_exr(rgb))
