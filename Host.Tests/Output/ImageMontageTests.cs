using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

public class ImageMontageTests
{
    [Fact]
    public void EveryPanelAppearsEnlargedAndWhole()
    {
        // Two rows, the second shorter; each panel has a colour found nowhere else, so its place can be searched for.
        var a = Panel(3, 2, 10);
        var b = Panel(2, 2, 100);
        var c = Panel(1, 3, 200);
        var montage = ImageMontage.Grid([[(a, "a"), (b, "b")], [(c, "c")]], 3);
        foreach (var panel in new[] { a, b, c })
        {
            var (left, top) = Find(montage, panel.GetPixel(0, 0));
            for (var y = 0; y < panel.Height * 3; y++)
                for (var x = 0; x < panel.Width * 3; x++)
                    Assert.Equal(panel.GetPixel(x / 3, y / 3), montage.GetPixel(left + x, top + y));
        }
        // Panels in one row share a top edge; the second row lies below the first.
        Assert.Equal(Find(montage, a.GetPixel(0, 0)).Top, Find(montage, b.GetPixel(0, 0)).Top);
        Assert.True(Find(montage, c.GetPixel(0, 0)).Top >= Find(montage, a.GetPixel(0, 0)).Top + 2 * 3);
        Assert.Throws<ArgumentException>(() => ImageMontage.Grid([[]], 1));
    }

    private static RgbImage Panel(int width, int height, byte tone)
    {
        var image = new RgbImage(width, height);
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
                image.SetPixel(x, y, tone, (byte)(x + 1), (byte)(y + 1));
        return image;
    }

    private static (int Left, int Top) Find(RgbImage image, (byte, byte, byte) colour)
    {
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
                if (image.GetPixel(x, y) == colour) return (x, y);
        throw new InvalidOperationException($"colour {colour} not in the montage");
    }
}
