namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// A small pixel font for printable ASCII (32 to 126): glyphs 5 pixels wide on a 9-row cell (7 rows from the
/// top of a capital to the baseline, 2 rows for descenders), 6 pixels apart, drawn at whole-number scales.
/// Characters outside that range are drawn as a hollow box.
/// </summary>
public static class BitmapFont
{
    /// <summary>Ink columns of one glyph.</summary>
    public const int GlyphWidth = 5;

    /// <summary>Rows of the character cell, descenders included.</summary>
    public const int GlyphHeight = 9;

    /// <summary>Rows from the top of the cell down to and including the baseline (the height of a capital).</summary>
    public const int CapHeight = 7;

    /// <summary>Horizontal distance from one character to the next: the glyph and one blank column.</summary>
    public const int Advance = GlyphWidth + 1;

    /// <summary>The first character with its own glyph (space).</summary>
    public const char FirstChar = ' ';

    /// <summary>The last character with its own glyph (tilde).</summary>
    public const char LastChar = '~';

    // One string per character from FirstChar to LastChar: rows top to bottom separated by spaces, '#' is ink.
    // Seven rows, or nine for glyphs that reach below the baseline.
    private static readonly string[] Sheet =
    [
        "..... ..... ..... ..... ..... ..... .....", // space
        "..#.. ..#.. ..#.. ..#.. ..#.. ..... ..#..", // !
        ".#.#. .#.#. ..... ..... ..... ..... .....", // "
        ".#.#. .#.#. ##### .#.#. ##### .#.#. .#.#.", // #
        "..#.. .#### #.#.. .###. ..#.# ####. ..#..", // $
        "##... ##..# ...#. ..#.. .#... #..## ...##", // %
        ".##.. #..#. #.#.. .#... #.#.# #..#. .##.#", // &
        "..#.. ..#.. ..... ..... ..... ..... .....", // '
        "...#. ..#.. .#... .#... .#... ..#.. ...#.", // (
        ".#... ..#.. ...#. ...#. ...#. ..#.. .#...", // )
        "..... ..#.. #.#.# .###. #.#.# ..#.. .....", // *
        "..... ..#.. ..#.. ##### ..#.. ..#.. .....", // +
        "..... ..... ..... ..... ..... .##.. ..#.. .#... .....", // ,
        "..... ..... ..... ##### ..... ..... .....", // -
        "..... ..... ..... ..... ..... .##.. .##..", // .
        "....# ...#. ...#. ..#.. .#... .#... #....", // /
        ".###. #...# #..## #.#.# ##..# #...# .###.", // 0
        "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###.", // 1
        ".###. #...# ....# ...#. ..#.. .#... #####", // 2
        "##### ...#. ..#.. ...#. ....# #...# .###.", // 3
        "...#. ..##. .#.#. #..#. ##### ...#. ...#.", // 4
        "##### #.... ####. ....# ....# #...# .###.", // 5
        "..##. .#... #.... ####. #...# #...# .###.", // 6
        "##### ....# ...#. ..#.. .#... .#... .#...", // 7
        ".###. #...# #...# .###. #...# #...# .###.", // 8
        ".###. #...# #...# .#### ....# ...#. .##..", // 9
        "..... .##.. .##.. ..... .##.. .##.. .....", // :
        "..... .##.. .##.. ..... .##.. ..#.. .#...", // ;
        "...#. ..#.. .#... #.... .#... ..#.. ...#.", // <
        "..... ..... ##### ..... ##### ..... .....", // =
        ".#... ..#.. ...#. ....# ...#. ..#.. .#...", // >
        ".###. #...# ....# ...#. ..#.. ..... ..#..", // ?
        ".###. #...# #.### #.#.# #.### #.... .####", // @
        ".###. #...# #...# ##### #...# #...# #...#", // A
        "####. #...# #...# ####. #...# #...# ####.", // B
        ".###. #...# #.... #.... #.... #...# .###.", // C
        "###.. #..#. #...# #...# #...# #..#. ###..", // D
        "##### #.... #.... ####. #.... #.... #####", // E
        "##### #.... #.... ####. #.... #.... #....", // F
        ".###. #...# #.... #.### #...# #...# .####", // G
        "#...# #...# #...# ##### #...# #...# #...#", // H
        ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###.", // I
        "..### ...#. ...#. ...#. ...#. #..#. .##..", // J
        "#...# #..#. #.#.. ##... #.#.. #..#. #...#", // K
        "#.... #.... #.... #.... #.... #.... #####", // L
        "#...# ##.## #.#.# #.#.# #...# #...# #...#", // M
        "#...# #...# ##..# #.#.# #..## #...# #...#", // N
        ".###. #...# #...# #...# #...# #...# .###.", // O
        "####. #...# #...# ####. #.... #.... #....", // P
        ".###. #...# #...# #...# #.#.# #..#. .##.#", // Q
        "####. #...# #...# ####. #.#.. #..#. #...#", // R
        ".#### #.... #.... .###. ....# ....# ####.", // S
        "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#..", // T
        "#...# #...# #...# #...# #...# #...# .###.", // U
        "#...# #...# #...# #...# #...# .#.#. ..#..", // V
        "#...# #...# #...# #.#.# #.#.# #.#.# .#.#.", // W
        "#...# #...# .#.#. ..#.. .#.#. #...# #...#", // X
        "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#..", // Y
        "##### ....# ...#. ..#.. .#... #.... #####", // Z
        ".###. .#... .#... .#... .#... .#... .###.", // [
        "#.... .#... .#... ..#.. ...#. ...#. ....#", // backslash
        ".###. ...#. ...#. ...#. ...#. ...#. .###.", // ]
        "..#.. .#.#. #...# ..... ..... ..... .....", // ^
        "..... ..... ..... ..... ..... ..... ..... ##### .....", // _
        ".#... ..#.. ..... ..... ..... ..... .....", // `
        "..... ..... .###. ....# .#### #...# .####", // a
        "#.... #.... ####. #...# #...# #...# ####.", // b
        "..... ..... .###. #.... #.... #...# .###.", // c
        "....# ....# .#### #...# #...# #...# .####", // d
        "..... ..... .###. #...# ##### #.... .###.", // e
        "..##. .#..# .#... ###.. .#... .#... .#...", // f
        "..... ..... .#### #...# #...# #...# .#### ....# .###.", // g
        "#.... #.... #.##. ##..# #...# #...# #...#", // h
        "..#.. ..... .##.. ..#.. ..#.. ..#.. .###.", // i
        "...#. ..... ..##. ...#. ...#. ...#. ...#. #..#. .##..", // j
        "#.... #.... #..#. #.#.. ##... #.#.. #..#.", // k
        ".##.. ..#.. ..#.. ..#.. ..#.. ..#.. .###.", // l
        "..... ..... ##.#. #.#.# #.#.# #.#.# #.#.#", // m
        "..... ..... #.##. ##..# #...# #...# #...#", // n
        "..... ..... .###. #...# #...# #...# .###.", // o
        "..... ..... ####. #...# #...# #...# ####. #.... #....", // p
        "..... ..... .#### #...# #...# #...# .#### ....# ....#", // q
        "..... ..... #.##. ##..# #.... #.... #....", // r
        "..... ..... .#### #.... .###. ....# ####.", // s
        ".#... .#... ###.. .#... .#... .#..# ..##.", // t
        "..... ..... #...# #...# #...# #..## .##.#", // u
        "..... ..... #...# #...# #...# .#.#. ..#..", // v
        "..... ..... #...# #...# #.#.# #.#.# .#.#.", // w
        "..... ..... #...# .#.#. ..#.. .#.#. #...#", // x
        "..... ..... #...# #...# #...# #...# .#### ....# .###.", // y
        "..... ..... ##### ...#. ..#.. .#... #####", // z
        "...## ..#.. ..#.. ##... ..#.. ..#.. ...##", // {
        "..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#..", // |
        "##... ..#.. ..#.. ...## ..#.. ..#.. ##...", // }
        "..... ..... .#... #.#.# ...#. ..... .....", // ~
    ];

