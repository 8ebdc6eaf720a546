using System.CommandLine;
using System.CommandLine.Help;
using System.Reflection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Cli;

/// <summary>
/// <c>--json FILE</c>: a command's run for scripts. The command hands over the result records it printed its figures
/// from; the options are read from the parse result, every one with its value (defaults included), so a sweep's
/// file says exactly what ran. The document itself is <see cref="RunJsonFile"/>'s.
/// </summary>
public sealed class JsonOption
{
    private static readonly MethodInfo GetOptionValue = GetValueMethod(typeof(Option<>));
    private static readonly MethodInfo GetArgumentValue = GetValueMethod(typeof(Argument<>));

    public readonly Option<string?> File = new("--json")
    {
        Description = $"Also write every printed figure, the options, the seed, the engine, the noise model and the versions as JSON to this file (counting conventions: {RunJsonFile.Conventions}). Default: none, no JSON file. An existing file is replaced only if this program wrote it.",
        HelpName = "FILE",
    };

    public void AddTo(Command command) => command.Options.Add(File);

    public string? Path(ParseResult parse) => parse.GetValue(File);

    /// <summary>Fails before any work when the file may not be written; <paramref name="otherFiles"/> are the command's inputs and outputs.</summary>
    public void EnsureWritable(ParseResult parse, IEnumerable<string> otherFiles) => RunJsonFile.EnsureWritable(Path(parse), otherFiles);

    /// <summary>
    /// Writes the file when --json was given: <paramref name="figures"/> are the result records the command printed,
    /// <paramref name="ranOn"/> where it printed that the work ran, <paramref name="noise"/> the noise when not the engine options' own.
    /// </summary>
    public void Write(ParseResult parse, object figures, EngineOptions? engine = null, RunPlace? ranOn = null, RunNoise? noise = null)
    {
        if (Path(parse) is not { } path) return;
        var record = new RunRecord(parse.CommandResult.Command.Name, Values(parse),
            engine is null ? null : parse.GetValue(engine.Seed),
            engine is null ? null : EngineFactory.Name(parse.GetValue(engine.Engine)),
            noise ?? (engine is null ? RunNoise.None : RunNoise.Of(parse.GetValue(engine.Engine), engine.GetNoise(parse))), figures, ranOn);
        RunJsonFile.Write(path, record);
    }

    /// <summary>Every argument and option of the command that ran, by name without dashes, with the value it had.</summary>
    public static IReadOnlyDictionary<string, object?> Values(ParseResult parse)
    {
        var command = parse.CommandResult.Command;
        var values = new SortedDictionary<string, object?>(StringComparer.Ordinal);
        foreach (var argument in command.Arguments)
            values[argument.Name] = Plain(GetArgumentValue.MakeGenericMethod(argument.ValueType).Invoke(parse, [argument]));
        foreach (var option in command.Options.Where(o => o is not HelpOption and not VersionOption))
            values[option.Name.TrimStart('-')] = Plain(GetOptionValue.MakeGenericMethod(option.ValueType).Invoke(parse, [option]));
        return values;
    }

    // Files as the paths the user gave, not their every property.
    private static object? Plain(object? value) => value is FileSystemInfo file ? file.ToString() : value;

    private static MethodInfo GetValueMethod(Type symbol) => typeof(ParseResult).GetMethods()
        .Single(m => m.Name == nameof(ParseResult.GetValue) && m.IsGenericMethodDefinition
            && m.GetParameters() is [{ ParameterType: { IsGenericType: true } type }] && type.GetGenericTypeDefinition() == symbol);
}
