using System.CommandLine;
using System.CommandLine.Parsing;

namespace QuantumRayTracing.Cli;

/// <summary>Range rules for numeric options, checked at parse time with a one-line message naming the option.</summary>
public static class OptionRules
{
    public static Option<int> AtLeast(this Option<int> option, int min) => option.Between(min, int.MaxValue);

    public static Option<int> Between(this Option<int> option, int min, int max)
    {
        option.Validators.Add(result =>
        {
            if (!result.TryGetValue<int>(out var value)) return;
            if (value < min) result.AddError($"{option.Name} must be at least {min}, got {value}");
            else if (value > max) result.AddError($"{option.Name} must be at most {max}, got {value}");
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
}
