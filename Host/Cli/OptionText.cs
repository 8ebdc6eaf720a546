using System.CommandLine.Parsing;
using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Cli;

/// <summary>The option values written in a syntax of their own: image sizes, pixels, engine lists.</summary>
public static class OptionText
{
    /// <summary>"128" or "160x120" → the size; null text → no size.</summary>
    public static ((int Width, int Height)? Size, string? Error) ParseSize(string? text)
    {
        if (text is null) return (null, null);
        var parts = text.Split('x', 'X');
        if (parts.Length > 2 || parts.Any(p => !int.TryParse(p, NumberStyles.None, CultureInfo.InvariantCulture, out _)))
            return (null, $"expected WIDTHxHEIGHT or one number, got '{text}'");
        var width = int.Parse(parts[0], CultureInfo.InvariantCulture);
        var height = parts.Length == 2 ? int.Parse(parts[1], CultureInfo.InvariantCulture) : width;
        if (width < 1 || height < 1 || width > SceneLoader.MaxImageSide || height > SceneLoader.MaxImageSide)
            return (null, $"each side must be 1..{SceneLoader.MaxImageSide}, got {width}x{height}");
        return ((width, height), null);
    }

    /// <summary>The size <paramref name="text"/> gives (validated at parse time), else the scene's own.</summary>
    public static (int Width, int Height) SizeOr(string? text, Scene scene) => ParseSize(text) is { Size: { } size } ? size : (scene.Width, scene.Height);

    /// <summary>"512M", "4G", "1.5G" or a plain byte count → bytes; null text → no limit.</summary>
    public static (long? Bytes, string? Error) ParseBytes(string? text)
    {
        if (text is null) return (null, null);
        var unit = text.Length > 0 ? char.ToUpperInvariant(text[^1]) : ' ';
        var shift = unit switch { 'K' => 10, 'M' => 20, 'G' => 30, 'T' => 40, _ => 0 };
        var number = shift == 0 ? text : text[..^1];
        if (!double.TryParse(number, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out var value) || value <= 0 || value * (1L << shift) > long.MaxValue / 2)
            return (null, $"expected a size such as 512M or 4G, got '{text}'");
        return ((long)(value * (1L << shift)), null);
    }

    /// <summary>"12,7" → the pixel; null text → no pixel.</summary>
    public static ((int X, int Y)? Pixel, string? Error) ParsePixel(string? text)
    {
        if (text is null) return (null, null);
        var parts = text.Split(',');
        if (parts.Length != 2 || !int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out var x)
            || !int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out var y))
            return (null, $"expected X,Y (two non-negative integers), got '{text}'");
        return ((x, y), null);
    }

    /// <summary>The pixel <paramref name="text"/> names (validated at parse time), refused when outside a width x height image.</summary>
    public static (int X, int Y) PixelIn(string text, int width, int height, string option = "--pixel")
    {
        var (x, y) = ParsePixel(text).Pixel!.Value;
        return x < width && y < height ? (x, y) : throw new Output.UserError($"{option} {x},{y} is outside the {width}x{height} image");
    }

    /// <summary>Engine names, space- or comma-separated, each kept once, in the order of <paramref name="all"/>.</summary>
    public static EngineKind[] ParseEngines(ArgumentResult result, string name, EngineKind[] all)
    {
        var kinds = new List<EngineKind>();
        foreach (var text in result.Tokens.SelectMany(t => t.Value.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)))
        {
            var index = Array.FindIndex(all, k => string.Equals(k.ToString(), text, StringComparison.OrdinalIgnoreCase));
            if (index < 0)
            {
                result.AddError($"{name}: '{text}' is not one of {string.Join(", ", all.Select(EngineFactory.Name))}");
                return [];
            }
            if (!kinds.Contains(all[index])) kinds.Add(all[index]);
        }
        if (kinds.Count == 0) result.AddError($"{name}: name at least one engine");
        return kinds.OrderBy(k => Array.IndexOf(all, k)).ToArray();
    }
}
