using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;
using System.Text.Json.Nodes;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// A cluster file that names a certificate: a worker serves a render holding the same certificate and refuses one
/// without it or with another certificate.
/// </summary>
public sealed class ClusterTlsTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-cluster-tls-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void AWorkerServesOnlyRendersHoldingTheClustersCertificate()
    {
        var certificate = SelfSigned("qrt-cluster", "cluster.pfx");
        var executor = new EchoExecutor();
        using var cluster = new TestCluster(120, null, certificate, executor);

        using (var pool = ClusterBridges.Start(cluster.ConfigPath, 1))
        {
            var answer = "";
            pool.ForEach([0], (_, bridge) => answer = Assert.Single(bridge.Run("Request(7)")));
            Assert.Equal("Request(7)", answer);
        }
        Assert.Equal(1, executor.Calls);

        var withoutCertificate = Variant(cluster.ConfigPath, "plain.json", null);
        var withAnother = Variant(cluster.ConfigPath, "other.json", SelfSigned("qrt-cluster", "other.pfx"));
        using var _ = TestCluster.RefusalIsTheAnswer();
        foreach (var refused in new[] { withoutCertificate, withAnother })
        {
            var error = Assert.Throws<ClusterException>(() => ClusterBridges.Start(refused, 1).Dispose());
            Assert.Contains("no worker of cluster", error.Message);
        }
        Assert.Equal(1, executor.Calls);
    }

    [Fact]
    public void ACertificateThatDoesNotReadIsNamedWithItsField()
    {
        var broken = _scratch.File("broken.pfx");
        File.WriteAllText(broken, "not a certificate");
        var config = _scratch.File("cluster.json");
        File.WriteAllText(config, """{ "clustering": "localhost", "certificate": "broken.pfx" }""");
        var error = Assert.Throws<UserError>(() => ClusterConfig.Load(config));
        Assert.StartsWith($"{config}: field 'certificate': cannot read '{broken}'", error.Message);
    }

    // The cluster file with its certificate field replaced (null: removed), written beside it.
    private string Variant(string configPath, string name, string? certificate)
    {
        var json = JsonNode.Parse(File.ReadAllText(configPath))!.AsObject();
        json.Remove("certificate");
        if (certificate is not null) json["certificate"] = certificate;
        var path = _scratch.File(name);
        File.WriteAllText(path, json.ToJsonString());
        return path;
    }

    // A self-signed certificate for server and client authentication, with its key, as the docs make one with openssl.
    private string SelfSigned(string subject, string file)
    {
        using var key = RSA.Create(2048);
        var request = new CertificateRequest($"CN={subject}", key, HashAlgorithmName.SHA256, RSASignaturePadding.Pkcs1);
        request.CertificateExtensions.Add(new X509EnhancedKeyUsageExtension([new Oid("1.3.6.1.5.5.7.3.1"), new Oid("1.3.6.1.5.5.7.3.2")], false));
        using var certificate = request.CreateSelfSigned(DateTimeOffset.UtcNow.AddDays(-1), DateTimeOffset.UtcNow.AddDays(30));
        var path = _scratch.File(file);
        File.WriteAllBytes(path, certificate.Export(X509ContentType.Pfx));
        return path;
    }
}
