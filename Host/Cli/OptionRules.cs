using System.CommandLine;

namespace QuantumRayTracing.Cli;

/// <summary>Range rules for numeric options, checked at parse time with a one-line message naming the option.</summary>
public static class OptionRules
{
    public static Option<int> AtLeast(this Option<int> option, int min) => option.Between(min, int.MaxValue);

    public static Option<int> Between(this Option<int> option, int min, int max)
    {
        option.Validators.Add(result =>
        {
            var value = result.GetValueOrDefault<int>();
            if (value < min) result.AddError($"{option.Name} must be at least {min}, got {value}");
            else if (value > max) result.AddError($"{option.Name} must be at most {max}, got {value}");
        });
        return option;
    }
}
