"""texexr: the few OpenEXR files texrender writes, read and written in pure Python + numpy.

texrender writes scanline EXRs of 32-bit float channels (B, G, R) with tinyexr, uncompressed
(images under 16x16) or ZIP (16 scanlines per zlib block). scripts/farm.py reads its tiles with
read_exr and writes stitched frames with write_exr (ZIP, the same channels), which texrender's
own reader (and texrender-compare) reads back. Other EXR features (tiles, half floats, other
compressions, multi-part) are refused with an error, not guessed.
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
    if struct.unpack_from("<i", data, 4)[0] & 0x1E00:
        raise ExrError("tiled, deep or multi-part EXR: not supported")
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


def read_exr(data):
    """An EXR's pixels as a float32 array (height, width, 3): R, G, B, row 0 at the top."""
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
