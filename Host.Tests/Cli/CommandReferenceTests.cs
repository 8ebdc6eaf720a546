using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>docs/commands.md is every command's --help as the parser prints it now, and `qrt docs commands` writes it.</summary>
public sealed class CommandReferenceTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-commands-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void DocsCommandsMdIsWhatTheParserPrints()
    {
        var path = Path.Combine(RepositoryPaths.Root, "docs", "commands.md");
        var regenerate = $"regenerate it with `dotnet run --project Host -- {CommandReference.CommandText["qrt ".Length..]}`";
        Assert.True(File.Exists(path), $"docs/commands.md is missing: {regenerate}");
        var expected = CommandReference.Markdown().ReplaceLineEndings("\n");
        var actual = File.ReadAllText(path).ReplaceLineEndings("\n");
        if (expected == actual) return;
        var (want, have) = (expected.Split('\n'), actual.Split('\n'));
        var line = Enumerable.Range(0, Math.Min(want.Length, have.Length)).FirstOrDefault(k => want[k] != have[k], Math.Min(want.Length, have.Length));
        Assert.Fail($"docs/commands.md differs from the command-line parser's help at line {line + 1} "
            + $"(page: '{(line < have.Length ? have[line] : "end of file")}', parser: '{(line < want.Length ? want[line] : "end of file")}'); {regenerate}.");
    }

    [Fact]
    public void EveryVisibleCommandHasItsSectionAndEveryOptionIsInIt()
    {
        var page = CommandReference.Markdown();
        var help = CommandReference.Help(["render"]);
        Assert.Contains("## qrt render\n", page);
        Assert.Contains("## qrt bench accuracy\n", page);
        Assert.Contains("## qrt estimate frame-sweep\n", page);
        Assert.Contains(help, page);
        Assert.Contains("  qrt render [<scene>] [options]", help);
        Assert.Contains("--budget", help);
        Assert.Contains("## qrt docs commands\n", page);
        Assert.All(page.Split('\n'), l => Assert.True(l.Length <= CommandReference.Width, $"wider than {CommandReference.Width}: {l}"));
    }

    [Fact]
    public void TheDocsCommandWritesThePageAndReplacesOnlyItsOwn()
    {
        var file = _scratch.File("commands.md");
        var (code, _, error) = ConsoleCapture.RunCapturingOutput("docs", "commands", "-o", file);
        Assert.Equal(0, code);
        Assert.Equal("", error);
        Assert.Equal(CommandReference.Markdown(), File.ReadAllText(file));
        Assert.Equal(0, ConsoleCapture.Run("docs", "commands", "-o", file).Code);

        var other = _scratch.File("notes.txt");
        File.WriteAllText(other, "# someone else's notes\n");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run("docs", "commands", "-o", other).Code);
        Assert.Equal("# someone else's notes\n", File.ReadAllText(other));
    }
}
