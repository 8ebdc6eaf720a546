using System.Text.RegularExpressions;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// The bad-input tests swap the console's writers to read what a command prints, so they run alone, after the
/// parallel tests: another test's output must not land in (or be missing from) a capture.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class BadInputCollection
{
    public const string Name = "bad input, console captured";
}

/// <summary>The corpus files, as copied next to the test binaries (Host.Tests.csproj).</summary>
internal static class Corpus
{
    public static string Root { get; } = Path.Combine(AppContext.BaseDirectory, "BadInput");

    public static string Scene(string name) => Path.Combine(Root, "Scenes", name);

    public static string Image(string name) => Path.Combine(Root, "Images", name);

    /// <summary>The names of every file in one corpus folder, but the valid baseline.</summary>
    public static string[] Files(string folder, string baseline) =>
        Directory.GetFiles(Path.Combine(Root, folder)).Select(Path.GetFileName).Where(n => n != baseline).Order().ToArray()!;
}

/// <summary>One command line run in-process: exit code, captured output and error, and an exception that escaped it.</summary>
internal sealed record Outcome(int Code, string Output, string Error, Exception? Escaped)
{
    public static Outcome Of(params string[] args)
    {
        var (code, output, error) = (-1, "", "");
        // An exception out of CommandLine.Run is what a user would see as a stack trace.
        var escaped = Record.Exception(() => (code, output, error) = ConsoleCapture.RunCapturingOutput(args));
        return new Outcome(code, output, error, escaped);
    }

    private static readonly Regex StackFrame = new(@"^\s+at \S+", RegexOptions.Multiline);

    /// <summary>
    /// The issue's contract for bad input: exit code 2, standard error exactly one line "error: FILE: ELEMENT...",
    /// no stack trace anywhere, and nothing left in <paramref name="outputDirectory"/> (no image, no temporary file).
    /// </summary>
    public string AssertBadInput(string file, string element, string problem, string? outputDirectory)
    {
        Assert.True(Escaped is null, $"escaped as {Escaped?.GetType().Name}: {Escaped?.Message}");
        Assert.Equal(ExitCodes.BadInput, Code);
        var line = AssertOneLine(Error);
        Assert.StartsWith($"error: {file}: {element}", line);
        Assert.Contains(problem, line);
        AssertNoStackTrace();
        if (outputDirectory is not null) AssertEmpty(outputDirectory);
        return line;
    }

    /// <summary>A usage error (an option's value, checked while parsing): exit code 1, one message naming the option.</summary>
    public string AssertUsageError(string option, string problem, string outputDirectory)
    {
        Assert.True(Escaped is null, $"escaped as {Escaped?.GetType().Name}: {Escaped?.Message}");
        Assert.Equal(1, Code);
        // System.CommandLine ends its error report with a blank line; the message itself is one line.
        var line = AssertOneLine(Error.TrimEnd() + Environment.NewLine);
        Assert.StartsWith($"{option}: ", line);
        Assert.Contains(problem, line);
        AssertNoStackTrace();
        AssertEmpty(outputDirectory);
        return line;
    }

    /// <summary>
    /// A usage error of a command line (an option's value or a rule across options): exit code 1, one line that
    /// names <paramref name="option"/> and says <paramref name="problem"/>, no stack trace.
    /// </summary>
    public string AssertUsageError(string option, string problem)
    {
        Assert.True(Escaped is null, $"escaped as {Escaped?.GetType().Name}: {Escaped?.Message}");
        Assert.Equal(1, Code);
        var line = AssertOneLine(Error.TrimEnd() + Environment.NewLine);
        Assert.Contains(option, line);
        Assert.Contains(problem, line);
        AssertNoStackTrace();
        return line;
    }

    /// <summary>Bad input that is no file's (a pixel outside the image): exit code 2, one line "error: ..." naming <paramref name="subject"/> and <paramref name="problem"/>.</summary>
    public string AssertBadInput(string subject, string problem)
    {
        Assert.True(Escaped is null, $"escaped as {Escaped?.GetType().Name}: {Escaped?.Message}");
        Assert.Equal(ExitCodes.BadInput, Code);
        var line = AssertOneLine(Error);
        Assert.StartsWith("error: ", line);
        Assert.Contains(subject, line);
        Assert.Contains(problem, line);
        AssertNoStackTrace();
        return line;
    }

    private static string AssertOneLine(string text)
    {
        Assert.EndsWith("\n", text);
        var lines = text.TrimEnd('\n').Split('\n');
        Assert.True(lines.Length == 1, $"expected one line, got {lines.Length}:\n{text}");
        return lines[0].TrimEnd('\r');
    }

    private void AssertNoStackTrace()
    {
        foreach (var text in new[] { Output, Error })
        {
            Assert.DoesNotMatch(StackFrame, text);
            Assert.DoesNotContain("Exception", text);
        }
    }

    public static void AssertEmpty(string directory) =>
        Assert.Empty(Directory.EnumerateFileSystemEntries(directory).Select(Path.GetFileName));
}
