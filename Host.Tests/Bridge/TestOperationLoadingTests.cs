using System.Diagnostics;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>The host's bridges load the Q# library alone; Quantum/tests/ only when QRT_QSHARP_TESTS=1, as the tests set it.</summary>
public sealed class TestOperationLoadingTests
{
    private const string TestCall = "{\"id\":1,\"method\":\"run\",\"expr\":\"QuantumRayTracing.Search.CompareMarkingOracleConstructions(2, [1])\"}";

    [Fact]
    public void TheTestsRunWithTheTestOperations() => Assert.Equal("1", Environment.GetEnvironmentVariable("QRT_QSHARP_TESTS"));

    [Fact]
    public void ABridgeStartedWithoutTheVariableDoesNotKnowThem()
    {
        var reply = Answer(withTests: false);
        Assert.Contains("\"ok\":false", reply);
        Assert.Contains("CompareMarkingOracleConstructions` not found", reply);
        Assert.Contains("\"ok\":true", Answer(withTests: true));
    }

    /// <summary>The reply of a bridge started with or without the variable to one call of a test operation.</summary>
    private static string Answer(bool withTests)
    {
        var start = new ProcessStartInfo(new BridgeOptions().Node)
        {
            ArgumentList = { QuantumProject.BridgeScript },
            WorkingDirectory = QuantumProject.Directory,
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
        };
        if (withTests) start.Environment["QRT_QSHARP_TESTS"] = "1";
        else start.Environment.Remove("QRT_QSHARP_TESTS");
        using var process = Process.Start(start)!;
        Assert.Contains("\"ready\":true", process.StandardOutput.ReadLine());
        process.StandardInput.WriteLine(TestCall);
        process.StandardInput.Close();
        var reply = process.StandardOutput.ReadLine() ?? "";
        process.WaitForExit();
        return reply;
    }
}
