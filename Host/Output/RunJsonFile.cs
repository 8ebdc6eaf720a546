using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.Json.Serialization;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Output;

/// <summary>
/// The <c>--json FILE</c> of a command, for scripts: one JSON object holding the run (<see cref="RunRecord"/>),
/// the versions of the program, the QDK and Node.js, and where the counting conventions are stated. The file is
/// this program's when it opens with <c>{"generator": "qrt"</c>; any other existing file is never replaced. Written whole or not at all (<see cref="AtomicFile"/>).
/// </summary>
public static class RunJsonFile
{
    public const string Generator = "qrt";

    /// <summary>Where every figure's counting convention is stated.</summary>
    public const string Conventions = "docs/conventions.md";

    private static readonly JsonSerializerOptions Options = new()
    {
        WriteIndented = true,
        // A file, not HTML: '+', '≥' and the like as themselves.
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull,
        NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals,
        Converters = { new JsonStringEnumConverter(JsonNamingPolicy.CamelCase), new SecondsConverter(), new ReportTableConverter() },
    };

    /// <summary>
    /// Throws a <see cref="UserError"/> naming <paramref name="path"/> when it may not be written: the rules of every
    /// output, and it is none of the command's other files (<paramref name="otherFiles"/>: inputs and outputs).
    /// </summary>
    public static void EnsureWritable(string? path, IEnumerable<string> otherFiles)
    {
        if (path is null) return;
        var full = Path.GetFullPath(path);
        if (otherFiles.Any(f => Path.GetFullPath(f) == full))
            throw new UserError($"{path}: --json names a file this command already reads or writes");
        OutputFile.EnsureReplaceable(path, IsOurs,
            $"exists and was not written by this program (no \"generator\": \"{Generator}\" at its top); choose another file or remove it");
    }

    /// <summary>
    /// A JSON object whose first member is <c>"generator": "qrt"</c>, as every file <see cref="Compose"/> writes starts.
    /// Only the file's first bytes are read, so a large file that is not ours costs nothing to refuse.
    /// </summary>
    public static bool IsOurs(string file)
    {
        var head = new byte[256];
        int length;
        using (var stream = File.OpenRead(file)) length = stream.ReadAtLeast(head, head.Length, throwOnEndOfStream: false);
        var reader = new Utf8JsonReader(head.AsSpan(0, length), isFinalBlock: false, state: default);
        try
        {
            return reader.Read() && reader.TokenType == JsonTokenType.StartObject
                && reader.Read() && reader.TokenType == JsonTokenType.PropertyName && reader.ValueTextEquals("generator")
                && reader.Read() && reader.TokenType == JsonTokenType.String && reader.ValueTextEquals(Generator);
        }
        catch (JsonException)
        {
            return false;
        }
    }

    /// <summary>The file's text.</summary>
    public static string Compose(RunRecord run, ToolVersions versions)
    {
        var document = new JsonObject
        {
            ["generator"] = Generator,
            ["command"] = run.Command,
            ["conventions"] = Conventions,
            ["versions"] = JsonSerializer.SerializeToNode(versions, Options),
            ["options"] = JsonSerializer.SerializeToNode(run.Options, Options),
            ["seed"] = run.Seed,
            ["engine"] = run.Engine,
            ["noise"] = JsonSerializer.SerializeToNode(run.Noise, Options),
            ["ranOn"] = JsonSerializer.SerializeToNode(run.RanOn, Options),
            ["figures"] = JsonSerializer.SerializeToNode(run.Figures, run.Figures.GetType(), Options),
        };
        if (run.RanOn is null) document.Remove("ranOn");
        return document.ToJsonString(Options) + "\n";
    }

    /// <summary>Writes <paramref name="run"/> to <paramref name="path"/> (nothing when it is null), with the versions found now.</summary>
    public static void Write(string? path, RunRecord run)
    {
        if (path is null) return;
        var bytes = new UTF8Encoding(false).GetBytes(Compose(run, ToolVersions.Detect()));
        try
        {
            AtomicFile.WriteAllBytes(path, bytes);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UserError($"{path}: cannot be written: {e.Message}");
        }
    }

    /// <summary>Durations in seconds, the unit every wall time is printed in.</summary>
    private sealed class SecondsConverter : JsonConverter<TimeSpan>
    {
        public override TimeSpan Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
            TimeSpan.FromSeconds(reader.GetDouble());

        public override void Write(Utf8JsonWriter writer, TimeSpan value, JsonSerializerOptions options) =>
            writer.WriteNumberValue(value.TotalSeconds);
    }

    /// <summary>A printed table as it reads: title, context lines, columns, rows of cells, notes.</summary>
    private sealed class ReportTableConverter : JsonConverter<ReportTable>
    {
        public override ReportTable Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
            throw new NotSupportedException("tables are written, not read");

        public override void Write(Utf8JsonWriter writer, ReportTable value, JsonSerializerOptions options) =>
            value.ToJson().WriteTo(writer, options);
    }
}
