using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;
using System.Runtime.Serialization;

namespace QuantumRayTracing.Cli;

/// <summary>Range rules for numeric options, checked at parse time with a one-line message naming the option.</summary>
public static class OptionRules
{
    public static Option<int> AtLeast(this Option<int> option, int min) => option.Between(min, int.MaxValue);

    /// <summary>An integer option's range (an option that may be left out is checked when given).</summary>
    public static Option<T> Between<T>(this Option<T> option, long min, long max) => option.Must(value =>
        value is null ? null : Convert.ToInt64(value, CultureInfo.InvariantCulture) switch
        {
            var v when v < min => $"{option.Name} must be at least {min}, got {v}",
            var v when v > max => $"{option.Name} must be at most {max}, got {v}",
            _ => null,
        });

    /// <summary>
    /// A named rule: <paramref name="problem"/> gives the whole one-line error for a parsed value, or null when it is
    /// fine. A value that does not parse is left to the parser's own error.
    /// </summary>
    public static Option<T> Must<T>(this Option<T> option, Func<T, string?> problem)
    {
        option.Validators.Add(result =>
        {
            if (result.TryGetValue<T>(out var value) && problem(value!) is { } error) result.AddError(error);
        });
        return option;
    }

    /// <summary>A rule on several options together, skipped while one of them does not parse (that has its own error).</summary>
    public static void AddRule(this Command command, Action<CommandResult> rule) => command.Validators.Add(result =>
    {
        try
        {
            rule(result);
        }
        catch (InvalidOperationException)
        {
        }
    });

    /// <summary>
    /// <paramref name="option"/>'s value as a command rule sees it: inside a command validator an option left out reads as
    /// default(T), not as its default value, so <paramref name="fallback"/> (that default) stands in for it.
    /// </summary>
    public static T ValueOr<T>(this CommandResult result, Option<T> option, T fallback) =>
        result.GetResult(option) is null ? fallback : result.GetValue(option)!;

    /// <summary>A probability strictly between 0 and 1, the error naming the option.</summary>
    public static Option<T> StrictProbability<T>(this Option<T> option) => option.Must(value =>
        value is not double p || p > 0 && p < 1 ? null : $"{option.Name} must lie strictly between 0 and 1, got {p}");

    /// <summary>
    /// The option's value for a validator, or false when its text does not convert: the parser reports
    /// that itself, and reading the value would throw.
    /// </summary>
    public static bool TryGetValue<T>(this OptionResult result, out T? value)
    {
        try
        {
            value = result.GetValueOrDefault<T>();
            return true;
        }
        catch (InvalidOperationException)
        {
            value = default;
            return false;
        }
    }

    /// <summary>Parses an enum option from its names in any case, with a one-line error listing them (the parser's own lists them one per line).</summary>
    public static Option<T> Choices<T>(this Option<T> option) where T : struct, Enum
    {
        option.CustomParser = result => ParseChoice<T>(result, option.Name) ?? default;
        return option;
    }

    public static Option<T?> Choices<T>(this Option<T?> option) where T : struct, Enum
    {
        option.CustomParser = result => ParseChoice<T>(result, option.Name);
        return option;
    }

    private static T? ParseChoice<T>(System.CommandLine.Parsing.ArgumentResult result, string name) where T : struct, Enum
    {
        var token = result.Tokens.Count == 1 ? result.Tokens[0].Value : "";
        // Enum.TryParse also takes numbers: only the names count.
        var match = Enum.GetValues<T>().Cast<T?>().FirstOrDefault(v => string.Equals(ChoiceName(v!.Value), token, StringComparison.OrdinalIgnoreCase));
        if (match is not null) return match;
        result.AddError($"{name}: '{token}' is not one of {string.Join(", ", Enum.GetValues<T>().Select(v => ChoiceName(v)))}");
        return null;
    }

    /// <summary>How a choice is written on the command line: its <see cref="EnumMemberAttribute"/> value (e.g. mlae-noise), else its name in lower case.</summary>
    public static string ChoiceName<T>(T value) where T : struct, Enum
    {
        var name = value.ToString();
        var member = typeof(T).GetField(name)?.GetCustomAttributes(typeof(EnumMemberAttribute), false).OfType<EnumMemberAttribute>().FirstOrDefault();
        return member?.Value ?? name.ToLowerInvariant();
    }
}
