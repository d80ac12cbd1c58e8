#!/usr/bin/env python3
"""Writes the oversized-input reproducers: images whose headers declare far more
texels than their bytes hold (decompression bombs), a PNG whose text chunks inflate
to 126 MB, a meshopt file whose fallback buffer declares 1.8 GB, and Draco streams
whose headers declare millions of triangles their bytes do not hold.
tests/texture/texel_budget_test.cpp,
tests/scene/oversized_input_test.cpp and tests/cli/memory_limit_test.sh read them.
Run from this directory:
    python3 make_oversized.py
"""
import base64, json, struct, zlib

def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

def png(width, height, rows=None):
    """An 8-bit RGBA PNG; `rows` None leaves the IDAT a few bytes long (a bomb)."""
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    raw = rows if rows is not None else b"\0" * 8
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) +
            png_chunk(b"IDAT", zlib.compress(raw, 9)) + png_chunk(b"IEND", b""))

def jpeg(width, height):
    """A baseline greyscale JPEG header (quantisation table, frame, scan) and 16
    bytes of entropy-coded data; libjpeg supplies the standard Huffman tables."""
    dqt = b"\xff\xdb" + struct.pack(">H", 67) + b"\x00" + b"\x01" * 64
    sof = b"\xff\xc0" + struct.pack(">HBHHB", 11, 8, height, width, 1) + b"\x01\x11\x00"
    sos = b"\xff\xda" + struct.pack(">HB", 8, 1) + b"\x01\x00\x00\x3f\x00"
    return b"\xff\xd8" + dqt + sof + sos + b"\0" * 16 + b"\xff\xd9"

def webp_lossless(width, height):
    """A VP8L (lossless WebP) header declaring the size, then 17 bytes of nothing."""
    bits = (width - 1) | (height - 1) << 14 | 1 << 28
    payload = b"\x2f" + struct.pack("<I", bits) + b"\0" * 17
    chunk = b"VP8L" + struct.pack("<I", len(payload)) + payload
    return b"RIFF" + struct.pack("<I", 4 + len(chunk)) + b"WEBP" + chunk

def zstd_zeros(size):
    """A Zstandard frame of RLE blocks inflating to `size` zero bytes (4 bytes per 128 KiB)."""
    block = 128 * 1024
    out = struct.pack("<I", 0xFD2FB528) + bytes([0x80, 0x38]) + struct.pack("<I", size)
    left = size
    while left:
        n = min(block, left)
        left -= n
        out += struct.pack("<I", n << 3 | 1 << 1 | (1 if left == 0 else 0))[:3] + b"\0"
    return out

def ktx2_uastc_zstd(side):
    """A Basis Universal KTX2 (UASTC, Zstandard) of side x side texels, one level."""
    blocks = ((side + 3) // 4) ** 2 * 16
    level = zstd_zeros(blocks)
    sample = struct.pack("<HBBI", 0, 127, 0, 0) + b"\0" * 8       # RGB, 128 bits
    block = (struct.pack("<IHH", 0, 2, 24 + len(sample)) +
             bytes([166, 1, 2, 0]) + bytes([3, 3, 0, 0]) + bytes([16] + [0] * 7) + sample)
    dfd = struct.pack("<I", 4 + len(block)) + block
    dfd_offset = 80 + 24
    level_offset = dfd_offset + len(dfd)
    header = (b"\xabKTX 20\xbb\r\n\x1a\n" +
              struct.pack("<IIIIIIIII", 0, 1, side, side, 0, 0, 1, 1, 2) +
              struct.pack("<IIII", dfd_offset, len(dfd), 0, 0) + struct.pack("<QQ", 0, 0) +
              struct.pack("<QQQ", level_offset, len(level), blocks))
    return header + dfd + level

def data_uri(blob):
    return "data:application/octet-stream;base64," + base64.b64encode(blob).decode()

def write_bytes(name, blob):
    with open(name, "wb") as f:
        f.write(blob)

def write_json(name, doc):
    with open(name, "w") as f:
        json.dump(doc, f, indent=1)

# --- images whose headers declare what their bytes do not hold --------------------
write_bytes("bomb_30000.png", png(30000, 30000))
write_bytes("bomb_65500.jpg", jpeg(65500, 65500))
write_bytes("bomb_16384.webp", webp_lossless(16384, 16384))
write_bytes("bomb_uastc_zstd.ktx2", ktx2_uastc_zstd(16384))
write_bytes("good_2x2.png", png(2, 2, (b"\0" + b"\x80\x40\x20\xff" * 2) * 2))
# A 2x2 PNG carrying 16 zTXt chunks of 7.7 KB, each inflating to 7.9 MB of text (just
# under libpng's default 8,000,000-byte chunk limit). libpng inflates and keeps every
# text chunk while it reads the header: 126 MB for 123 KB, unbounded in the count.
ztxt = png_chunk(b"zTXt", b"bomb\0\0" + zlib.compress(b"a" * 7_900_000, 9))
good = png(2, 2, (b"\0" + b"\x80\x40\x20\xff" * 2) * 2)
write_bytes("ztxt_bomb.png", good[:33] + ztxt * 16 + good[33:])

# A quad whose material reads each bomb in one slot, and a good image in another.
positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
uvs = struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)
indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
blob = positions + uvs + indices
write_json("image_bombs.gltf", {
    "asset": {"version": "2.0", "generator": "sherpa tests/data/make_oversized.py"},
    "extensionsUsed": ["EXT_texture_webp", "KHR_texture_basisu"],
    "extensionsRequired": ["EXT_texture_webp", "KHR_texture_basisu"],
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                "material": 0}]}],
    "materials": [{"name": "bombs",
                   "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                            "metallicRoughnessTexture": {"index": 4}},
                   "normalTexture": {"index": 1}, "emissiveTexture": {"index": 2},
                   "occlusionTexture": {"index": 3}, "emissiveFactor": [1, 1, 1]}],
    "textures": [{"source": 0}, {"source": 1},
                 {"extensions": {"EXT_texture_webp": {"source": 2}}},
                 {"extensions": {"KHR_texture_basisu": {"source": 3}}}, {"source": 4}],
    "images": [{"uri": "bomb_30000.png"}, {"uri": "bomb_65500.jpg"},
               {"uri": "bomb_16384.webp"}, {"uri": "bomb_uastc_zstd.ktx2"},
               {"uri": "good_2x2.png"}],
    "buffers": [{"uri": data_uri(blob), "byteLength": len(blob)}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
})

