using QuantumRayTracing.Output;
using QuantumRayTracing.Output.Plots;

namespace QuantumRayTracing.Tests.Output.Plots;

public class BitmapFontTests
{
    private static IEnumerable<char> Printable => Enumerable.Range(32, 95).Select(c => (char)c);

    [Fact]
    public void EveryPrintableAsciiCharacterHasAGlyphWithInkExceptSpace()
    {
        foreach (var c in Printable)
        {
            Assert.True(BitmapFont.HasGlyph(c), $"no glyph for '{c}'");
            var rows = BitmapFont.GlyphRows(c);
            Assert.Equal(BitmapFont.GlyphHeight, rows.Count);
            Assert.True(rows.All(r => r < 1 << BitmapFont.GlyphWidth), $"'{c}' is wider than {BitmapFont.GlyphWidth}");
            Assert.Equal(c != ' ', rows.Any(r => r != 0));
        }
        Assert.False(BitmapFont.HasGlyph('\u00e9'));
        Assert.False(BitmapFont.HasGlyph('\t'));
    }

    [Fact]
    public void NoTwoGlyphsAreTheSame()
    {
        var seen = new Dictionary<string, char>();
        foreach (var c in Printable)
        {
            var key = string.Join(",", BitmapFont.GlyphRows(c));
            Assert.False(seen.TryGetValue(key, out var other), $"'{c}' looks like '{other}'");
            seen[key] = c;
        }
        // The placeholder for other characters is distinct too.
        Assert.DoesNotContain(string.Join(",", BitmapFont.GlyphRows('\u00e9')), seen.Keys);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void DrawingAStaysInsideItsMeasuredBox(int scale)
    {
        var image = White(40, 50);
        const int left = 7, top = 11;
        BitmapFont.DrawText(image, "A", left, top, PlotColour.Black, scale);
        var (width, height) = BitmapFont.Measure("A", scale);
        Assert.Equal((5 * scale, 9 * scale), (width, height));
        var ink = 0;
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
            {
                if (image.GetPixel(x, y) == ((byte)255, (byte)255, (byte)255)) continue;
                Assert.InRange(x, left, left + width - 1);
                Assert.InRange(y, top, top + height - 1);
                ink++;
            }
        // 'A' has ink on every one of its 7 rows above the baseline, and each font pixel is a scale x scale block.
        var fontPixels = BitmapFont.GlyphRows('A').Sum(r => System.Numerics.BitOperations.PopCount(r));
        Assert.Equal(fontPixels * scale * scale, ink);
        Assert.True(fontPixels >= 7);
    }

    [Fact]
    public void TextAdvancesOneGlyphAndAGapPerCharacter()
    {
        Assert.Equal((0, 9), BitmapFont.Measure(""));
        Assert.Equal((3 * 6 - 1, 9), BitmapFont.Measure("abc"));
        Assert.Equal(((3 * 6 - 1) * 2, 18), BitmapFont.Measure("abc", 2));

        // The second character starts Advance pixels after the first: "|" has its stroke in the middle column.
        var image = White(20, 12);
        BitmapFont.DrawText(image, "||", 0, 0, PlotColour.Black);
        Assert.Equal((byte)0, image.GetPixel(2, 0).R);
        Assert.Equal((byte)0, image.GetPixel(2 + BitmapFont.Advance, 0).R);
        Assert.Equal((byte)255, image.GetPixel(3, 0).R);
    }

    [Fact]
    public void TextRunningOffTheImageIsCutNotAnError()
    {
        var image = White(8, 8);
        BitmapFont.DrawText(image, "Wide text", -3, -4, PlotColour.Black, 2);
        Assert.Contains((byte)0, image.Pixels.ToArray());
    }

    private static RgbImage White(int width, int height) => RgbImage.FromLinear(width, height, (_, _) => (1, 1, 1));
}