    private const string MissingGlyph = "##### #...# #...# #...# #...# #...# #####";

    // Each glyph as GlyphHeight row masks; bit (GlyphWidth - 1 - column) is set where there is ink.
    private static readonly byte[][] Glyphs = Sheet.Select(Parse).ToArray();
    private static readonly byte[] Missing = Parse(MissingGlyph);

    /// <summary>Whether <paramref name="c"/> has a glyph of its own (otherwise it is drawn as a hollow box).</summary>
    public static bool HasGlyph(char c) => c >= FirstChar && c <= LastChar;

    /// <summary>
    /// The glyph of <paramref name="c"/> as <see cref="GlyphHeight"/> row masks, top row first; in each row, bit
    /// <c>GlyphWidth - 1 - column</c> is set where the glyph has ink.
    /// </summary>
    public static IReadOnlyList<byte> GlyphRows(char c) => HasGlyph(c) ? Glyphs[c - FirstChar] : Missing;

    /// <summary>
    /// The size of the box <see cref="DrawText"/> fills for <paramref name="text"/>: every glyph and the gaps
    /// between them (no trailing gap), and the full cell height including descenders. Empty text is 0 wide.
    /// </summary>
    public static (int Width, int Height) Measure(string text, int scale = 1)
    {
        ArgumentNullException.ThrowIfNull(text);
        ArgumentOutOfRangeException.ThrowIfLessThan(scale, 1);
        return (text.Length == 0 ? 0 : (text.Length * Advance - 1) * scale, GlyphHeight * scale);
    }

