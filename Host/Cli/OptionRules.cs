using System.CommandLine;
using System.CommandLine.Parsing;
using System.Runtime.Serialization;

namespace QuantumRayTracing.Cli;

/// <summary>Range rules for numeric options, checked at parse time with a one-line message naming the option.</summary>
public static class OptionRules
{
    public static Option<int> AtLeast(this Option<int> option, int min) => option.Between(min, int.MaxValue);

    public static Option<int> Between(this Option<int> option, int min, int max)
    {
        option.Validators.Add(result =>
        {
            if (result.TryGetValue<int>(out var value)) Check(result, option.Name, value, min, max);
        });
        return option;
    }

    /// <summary>The same rule for an option that may be left out (null: the command picks a default).</summary>
    public static Option<int?> Between(this Option<int?> option, int min, int max)
    {
        option.Validators.Add(result =>
        {
            if (result.TryGetValue<int?>(out var value) && value is { } given) Check(result, option.Name, given, min, max);
        });
        return option;
    }

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

    public static Option<long?> Between(this Option<long?> option, long min, long max)
    {
        option.Validators.Add(result =>
        {
            if (result.TryGetValue<long?>(out var value) && value is { } given) Check(result, option.Name, given, min, max);
        });
        return option;
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

    private static void Check(System.CommandLine.Parsing.OptionResult result, string name, long value, long min, long max)
    {
        if (value < min) result.AddError($"{name} must be at least {min}, got {value}");
        else if (value > max) result.AddError($"{name} must be at most {max}, got {value}");
    }
}
