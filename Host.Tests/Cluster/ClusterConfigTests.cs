using QuantumRayTracing.Cluster;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>A cluster file is checked field by field; every problem is one line naming the file and the field.</summary>
public sealed class ClusterConfigTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-cluster-config");

    private string Write(string json)
    {
        var path = _scratch.File($"c{Guid.NewGuid():N}.json");
        File.WriteAllText(path, json);
        return path;
    }

    [Fact]
    public void ReadsEveryField()
    {
        var path = Write("""{ "clusterId": "lab", "clustering": "redis", "redis": "r1:6379", "gateways": [30000], "chunkTimeoutSeconds": 90 }""");
        var config = ClusterConfig.Load(path);
        Assert.Equal(("lab", ClusteringKind.Redis, "r1:6379", TimeSpan.FromSeconds(90)), (config.ClusterId, config.Clustering, config.Redis, config.ChunkTimeout));
    }

    [Fact]
    public void LocalhostDefaults()
    {
        var config = ClusterConfig.Load(Write("""{ "clustering": "localhost" }"""));
        Assert.Equal(("qrt", ClusterConfig.DefaultPrimaryPort, ClusterConfig.DefaultGatewayPort, ClusterConfig.DefaultChunkTimeout),
            (config.ClusterId, config.PrimaryPort, config.Gateways.Single(), config.ChunkTimeout));
    }

    [Theory]
    [InlineData("""{ }""", "field 'clustering' is missing")]
    [InlineData("""{ "clustering": "consul" }""", "field 'clustering' is 'consul'")]
    [InlineData("""{ "clustering": "redis" }""", "field 'redis' is missing")]
    [InlineData("""{ "clustering": "localhost", "redis": "x:1" }""", "field 'redis' is for")]
    [InlineData("""{ "clustering": "localhost", "gateways": [70000] }""", "field 'gateways' must be a port number")]
    [InlineData("""{ "clustering": "localhost", "gateways": [] }""", "field 'gateways' must be a non-empty array")]
    [InlineData("""{ "clustering": "localhost", "primaryPort": "x" }""", "field 'primaryPort' must be a port number")]
    [InlineData("""{ "clustering": "localhost", "chunkTimeoutSeconds": 0 }""", "field 'chunkTimeoutSeconds' must be a number")]
    [InlineData("""{ "clustering": "localhost", "chunkTimout": 5 }""", "unknown field 'chunkTimout'")]
    [InlineData("""[1]""", "a cluster file is one JSON object")]
    [InlineData("""{ "clustering": """, "not JSON")]
    public void BadFileIsOneLineNamingFileAndField(string json, string expected)
    {
        var path = Write(json);
        var error = Assert.Throws<UserError>(() => ClusterConfig.Load(path));
        Assert.StartsWith(path + ": ", error.Message);
        Assert.Contains(expected, error.Message);
        Assert.DoesNotContain('\n', error.Message);
    }

    public void Dispose() => _scratch.Dispose();
}