    /// <summary>
    /// Draws <paramref name="text"/> on one line with the top-left corner of its box at (<paramref name="x"/>,
    /// <paramref name="y"/>), each font pixel a <paramref name="scale"/> x <paramref name="scale"/> block. Only ink
    /// pixels are written; pixels that fall outside the image are left out.
    /// </summary>
    public static void DrawText(RgbImage image, string text, int x, int y, PlotColour colour, int scale = 1)
    {
        ArgumentNullException.ThrowIfNull(image);
        ArgumentNullException.ThrowIfNull(text);
        ArgumentOutOfRangeException.ThrowIfLessThan(scale, 1);
        for (var i = 0; i < text.Length; i++)
        {
            var rows = GlyphRows(text[i]);
            var left = x + i * Advance * scale;
            for (var row = 0; row < GlyphHeight; row++)
                for (var column = 0; column < GlyphWidth; column++)
                    if ((rows[row] & (1 << (GlyphWidth - 1 - column))) != 0)
                        FillBlock(image, left + column * scale, y + row * scale, scale, colour);
        }
    }

    private static void FillBlock(RgbImage image, int x, int y, int size, PlotColour colour)
    {
        for (var dy = 0; dy < size; dy++)
            for (var dx = 0; dx < size; dx++)
            {
                int px = x + dx, py = y + dy;
                if (px >= 0 && px < image.Width && py >= 0 && py < image.Height)
                    image.SetPixel(px, py, colour.R, colour.G, colour.B);
            }
    }

    // A malformed sheet entry fails when the type is first used, so any test touching the font catches it.
    private static byte[] Parse(string glyph)
    {
        var rows = glyph.Split(' ');
        if ((rows.Length != CapHeight && rows.Length != GlyphHeight) || rows.Any(r => r.Length != GlyphWidth || r.Trim('.', '#').Length != 0))
            throw new InvalidOperationException($"Malformed glyph \"{glyph}\"");
        var masks = new byte[GlyphHeight];
        for (var row = 0; row < rows.Length; row++)
            for (var column = 0; column < GlyphWidth; column++)
                if (rows[row][column] == '#') masks[row] |= (byte)(1 << (GlyphWidth - 1 - column));
        return masks;
    }
}
