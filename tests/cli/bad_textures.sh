#!/usr/bin/env bash
# Hostile texture files given to a chapter's --texture: each is refused with exit code 2, exactly
# one line on stderr naming the file (and, for an enormous one, its size), and the existing
# output file is left as it was, with nothing else in the folder.
#   bad_textures.sh CHAPTER_EXE GOOD_TEXTURE.png [ARGS...]   (ARGS choose a scene with a texture)
# The files are made here: cut copies of the good texture, headers written by hand (python3) that
# claim sizes far beyond the 2^26-texel limit in a few dozen bytes, and a decompression bomb.
set -uo pipefail
exe=$1 good=$2
shift 2
scene_args=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir textures
failures=0

size=$(stat -c %s "$good")
: >textures/empty.png
head -c $((size / 2)) "$good" >textures/half.png
head -c $((size - 12)) "$good" >textures/no_end.png  # only the 12-byte IEND chunk cut off
head -c 20 "$good" >textures/header_only.png
printf 'These are not the pixels you are looking for.\n' >textures/notes.png
mkdir textures/folder.png
python3 - <<'EOF'
import struct, zlib

def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

def png(width, height, data=b"", compressed=None):
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    if data:
        compressed = zlib.compress(data)
    idat = chunk(b"IDAT", compressed) if compressed else b""
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + idat + chunk(b"IEND", b"")

def jpeg(width, height):  # a start of frame (SOF0) with three components, and nothing else
    return (b"\xff\xd8\xff\xc0\x00\x11\x08" + struct.pack(">HH", height, width) +
            b"\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01\xff\xd9")

def bomb():
    z = zlib.compressobj(9)
    zeros = bytes(1 << 20)
    return b"".join(z.compress(zeros) for _ in range(256)) + z.flush()

files = {
    "huge.png": png(100000, 100000),
    "wide.png": png(8193, 8192),  # one column more than 2^26 texels
    "huge.jpg": jpeg(65535, 65535),
    "big.jpg": jpeg(10000, 10000),
    "huge.ppm": b"P6\n100000 100000\n255\n" + bytes(30),
    "cut.ppm": b"P6\n4 4\n255\n" + bytes(30),  # 48 bytes of texels needed
    "digits.ppm": b"P6\n99999999999 1\n255\n" + bytes(3),
    # a valid header and a zlib stream that holds one row of the 4 x 4 image
    "short_data.png": png(4, 4, b"\x00" + bytes(12)),
    # a JPEG Huffman table (DHT) of 16 x 20 = 320 codes: stb 2.27 would write past its arrays
    "dht_overflow.jpg": b"\xff\xd8\xff\xc4\x01\x51\x00" + bytes([20] * 16) + bytes(320),
    # a format stb_image reads but we do not: a BMP of 1 x 1 texels
    "bitmap.bmp": b"BM" + struct.pack("<IHHIIiiHHIIiiII", 58, 0, 0, 54, 40, 1, 1, 1, 24, 0, 4,
                                      2835, 2835, 0, 0) + b"\x00\x00\xff\x00",
    # a decompression bomb: 1 x 1 texels, and 256 MiB of zeros in 256 KiB of zlib stream
    "bomb.png": png(1, 1, compressed=bomb()),
}
for name, data in files.items():
    with open("textures/" + name, "wb") as f:
        f.write(data)
EOF

# expect_refusal FILE TEXT...: --texture FILE is refused naming FILE and each TEXT.
expect_refusal() {
    local file=$1
    shift
    printf 'keep' >existing.png
    "$exe" --quiet --width 8 --spp 1 "${scene_args[@]}" --texture "$file" --out existing.png \
        >stdout.txt 2>stderr.txt
    local rc=$?
    local problem=""
    [ "$rc" -eq 2 ] || problem+=" exit code $rc, not 2;"
    [ "$(wc -l <stderr.txt)" -eq 1 ] || problem+=" $(wc -l <stderr.txt) lines on stderr, not 1;"
    for text in "'$file'" "$@"; do
        grep -qF -- "$text" stderr.txt || problem+=" message does not say \"$text\";"
    done
    [ "$(cat existing.png)" = "keep" ] || problem+=" existing.png was changed;"
    local extra
    extra=$(ls -A | grep -vxE 'existing.png|stdout.txt|stderr.txt|textures')
    [ -z "$extra" ] || problem+=" left files: $extra;"
    if [ -n "$problem" ]; then
        echo "FAIL [$file]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
    else
        echo "ok   [$file] -> $(cat stderr.txt)"
    fi
    rm -f stdout.txt stderr.txt
}

expect_refusal textures/missing.png "No such file or directory"
expect_refusal textures/folder.png "is a folder"
expect_refusal /dev/null "not a regular file"
expect_refusal textures/empty.png "empty"
expect_refusal textures/notes.png "not a PNG, JPEG or binary PPM/PGM image"
expect_refusal textures/header_only.png "damaged or truncated"
expect_refusal textures/dht_overflow.jpg "a JPEG Huffman table of 320 codes, more than 256"
expect_refusal textures/bitmap.bmp "not a PNG, JPEG or binary PPM/PGM image"
expect_refusal textures/half.png "damaged or truncated"
expect_refusal textures/no_end.png "damaged or truncated"
expect_refusal textures/short_data.png "damaged or truncated"
expect_refusal textures/bomb.png "inflates to more than 1048584 bytes where its 1 x 1 texels need 4"
expect_refusal textures/cut.ppm "holds 30 bytes where its 4 x 4 texels need 48"
expect_refusal textures/digits.ppm "a number in its PPM/PGM header is above 2147483647"
expect_refusal textures/huge.png "at most 67108864 texels (2^26)" "got 100000 x 100000"
expect_refusal textures/wide.png "at most 67108864 texels (2^26)" "got 8193 x 8192"
expect_refusal textures/huge.jpg "at most 67108864 texels (2^26)" "got 65535 x 65535"
expect_refusal textures/big.jpg "at most 67108864 texels (2^26)" "got 10000 x 10000"
expect_refusal textures/huge.ppm "at most 67108864 texels (2^26)" "got 100000 x 100000"

# The good texture itself renders: the refusals above are the files', not the command's.
"$exe" --quiet --width 8 --spp 1 "${scene_args[@]}" --texture "$good" --out good.png ||
    { echo "FAIL: the good texture $good was refused"; failures=$((failures + 1)); }
rm -f good.png

[ "$failures" -eq 0 ] || { echo "$failures bad textures not refused as they should be"; exit 1; }
echo "all bad textures refused"
