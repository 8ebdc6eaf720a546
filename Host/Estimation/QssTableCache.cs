using System.Globalization;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimation;

/// <summary>
/// Keeps QSS lookup tables on disk, one JSON file per (subpixels, counter bits, source), so a table is built once per
/// configuration. A file that cannot be read, or whose contents do not match its key or are not a table of
/// probability columns, is treated as absent and rebuilt; it never fails a run.
/// </summary>
public sealed class QssTableCache(string directory)
{
    public const string Format = "qrt-qss-lookup-table/1";

    /// <summary>The user's cache directory for tables: $XDG_CACHE_HOME or ~/.cache (LocalApplicationData elsewhere), then QuantumRayTracing/qss-tables.</summary>
    public static string DefaultDirectory()
    {
        var root = Environment.GetEnvironmentVariable("XDG_CACHE_HOME");
        if (string.IsNullOrEmpty(root))
            root = OperatingSystem.IsWindows()
                ? Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData)
                : Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.UserProfile), ".cache");
        return Path.Combine(root, "QuantumRayTracing", "qss-tables");
    }

    public string Directory => directory;

    /// <summary>True when the last <see cref="GetOrBuild"/> read the table from disk.</summary>
    public bool LastWasHit { get; private set; }

    public string PathFor(int subpixels, int counterBits, string source) =>
        Path.Combine(directory, $"qss-n{subpixels}-t{counterBits}-{Slug(source)}.json");

    /// <summary>The cached table for the key, or <paramref name="build"/>'s, which is then stored (atomically).</summary>
    public QssLookupTable GetOrBuild(int subpixels, int counterBits, string source, Func<QssLookupTable> build)
    {
        var path = PathFor(subpixels, counterBits, source);
        var cached = TryRead(path, subpixels, counterBits, source);
        LastWasHit = cached is not null;
        if (cached is not null) return cached;
        var table = build();
        try
        {
            System.IO.Directory.CreateDirectory(directory);
            AtomicFile.WriteAllBytes(path, Encoding.UTF8.GetBytes(Serialize(table)));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // An unwritable cache costs a rebuild next time, not this run.
        }
        return table;
    }

    public static string Serialize(QssLookupTable table)
    {
        var rows = new JsonArray();
        for (var y = 0; y < table.Readouts; y++)
        {
            var row = new JsonArray();
            for (var h = 0; h <= table.Subpixels; h++) row.Add(table.Probabilities[y, h]);
            rows.Add(row);
        }
        return new JsonObject
        {
            ["format"] = Format,
            ["subpixels"] = table.Subpixels,
            ["counterBits"] = table.CounterBits,
            ["source"] = table.Source,
            ["probabilities"] = rows,
        }.ToJsonString();
    }

    /// <summary>The table in <paramref name="path"/> if it is one for exactly this key, else null.</summary>
    public static QssLookupTable? TryRead(string path, int subpixels, int counterBits, string source)
    {
        try
        {
            if (!File.Exists(path)) return null;
            if (JsonNode.Parse(File.ReadAllText(path)) is not JsonObject root) return null;
            if ((string?)root["format"] != Format || (int?)root["subpixels"] != subpixels
                || (int?)root["counterBits"] != counterBits || (string?)root["source"] != source) return null;
            if (root["probabilities"] is not JsonArray rows || rows.Count != 1 << counterBits) return null;
            var table = new double[rows.Count, subpixels + 1];
            for (var y = 0; y < rows.Count; y++)
            {
                if (rows[y] is not JsonArray row || row.Count != subpixels + 1) return null;
                for (var h = 0; h <= subpixels; h++)
                {
                    var p = (double?)row[h];
                    if (p is not double value || !(value >= 0 && value <= 1)) return null;
                    table[y, h] = value;
                }
            }
            for (var h = 0; h <= subpixels; h++)
            {
                var total = 0.0;
                for (var y = 0; y < rows.Count; y++) total += table[y, h];
                if (Math.Abs(total - 1) > 1e-6) return null;
            }
            return new QssLookupTable(subpixels, counterBits, table, source);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException or InvalidOperationException or FormatException or ArgumentException)
        {
            return null;
        }
    }

    private static string Slug(string source) =>
        new(source.ToLowerInvariant().Select(c => char.IsAsciiLetterOrDigit(c) ? c : '-').ToArray());
}
