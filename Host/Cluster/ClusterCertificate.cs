using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;
using Orleans.Connections.Security;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cluster;

/// <summary>
/// The certificate a cluster file names: every worker and every render of the cluster holds it, and they talk over
/// mutual TLS with it. Each side presents it and accepts only a peer presenting the same certificate (pinned by
/// thumbprint), so a process without the file can neither join nor send work, whoever signed the certificate.
/// </summary>
public static class ClusterCertificate
{
    /// <summary>The environment variable holding the PKCS#12 file's password, when it has one.</summary>
    public const string PasswordVariable = "QRT_CLUSTER_CERTIFICATE_PASSWORD";

    /// <summary>Reads a PKCS#12 (.pfx) file with its private key; a file that does not read is a <see cref="UserError"/> naming the cluster file and the field.</summary>
    public static X509Certificate2 Load(string clusterFile, string path)
    {
        X509Certificate2 certificate;
        try
        {
            certificate = X509CertificateLoader.LoadPkcs12FromFile(path, Environment.GetEnvironmentVariable(PasswordVariable));
        }
        catch (Exception e) when (e is CryptographicException or IOException or UnauthorizedAccessException)
        {
            throw new UserError($"{clusterFile}: field 'certificate': cannot read '{path}' as a PKCS#12 certificate ({e.Message.TrimEnd('.')}; a password goes in {PasswordVariable})");
        }
        if (!certificate.HasPrivateKey)
            throw new UserError($"{clusterFile}: field 'certificate': '{path}' holds no private key; export the certificate with its key (docs/cluster.md)");
        return certificate;
    }

    /// <summary>Mutual TLS with <paramref name="certificate"/> on both sides, every peer pinned to it.</summary>
    public static void Configure(TlsOptions options, X509Certificate2 certificate)
    {
        options.LocalCertificate = certificate;
        options.RemoteCertificateMode = RemoteCertificateMode.RequireCertificate;
        options.ClientCertificateMode = RemoteCertificateMode.RequireCertificate;
        // The chain and the host name say nothing here (the certificate is usually self-signed and names no host):
        // holding the cluster's own certificate is what admits a peer.
        options.RemoteCertificateValidation = (remote, _, _) => remote.Thumbprint == certificate.Thumbprint;
        options.OnAuthenticateAsClient = (_, tls) => tls.TargetHost = certificate.GetNameInfo(X509NameType.SimpleName, forIssuer: false);
    }
}
