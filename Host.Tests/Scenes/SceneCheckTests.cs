using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes;

public class SceneCheckTests
{
    [Fact]
    public void AGoodFileIsSummarisedAndABadOneCountedWithItsProblem()
    {
        var good = new FileInfo(Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"));
        var missing = new FileInfo(Path.Combine(Path.GetTempPath(), $"qrt-missing-{Guid.NewGuid():N}.json"));
        var (output, errors) = (new StringWriter(), new StringWriter());

        Assert.Equal(1, SceneCheck.Run([good, missing], output, errors));

        // 8 rectangles need a 3-qubit index register (2^3 = 8).
        Assert.StartsWith($"{good}: ok: '", output.ToString());
        Assert.Contains("8 rectangles (3 index qubits)", output.ToString());
        Assert.Equal($"error: {missing.FullName}: file: not found{Environment.NewLine}", errors.ToString());
    }
}
