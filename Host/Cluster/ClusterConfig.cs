using System.Text.Json;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cluster;

/// <summary>How workers find each other and how a render reaches them (a small JSON file; docs/cluster.md).</summary>
/// <param name="Path">The file the settings came from, for messages.</param>
/// <param name="ClusterId">Workers and renders of one cluster share this name.</param>
/// <param name="Clustering">Membership: localhost (workers on this machine) or redis (workers on several machines).</param>
/// <param name="PrimaryPort">Localhost: the silo port of the first worker, which the others join.</param>
/// <param name="Gateways">Localhost: the gateway ports of the workers, which a render connects to.</param>
/// <param name="Redis">Redis: the StackExchange.Redis connection string, e.g. <c>redis-host:6379</c>.</param>
/// <param name="ChunkTimeout">How long one chunk may take on one worker before it is sent to another.</param>
/// <param name="Certificate">The PKCS#12 file workers and renders talk over mutual TLS with (<see cref="ClusterCertificate"/>); null: plain TCP.</param>
public sealed record ClusterConfig(
    string Path,
    string ClusterId,
    ClusteringKind Clustering,
    int PrimaryPort,
    IReadOnlyList<int> Gateways,
    string? Redis,
    TimeSpan ChunkTimeout,
    string? Certificate = null)
{
    public const int DefaultPrimaryPort = 11111;
    public const int DefaultGatewayPort = 30000;
    public static readonly TimeSpan DefaultChunkTimeout = TimeSpan.FromMinutes(10);

    /// <summary>Reads and checks a cluster file; a bad file is a <see cref="UserError"/> naming the file and the field.</summary>
    public static ClusterConfig Load(string path)
    {
        JsonElement root;
        try
        {
            using var document = JsonDocument.Parse(File.ReadAllText(path), new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
            root = document.RootElement.Clone();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UserError($"{path}: cannot read the cluster file: {e.Message}");
        }
        catch (JsonException e)
        {
            throw new UserError($"{path}: not JSON: {e.Message}");
        }
        if (root.ValueKind != JsonValueKind.Object) throw new UserError($"{path}: a cluster file is one JSON object");

        var known = new[] { "clusterId", "clustering", "primaryPort", "gateways", "redis", "chunkTimeoutSeconds", "certificate" };
        foreach (var property in root.EnumerateObject())
            if (!known.Contains(property.Name))
                throw new UserError($"{path}: unknown field '{property.Name}'; the fields are {string.Join(", ", known)}");

        string Text(string field, string? fallback)
        {
            if (!root.TryGetProperty(field, out var value)) return fallback ?? throw new UserError($"{path}: field '{field}' is missing");
            if (value.ValueKind != JsonValueKind.String || value.GetString() is not { Length: > 0 } text)
                throw new UserError($"{path}: field '{field}' must be a non-empty string");
            return text;
        }
        int Port(JsonElement value, string field) =>
            value.ValueKind == JsonValueKind.Number && value.TryGetInt32(out var port) && port is >= 1 and <= 65535
                ? port
                : throw new UserError($"{path}: field '{field}' must be a port number 1..65535, not {value.GetRawText()}");

        var clustering = Text("clustering", null) switch
        {
            "localhost" => ClusteringKind.Localhost,
            "redis" => ClusteringKind.Redis,
            var other => throw new UserError($"{path}: field 'clustering' is '{other}'; choose localhost or redis"),
        };
        var primary = root.TryGetProperty("primaryPort", out var p) ? Port(p, "primaryPort") : DefaultPrimaryPort;
        var gateways = new List<int>();
        if (root.TryGetProperty("gateways", out var g))
        {
            if (g.ValueKind != JsonValueKind.Array || g.GetArrayLength() == 0)
                throw new UserError($"{path}: field 'gateways' must be a non-empty array of port numbers");
            gateways.AddRange(g.EnumerateArray().Select(port => Port(port, "gateways")));
        }
        else gateways.Add(DefaultGatewayPort);
        string? redis = null;
        if (clustering == ClusteringKind.Redis) redis = Text("redis", null);
        else if (root.TryGetProperty("redis", out _)) throw new UserError($"{path}: field 'redis' is for \"clustering\": \"redis\" only");
        var timeout = DefaultChunkTimeout;
        if (root.TryGetProperty("chunkTimeoutSeconds", out var t))
        {
            if (t.ValueKind != JsonValueKind.Number || !t.TryGetDouble(out var seconds) || !(seconds is > 0 and <= 86_400))
                throw new UserError($"{path}: field 'chunkTimeoutSeconds' must be a number of seconds in (0, 86400], not {t.GetRawText()}");
            timeout = TimeSpan.FromSeconds(seconds);
        }
        // A certificate path is relative to the cluster file; it is read once here so a bad one fails before anything starts.
        string? certificate = null;
        if (root.TryGetProperty("certificate", out _))
        {
            certificate = System.IO.Path.GetFullPath(Text("certificate", null), System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path))!);
            ClusterCertificate.Load(path, certificate).Dispose();
        }
        return new ClusterConfig(path, Text("clusterId", "qrt"), clustering, primary, gateways, redis, timeout, certificate);
    }
}

/// <summary>How the members of a cluster find each other.</summary>
public enum ClusteringKind
{
    /// <summary>Every worker on this machine; the first one's silo port is the meeting point.</summary>
    Localhost,

    /// <summary>Members write themselves into a Redis table: workers on several machines.</summary>
    Redis,
}
