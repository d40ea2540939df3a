#!/usr/bin/python3
"""Extract the cubic Bezier segments of a few Debian URW base35 fonts.

Walter & Fournier measured their fit on the outlines of two Bitstream font
families (4 fonts each).  The free stand-ins here are two URW families from
Debian's fonts-urw-base35 (OpenType/CFF outlines, read with fontTools):
URW Bookman (soft, Cooper-like) and Nimbus Sans (a Helvetica clone, as
Bitstream's Zurich is a Swiss sans).  Glyphs: the printable Latin-1
characters (U+0021-U+007E, U+00A1-U+00FF) that the font maps.

Output (stdout or the path given): TSV with a header; one cubic per line:
family, font, glyph, x0 y0 x1 y1 x2 y2 x3 y3 (font units, repr(float)).
Segments whose four points coincide (no length) are skipped.

Run: /usr/bin/python3 tools/font_cubics.py spec/data/font_cubics.tsv
"""
import sys

from fontTools.pens.basePen import BasePen
from fontTools.ttLib import TTFont

FONT_DIR = "/usr/share/fonts/opentype/urw-base35/"
FAMILIES = {
    "URWBookman": ["URWBookman-Light", "URWBookman-LightItalic",
                   "URWBookman-Demi", "URWBookman-DemiItalic"],
    "NimbusSans": ["NimbusSans-Regular", "NimbusSans-Italic",
                   "NimbusSans-Bold", "NimbusSans-BoldItalic"],
}
CHARS = [chr(c) for c in list(range(0x21, 0x7F)) + list(range(0xA1, 0x100))]


class CubicPen(BasePen):
    """Collects (p0, p1, p2, p3) for every cubic segment drawn."""

    def __init__(self, glyphset):
        super().__init__(glyphset)
        self.cubics = []

    def _moveTo(self, pt):
        pass

    def _lineTo(self, pt):
        pass

    def _curveToOne(self, p1, p2, p3):
        p0 = self._getCurrentPoint()
        self.cubics.append((p0, p1, p2, p3))

    def _closePath(self):
        pass


def num(v):
    v = float(v)
    return repr(int(v)) if v == int(v) else repr(v)


def main(out):
    out.write("family\tfont\tglyph\tx0\ty0\tx1\ty1\tx2\ty2\tx3\ty3\n")
    for family, fonts in FAMILIES.items():
        for name in fonts:
            font = TTFont(FONT_DIR + name + ".otf")
            cmap = font.getBestCmap()
            glyphs = font.getGlyphSet()
            for ch in CHARS:
                gname = cmap.get(ord(ch))
                if gname is None:
                    continue
                pen = CubicPen(glyphs)
                glyphs[gname].draw(pen)
                for cubic in pen.cubics:
                    if all(p == cubic[0] for p in cubic):
                        continue
                    coords = [num(v) for p in cubic for v in p]
                    out.write("\t".join([family, name, "U+%04X" % ord(ch)]
                                         + coords) + "\n")


if __name__ == "__main__":
    if len(sys.argv) > 1:
        with open(sys.argv[1], "w") as f:
            main(f)
    else:
        main(sys.stdout)