# --- a meshopt view whose fallback buffer declares 1.8 GB ---------------------------
# The ATTRIBUTES stream of three (0, 0, 0) positions (bitstream version 0): header
# byte, one all-zero group header per byte column, then the 32-byte tail.
stream = b"\xa0" + b"\0" * 12 + b"\0" * 32
declared = 1_800_000_000
write_json("meshopt_fallback_1800mb.gltf", {
    "asset": {"version": "2.0", "generator": "sherpa tests/data/make_oversized.py"},
    "extensionsUsed": ["EXT_meshopt_compression"],
    "extensionsRequired": ["EXT_meshopt_compression"],
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"uri": data_uri(stream), "byteLength": len(stream)},
                {"byteLength": declared,
                 "extensions": {"EXT_meshopt_compression": {"fallback": True}}}],
    "bufferViews": [{"buffer": 1, "byteOffset": 0, "byteLength": declared,
                     "extensions": {"EXT_meshopt_compression": {
                         "buffer": 0, "byteOffset": 0, "byteLength": len(stream),
                         "byteStride": 12, "count": 3, "mode": "ATTRIBUTES"}}}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [0, 0, 0]}],
})

# --- Draco streams whose headers declare what their bytes do not hold ---------------
# Box's Edgebreaker stream (130 bytes, gltf-transform's seed in compressed_seeds/, see
# tools/gltf_compress) with counts of its connectivity header rewritten. Draco 1.5.5
# checks them against each other (vertices <= 3 x faces, faces <= 4/3 x symbols,
# splits <= symbols) but not against the bytes behind the symbols, and sizes its
# corner table (24 bytes a face, filled) by the faces before it reads one symbol.
def glb_stream(name):
    """The first Draco primitive's stream of a GLB."""
    with open(name, "rb") as f:
        b = f.read()
    length = struct.unpack_from("<I", b, 12)[0]
    doc = json.loads(b[20:20 + length])
    binary = b[20 + length + 8:]
    prim = doc["meshes"][0]["primitives"][0]
    view = doc["bufferViews"][prim["extensions"]["KHR_draco_mesh_compression"]["bufferView"]]
    start = view.get("byteOffset", 0)
    return binary[start:start + view["byteLength"]]

def varint(v):
    out = b""
    while True:
        out += bytes([(v & 0x7F) | (0x80 if v > 0x7F else 0)])
        v >>= 7
        if not v:
            return out

def draco_gltf(name, stream, points, indices):
    """Box's primitive (NORMAL, POSITION, indices) over `stream`, with the accessor counts
    given."""
    write_json(name, {
        "asset": {"version": "2.0", "generator": "sherpa tests/data/make_oversized.py"},
        "extensionsUsed": ["KHR_draco_mesh_compression"],
        "extensionsRequired": ["KHR_draco_mesh_compression"],
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{
            "attributes": {"NORMAL": 0, "POSITION": 1}, "indices": 2, "mode": 4,
            "extensions": {"KHR_draco_mesh_compression": {
                "bufferView": 0, "attributes": {"NORMAL": 0, "POSITION": 1}}}}]}],
        "buffers": [{"uri": data_uri(stream), "byteLength": len(stream)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(stream)}],
        "accessors": [{"componentType": 5126, "count": points, "type": "VEC3"},
                      {"componentType": 5126, "count": points, "type": "VEC3",
                       "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
                      {"componentType": 5125, "count": indices, "type": "SCALAR"}],
    })

# After the 11-byte header: traversal 0, 8 vertices, 12 faces, 1 attribute connectivity,
# 11 symbols, 0 split symbols (varints), then the traversal.
box = glb_stream("compressed_seeds/Box.draco.glb")
assert box[11:17] == b"\x00\x08\x0c\x01\x0b\x00"

def edgebreaker(faces, attribute_data=1):
    """Box's stream declaring `faces` triangles and as many symbols."""
    return (box[:12] + varint(8) + varint(faces) + bytes([attribute_data]) + varint(faces) +
            box[16:])

# 2^28 triangles for an indices accessor of 36: a 6 GB corner table.
draco_gltf("draco_faces_268m.gltf", edgebreaker(1 << 28), 24, 36)
# 20M triangles whose accessors agree, over the documented limit of 2^24: 470 MB.
draco_gltf("draco_faces_20m.gltf", edgebreaker(20_000_000), 24, 60_000_000)
# 255 attribute connectivities (one corner table each) for a primitive of two attributes.
draco_gltf("draco_attribute_data_255.gltf", edgebreaker(12, 255), 24, 36)
