"""PFM images for the project's Python scripts and tests: one reader.

`sunglint render` writes PFM (docs/scene-format.md, "Output"): a header of four
whitespace-separated fields, "PF" (RGB) or "Pf" (grey), the width, the height and a scale
whose sign gives the byte order (negative: little endian), one whitespace byte, then float32
rows from the bottom of the image to the top. The reader checks the header and the length
and raises ValueError naming the file, so that a truncated or foreign file is never read as
an image. Standard library only.

    import pfm
    w, h, channels, values = pfm.read(path)   # flat, rows bottom to top, as stored
    image = pfm.rows(w, h, channels, values)  # image[j][i] = (r, g, b), row 0 at the top
"""
import struct


def read(path):
    """(width, height, channels, values): values flat, channel-interleaved, rows from the
    bottom to the top as the file stores them."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # four whitespace-separated fields, then one whitespace byte
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while end < len(data) and not data[end:end + 1].isspace():
            end += 1
        if end == pos or end - pos > 32:
            raise ValueError("%s: not a PFM file (header field %d)" % (path, len(fields) + 1))
        fields.append(data[pos:end])
        pos = end
    pos += 1
    kind = fields[0]
    if kind not in (b"PF", b"Pf"):
        raise ValueError("%s: not a PFM file (starts %r)" % (path, kind))
    try:
        width, height, scale = int(fields[1]), int(fields[2]), float(fields[3])
    except ValueError:
        raise ValueError("%s: PFM header's size or scale is not a number" % path) from None
    if width <= 0 or height <= 0 or scale == 0:
        raise ValueError("%s: PFM header gives %dx%d, scale %g" % (path, width, height, scale))
    channels = 3 if kind == b"PF" else 1
    n = width * height * channels
    if len(data) - pos < 4 * n:
        raise ValueError("%s: truncated PFM (%d bytes of pixels for %d values)"
                         % (path, len(data) - pos, n))
    values = struct.unpack(("<" if scale < 0 else ">") + "%df" % n, data[pos:pos + 4 * n])
    return width, height, channels, list(values)


def rows(width, height, channels, values):
    """image[j][i] = (r, g, b) with row 0 at the top; a grey image's value in all three."""
    image = [[None] * width for _ in range(height)]
    for row in range(height):
        j = height - 1 - row
        for i in range(width):
            k = (row * width + i) * channels
            image[j][i] = tuple(values[k:k + 3]) if channels == 3 else (values[k],) * 3
    return image


def read_rows(path):
    """read() then rows(): image[j][i] = (r, g, b), row 0 at the top."""
    return rows(*read(path))

