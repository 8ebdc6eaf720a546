using System.Diagnostics;

namespace QuantumRayTracing.Tests.Repository;

/// <summary>The project's texts name only documents the repository holds.</summary>
public sealed class DocumentReferenceTests
{
    private static readonly string[] TextExtensions = [".cs", ".qs", ".md", ".mjs", ".json", ".csproj", ".props", ".targets", ".sh", ".yml", ".yaml"];

    // The made-up references below are put together from pieces, so this file does not itself name a missing document.
    private const string Up = "." + "./";

    private static string Md(string stem) => stem + ".md";

    [Fact]
    public void EveryTextNamesOnlyDocumentsInTheRepository()
    {
        var files = RepositoryFiles();
        Assert.Contains("docs/conventions.md", files);
        Assert.Contains("README.md", files);
        var checker = new DocumentReferences(files);
        var problems = files
            .Where(f => TextExtensions.Contains(Path.GetExtension(f)) && !f.EndsWith("package-lock.json", StringComparison.Ordinal))
            .SelectMany(f => checker.Problems(f, File.ReadAllText(Path.Combine(RepositoryPaths.Root, f))))
            .ToArray();
        Assert.True(problems.Length == 0, string.Join(Environment.NewLine, problems));
    }

    [Fact]
    public void AMarkdownLinkToAMissingFileIsFound()
    {
        var page = Md("docs/a");
        var checker = new DocumentReferences([Md("README"), page, "docs/images/x.png"]);
        Assert.Empty(checker.Problems(page, $"see [readme]({Up}{Md("README")}), ![x](images/x.png), [here](#top) and [web](https://example.org/{Md("y")})"));
        var problems = checker.Problems(page, $"line one\nsee [b]({Md("b")}) and ![y](images/y.png)").ToArray();
        Assert.Equal([$"{page}:2: names '{Md("b")}', which is not in the repository", $"{page}:2: names 'images/y.png', which is not in the repository"], problems);
    }

    [Fact]
    public void AMentionOfAMissingMarkdownFileIsFoundInCode()
    {
        var checker = new DocumentReferences([Md("README"), Md("docs/conventions"), Md("Host.Tests/BadInput/README"), "Host/A.cs"]);
        Assert.Empty(checker.Problems("Host/A.cs", $"/// Counted as in {Md("docs/conventions")}; see {Md("README")}, {Md("conventions")} and {Md("BadInput/README")}."));
        Assert.Equal([$"Host/A.cs:1: names '{Md("NOTES")}', which is not in the repository"],
            checker.Problems("Host/A.cs", $"/// Counted as in {Md("NOTES")} §5."));
        Assert.Single(checker.Problems("Host/A.cs", $"// see {Md("docs/notes")}"));
        Assert.Single(checker.Problems("Host/A.cs", $"// see {Md("Other/README")}"));
    }

    [Fact]
    public void APathOutsideTheRepositoryIsFound()
    {
        var page = Md("docs/a");
        var checker = new DocumentReferences(["Host/Host.csproj", "Quantum/Quantum.csproj", page]);
        Assert.Empty(checker.Problems("Host/Host.csproj", $"<ProjectReference Include=\"{Up}Quantum/Quantum.csproj\" />"));
        Assert.Single(checker.Problems("Host/A.cs", $"/// the paper ({Up}shared/papers/000)"));
        Assert.Single(checker.Problems(page, $"[notes]({Up}{Up}outside.txt)"));
    }

    [Fact]
    public void APlantedBadReferenceInTheRealTreeIsFound()
    {
        var files = RepositoryFiles();
        var checker = new DocumentReferences(files);
        var readme = File.ReadAllText(Path.Combine(RepositoryPaths.Root, "README.md"));
        Assert.Empty(checker.Problems("README.md", readme));
        Assert.Single(checker.Problems("README.md", readme + $"\nSee [the notes]({Md("notes")}).\n"));
        Assert.Single(checker.Problems("Host/Search/SearchCost.cs", $"/// What searches cost ({Up}{Up}shared/notes)."));
    }

    /// <summary>The repository's files, tracked or new but not ignored, relative to its root with '/' separators.</summary>
    private static string[] RepositoryFiles()
    {
        var start = new ProcessStartInfo("git", ["ls-files", "--cached", "--others", "--exclude-standard"])
        {
            WorkingDirectory = RepositoryPaths.Root,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        using var git = Process.Start(start)!;
        var output = git.StandardOutput.ReadToEnd();
        git.WaitForExit();
        Assert.True(git.ExitCode == 0, $"git ls-files failed in {RepositoryPaths.Root}: {git.StandardError.ReadToEnd()}");
        // A file deleted but not yet committed is still listed by --cached: keep only what exists.
        return output.Split('\n', StringSplitOptions.RemoveEmptyEntries)
            .Where(f => File.Exists(Path.Combine(RepositoryPaths.Root, f)))
            .ToArray();
    }
}
