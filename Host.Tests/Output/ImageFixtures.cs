namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// The image fixtures in Output/Images (made by make-fixtures.sh there) and the pixel values they were made from,
/// read from the plain-text PPM sources.
/// </summary>
internal static class ImageFixtures
{
    public static string Path(string name) => System.IO.Path.Combine(AppContext.BaseDirectory, "Output", "Images", name);

    /// <summary>The source's pixels as [x, y] = (R, G, B) on its own scale, and that scale's maximum (255 or 65535).</summary>
    public static ((int R, int G, int B)[,] Pixels, int Max) Source(string name)
    {
        // P3: "P3", width, height, maximum, then the samples, all separated by white space; '#' starts a comment.
        var words = File.ReadLines(Path(name))
            .Select(line => line.Split('#')[0])
            .SelectMany(line => line.Split((char[])[' ', '\t'], StringSplitOptions.RemoveEmptyEntries))
            .ToArray();
        if (words[0] != "P3") throw new InvalidDataException($"{name} is not a plain PPM");
        int width = int.Parse(words[1]), height = int.Parse(words[2]), max = int.Parse(words[3]);
        var pixels = new (int, int, int)[width, height];
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
            {
                var at = 4 + 3 * (y * width + x);
                pixels[x, y] = (int.Parse(words[at]), int.Parse(words[at + 1]), int.Parse(words[at + 2]));
            }
        return (pixels, max);
    }

    /// <summary>A sample on the scale 0..<paramref name="max"/> as an 8-bit level, rounded (PNG spec, section 13.12).</summary>
    public static int To8Bit(int sample, int max) => (int)Math.Round(sample * 255.0 / max, MidpointRounding.AwayFromZero);
}
