using System.CommandLine;
using System.CommandLine.Help;
using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>Every command's --help explains every option and says what happens when it is left out.</summary>
public sealed class HelpTests
{
    public static TheoryData<string> Commands()
    {
        var data = new TheoryData<string>();
        void Walk(Command command, string path)
        {
            data.Add(path);
            foreach (var sub in command.Subcommands) Walk(sub, path.Length == 0 ? sub.Name : $"{path} {sub.Name}");
        }
        Walk(CommandLine.Build(), "");
        return data;
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void EveryOptionIsDescribedWithItsDefault(string path)
    {
        var command = Find(path);
        Assert.False(string.IsNullOrWhiteSpace(command.Description), $"'{path}' has no description");
        foreach (var option in command.Options.Where(o => o is not (HelpOption or VersionOption)))
        {
            Assert.False(string.IsNullOrWhiteSpace(option.Description), $"'{path} {option.Name}' has no description");
            // A flag defaults to off; any other option either has a default the help prints or says in words what leaving it out does.
            var explained = option.ValueType == typeof(bool) || option.HasDefaultValue || option.Description!.Contains("Default", StringComparison.Ordinal);
            Assert.True(explained, $"'{path} {option.Name}' does not say its default");
        }
        foreach (var argument in command.Arguments)
            Assert.False(string.IsNullOrWhiteSpace(argument.Description), $"'{path}' argument {argument.Name} has no description");
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public void HelpListsEveryOptionAndExitsCleanly(string path)
    {
        var output = new StringWriter();
        var args = path.Split(' ', StringSplitOptions.RemoveEmptyEntries).Append("--help").ToArray();

        var code = CommandLine.Build().Parse(args).Invoke(new InvocationConfiguration { Output = output });

        Assert.Equal(0, code);
        var text = output.ToString();
        foreach (var option in Find(path).Options) Assert.Contains(option.Name, text);
        Assert.Contains("--verbose", text);
    }

    private static Command Find(string path)
    {
        Command command = CommandLine.Build();
        foreach (var name in path.Split(' ', StringSplitOptions.RemoveEmptyEntries))
            command = command.Subcommands.Single(c => c.Name == name);
        return command;
    }
}

/// <summary>Each experiment's command, folder and page share one name; the commands' earlier names still run them.</summary>
public sealed class ExperimentNameTests
{
    [Theory]
    [InlineData("bench capacity", "simulator-capacity")]
    [InlineData("bench cluster", "cluster-performance")]
    [InlineData("bench fullstate", "fullstate-performance")]
    [InlineData("bench grover", "grover-performance")]
    [InlineData("bench optimised", "optimised-tracing")]
    [InlineData("bench pareto", "speed-vs-error")]
    [InlineData("bench render", "render-results")]
    [InlineData("bench supersample", "supersampling-results")]
    [InlineData("bench supersample-images", "supersampling-images")]
    [InlineData("estimate sweep", "oracle-sweep")]
    public void EarlierNamesStillRunTheirExperiment(string earlier, string name)
    {
        var result = CommandLine.Build().Parse([.. earlier.Split(' '), "--help"]);
        Assert.Equal(name, result.CommandResult.Command.Name);
        Assert.Empty(result.Errors);
    }

    [Fact]
    public void EveryExperimentFolderHasItsCommandAndItsPage()
    {
        var experiments = Path.Combine(RepositoryPaths.Root, "Host", "Experiments");
        var folders = Directory.GetDirectories(experiments).Select(Path.GetFileName).Where(f => f != "Shared").ToArray();
        Assert.NotEmpty(folders);
        var root = CommandLine.Build();
        var commands = root.Subcommands.Where(c => c.Name is "bench" or "estimate").SelectMany(c => c.Subcommands).Select(c => c.Name).ToHashSet();
        foreach (var folder in folders)
        {
            // PascalCase folder → kebab-case command and page: SpeedVsError → speed-vs-error.
            var name = string.Concat(folder!.Select((ch, k) => char.IsUpper(ch) && k > 0 ? "-" + char.ToLowerInvariant(ch) : char.ToLowerInvariant(ch).ToString()))
                .Replace("full-state", "fullstate");
            Assert.Contains(name, commands);
            Assert.True(File.Exists(Path.Combine(RepositoryPaths.Root, "docs", name + ".md")), $"docs/{name}.md is missing for Host/Experiments/{folder}");
        }
    }
}
